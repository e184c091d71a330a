#pragma once
/// \file planar_rigid.hpp
/// A rigid part on a contact patch, translating and rotating on a table that moves in the plane
/// (translation along two directions and an in-plane rotation; issue 13), by Moreau's
/// time-stepping with the set-valued friction of every contact point solved exactly per step
/// (patch_impulse.hpp: exact zero relative twist in stick, exact zero slip at a pivot).
///
/// The part's pose is kept on the table: centre of mass xi in table coordinates and angle phi
/// relative to the table, with its twist relative to the table (u, w) in table axes (the exact
/// time derivatives of xi and phi). The table moves by T(t) and turns by psi(t) about its
/// origin; its velocity at a world point p is V_T(p) = T' + psi' J (p - T) (J: +90 degrees),
/// and the friction level is read at table coordinates. The impulse balance is written in the
/// world (inertial) frame. One step from t_k to t_{k+1} = t_k + h:
///   midpoint   xi_M = xi_k + (h/2) u_k, phi_M = phi_k + (h/2) w_k; the table at
///              T_M = T_k + (h/2) T'_k, psi_M = psi_k + (h/2) psi'_k; X_M = T_M + R(psi_M) xi_M;
///   contact i  lever d_i = R(psi_M + phi_M) r_i, friction level m(xi_M + R(phi_M) r_i);
///   free       delta* = (V_k, omega_k) - (V_T(X_M), psi') at t_{k+1} (world twists);
///   impulse    delta = argmin f (patch_impulse.hpp) with c_i = h mu m_i w_i;
///   update     (u, w)_{k+1} = (R(-psi_{k+1}) delta_v, delta_omega),
///              (xi, phi)_{k+1} = (xi, phi)_k + h ((1 - theta) (u, w)_k + theta (u, w)_{k+1}).
/// So a part that sticks (delta = 0 in consecutive steps) keeps its table pose exactly, also on
/// a rotating table. Dimensionless as the 1-D model: mass 1, lengths in L, friction per unit
/// m g mu_1; the inertia is j = I / (m L^2). For one point at the centre of mass on a
/// translating table this is the point stepper (planar_point.hpp) term for term, the spin left
/// unchanged; for a patch symmetric about the motion's axis it is the 1-D scheme.

#include <vector>

#include "selfalign/core/step.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/patch_impulse.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/planar/rigid_part.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {


struct PlanarRigidState {
  double t0 = 0;
  long long step_index = 0;
  double t = 0;
  PlanarPose pose;                      ///< on the table [-], [rad]
  PlanarTwist twist;                    ///< relative to the table, table axes [-]
  PlanarTablePose table;                ///< the table at t
  PatchMode mode = PatchMode::stick;    ///< how the last step ended
  int pivot = -1;                       ///< the pivot contact (mode pivot)
  long long sweeps = 0, newton_steps = 0;  ///< solver work so far
  PatchImpulseSolver solver;            ///< warm start of the impulse solver
  /// The core's status: non_finite once the table's motion or the part's state left the finite
  /// numbers; advance_planar_rigid then takes no more steps (the state is that of the failing
  /// step).
  core::StepStatus status = core::StepStatus::ok;
};

/// The state at time t with the given pose on the table and twist relative to it.
PlanarRigidState make_planar_rigid_state(const PlanarTableMotion& motion, double t,
                                         const PlanarPose& pose, const PlanarTwist& twist);

/// World (inertial-frame) pose and twist of the part: centre of mass, angle; velocity, spin.
PlanarPose world_pose(const PlanarRigidState& state);
/// The world pose of a part at `pose` on a table at `table` (only its x, y, angle are read).
PlanarPose world_pose(const PlanarTablePose& table, const PlanarPose& pose);
/// The world twist of a part at `pose` with `twist` relative to a table at `table`.
PlanarTwist world_twist(const PlanarTablePose& table, const PlanarPose& pose,
                        const PlanarTwist& twist);
PlanarTwist world_twist(const PlanarRigidState& state);

/// Advances `steps` steps: the contact core's step (core/step.hpp) on a model of this one body,
/// so a part alone moves exactly as a body of any model; `observer` (if any) sees the core's
/// state after each step (its one body: bodies[0]). The law must be isotropic and
/// velocity-independent (InvalidParameter naming "law" otherwise).
void advance_planar_rigid(const PlanarTableMotion& motion, const PlanarField& field,
                          const FrictionLaw& law, const RigidPart& part,
                          const TimeSteppingOptions& options, PlanarRigidState& state,
                          long long steps, MotionObserver* observer = nullptr);

}  // namespace selfalign
