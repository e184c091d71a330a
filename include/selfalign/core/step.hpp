#pragma once
/// \file step.hpp
/// The contact core's one staged step (issue 21, first slice), Moreau's scheme of
/// planar_rigid.hpp for N bodies on one table:
///   kinematics   the table's pose and twist at t_{k+1}, once for every body
///   loads        the step's normal impulse per unit weight: h (the paper's constant load) or,
///                with Model::gravity, h cos(incline) + (z'(t_{k+1}) - z'(t_k)) / g, and
///                gravity's impulse h g sin(incline) downhill; a negative normal impulse lifts
///                the bodies off (status lift_off, the run stops before the step)
///   per body     contacts (patch points at the midpoint pose, the field read on the table)
///                -> normal loads (each point's load fraction of the step's normal impulse)
///                -> friction impulse (PatchImpulseSolver: exact stick; the mass matrix is
///                   block diagonal over bodies while bodies do not touch, so each block is
///                   solved on its own)
///                -> integrate
///   checks       finiteness: a body whose state is no longer finite sets status non_finite
///                and the run stops (no exception inside the loop)
///   observe      the step to the one observer interface (simulate/motion_observer.hpp): each
///                1-D part's step as a piece (on_motion, `body` its index), then the state
///                (on_step)
/// The per-body stages are a visitor over the body's kind: a rigid body's are
/// src/planar/rigid_body_step.hpp; a 1-D part's (SliderBody) its level at the midpoint and the
/// 1-D Moreau projection (src/simulate/moreau_slider_step.hpp). A rigid body of an N-body model
/// moves bit for bit as advance_planar_rigid moves it alone, a 1-D part as
/// advance_time_stepping moves it: each pair runs the same stages.

#include "selfalign/core/state.hpp"
#include "selfalign/simulate/motion_observer.hpp"

namespace selfalign::core {

/// Advances up to `steps` steps (fewer when a check fails: see state.status). After each step
/// the observer (if any) is handed every SliderBody's step as a piece (on_motion: t0, t1, x
/// and x' before and after, direction of x' at its end, ArcEnd::time_step, `body` its index;
/// no closed form), then the state (on_step). Returns the steps taken. Validates the model and
/// that the state has one entry per body.
long long step(const Model& model, State& state, long long steps,
               MotionObserver* observer = nullptr);

}  // namespace selfalign::core
