#pragma once
/// \file planar_patch_integrator.hpp
/// The event-driven solver for a rigid part on a contact patch (issue 22, item 4): a higher
/// order method between mode changes, with stick and pivot decided exactly at the events,
/// where Moreau's stepper (planar_rigid.hpp) is first order in h.
///
/// Between events the part is in one of three modes (docs/planar-integrator.md derives them):
///  - stick: at rest on the table, exactly (twist 0), while the table's acceleration A stays in
///    the patch's static limit set, (A, 0) in L_s (patch_impulse.hpp); with piecewise-constant
///    accelerations that is decided once per segment;
///  - slip: every contact point slides; the smooth ODE
///      xi' = u, phi' = w,   (u, w)' = (-A, 0) + sum_i G_i^T f_i / (1, 1, j),
///      f_i = -k m(p_i) w_i g_i / |g_i|,   g_i = G_i (u, w) the slip velocity of contact i,
///    integrated by Boost.Odeint's controlled Dormand-Prince 5(4) (the stepper of the 1-D slip
///    integrator, slip_integrator.hpp, with the same tolerances IntegratorOptions);
///  - pivot about contact j: g_j = 0 exactly, the twist s r_j (r_j = (d_jy, -d_jx, 1)), the
///    reduced ODE s' = r_j^T F_o / (r_j^T M r_j) (F_o: the drive and the other contacts'
///    friction), while contact j's friction lambda_j stays in its kinetic disc.
/// Events, each deciding the next mode by the acceleration-level problem, which is the patch
/// impulse problem with h = 1 (PatchImpulseSolver: certificates, no velocity threshold):
///  - a contact's slip velocity reaches 0 (finite-time arrival; in 2-D a sign-change detector
///    never sees it): the steps are shortened toward its linearly predicted arrival until the
///    slip is below the snap size (absolute_tolerance + relative_tolerance times the run's
///    largest slip speed), and the arrival is closed by one Euler step of that size; then the
///    twist is projected onto the pivot line (or set to 0 when every contact has arrived) and
///    the mode decided;
///  - a pivot's spin reaches 0 or its friction leaves its disc: located on the step by TOMS 748
///    (re-stepping from the step's start);
///  - a switch of the table acceleration (a window end): stick and pivot are decided again.
///
/// Applies to a translating table (no rotation, no normal motion) with piecewise-constant
/// accelerations along both directions, any planar field, an isotropic velocity-independent
/// law (static s >= kinetic k: stick and departures tested with s, slip and pivots with k, as
/// the Moreau stepper).

#include <vector>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/patch_impulse.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/planar/rigid_part.hpp"
#include "selfalign/simulate/slip_integrator.hpp"  // IntegratorOptions, IntegratorStatistics

namespace selfalign {

/// The solver's state: pose on the table and twist relative to it (table axes = world axes on
/// a translating table), the current mode, and what the next call needs to continue an arc.
struct PlanarPatchState {
  double t = 0;
  PlanarPose pose;    ///< on the table [-], [rad]
  PlanarTwist twist;  ///< relative to the table [-]
  PatchMode mode = PatchMode::stick;  ///< the current mode (stick: at rest on the table)
  int pivot = -1;                     ///< the pivot contact (mode pivot), else -1
  /// Continuation data (not physics): the pivot's spin direction (+1, -1) while it is 0 at its
  /// start, and the departure direction of every contact whose slip is exactly 0 in mode
  /// slip (x, y per contact; 0 where the slip itself gives the direction).
  int sense = 0;
  std::vector<double> departure;
  /// The largest contact slip speed seen so far [-]: scales the snap size of arrivals.
  double speed_scale = 0;
  /// The step the controller proposed last [-] (0: none yet).
  double step_guess = 0;
};

/// A state at rest or moving at time t (mode decided by the first advance).
PlanarPatchState make_planar_patch_state(double t, const PlanarPose& pose,
                                         const PlanarTwist& twist);

/// Advances to t_end (>= state.t). Throws InvalidParameter naming "rotation" (a rotating
/// table), "normal", "first"/"second" (a profile without piecewise-constant acceleration),
/// "law", the part's or the field's parameter, the tolerances, or "relative_tolerance" when
/// more than options.max_steps_per_period steps per table period would be needed.
/// `stats` (optional) accumulates steps, rejections, right-hand sides, events, slips and sticks.
void advance_planar_integrated(const PlanarTableMotion& motion, const PlanarField& field,
                               const FrictionLaw& law, const RigidPart& part,
                               const IntegratorOptions& options, PlanarPatchState& state,
                               double t_end, IntegratorStatistics* stats = nullptr);

}  // namespace selfalign
