#pragma once
/// \file step.hpp
/// The contact core's one staged step (issue 21, first slice), Moreau's scheme of
/// planar_rigid.hpp for N bodies on one table:
///   kinematics   the table's pose and twist at t_{k+1}, once for every body
///   per body     contacts (patch points at the midpoint pose, the field read on the table)
///                -> normal loads (each point's load fraction; constant for now)
///                -> friction impulse (PatchImpulseSolver: exact stick; the mass matrix is
///                   block diagonal over bodies while bodies do not touch, so each block is
///                   solved on its own)
///                -> integrate
///   checks       finiteness: a body whose state is no longer finite sets status non_finite
///                and the run stops (no exception inside the loop)
/// The per-body stages are a visitor over the body's kind: a rigid body's are
/// src/planar/rigid_body_step.hpp; a 1-D part's (SliderBody) its level at the midpoint and the
/// 1-D Moreau projection (src/simulate/moreau_slider_step.hpp). A rigid body of an N-body model
/// moves bit for bit as advance_planar_rigid moves it alone, a 1-D part as
/// advance_time_stepping moves it: each pair runs the same stages.

#include "selfalign/core/state.hpp"

namespace selfalign::core {

/// Observer of the core's steps: on_step(state) after each step, every body's state in it.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void on_step(const State& state) = 0;
};

/// Advances up to `steps` steps (fewer when a check fails: see state.status), calling
/// observer->on_step (if any) after each. Returns the steps taken. Validates the model and
/// that the state has one entry per body.
long long step(const Model& model, State& state, long long steps,
               StepObserver* observer = nullptr);

}  // namespace selfalign::core
