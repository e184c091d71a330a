#pragma once
/// \file state.hpp
/// The contact core's state (issue 21, first slice): everything that changes, sized from the
/// model (MuJoCo's mjData): time, the table's pose, per body its pose, twist, contact mode,
/// solver warm start and work counters, and a status that the step sets instead of throwing
/// inside its loop.

#include <span>
#include <vector>

#include "selfalign/core/chain_problem.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/step_loads.hpp"
#include "selfalign/planar/patch_impulse.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/planar/rigid_part.hpp"

namespace selfalign::core {

/// How the last step ended: ok; the table's motion or a body's state left the finite numbers
/// (non_finite: the run stops there; `failed_body` is the body, -1 for the table's motion); or
/// the table's normal motion lifts the bodies off in the next step (lift_off: its normal
/// impulse is negative, Model::gravity; the run stops before that step, whose flight the core
/// does not integrate yet).
enum class StepStatus { ok, non_finite, lift_off };

struct BodyState {
  PlanarPose pose;                    ///< on the table [-], [rad] (a 1-D part: x only)
  PlanarTwist twist;                  ///< relative to the table, table axes [-] (1-D: ux = x')
  PatchMode mode = PatchMode::stick;  ///< how the last step ended
  int pivot = -1;                     ///< the pivot contact (mode pivot)
  long long sweeps = 0, newton_steps = 0;  ///< impulse-solver work so far
  PatchImpulseSolver solver;          ///< warm start of the impulse solver
  /// Height above the table and its rate [-] (Gravity::flight; 0 while in contact).
  double height = 0, normal_velocity = 0;
};

/// The row stage's workspace (Model::part_contacts; no allocation per step once sized): per
/// body its position and velocity at the step's start, per chain its parts.
struct RowWork {
  std::vector<double> x0, v0;             ///< per body
  std::vector<signed char> chained;       ///< per body: in a chain this step
  std::vector<signed char> active;        ///< per part contact: active this step
  std::vector<int> behind, ahead;         ///< per body: the contact behind / ahead of it (-1)
  std::vector<int> bodies;                ///< one chain's bodies, rear to front
  std::vector<ChainPart> parts;
  std::vector<ChainFriction> chain_friction;
  std::vector<double> c, v;
  ChainWorkspace chain;
};

struct State {
  double t0 = 0, t = 0;          ///< step times are t0 + k h
  long long step_index = 0;
  PlanarTablePose table;         ///< the table at t
  std::vector<BodyState> bodies; ///< one per model body
  StepStatus status = StepStatus::ok;
  int failed_body = -1;          ///< the body that left the finite numbers (non_finite; -1: the table)
  std::vector<std::vector<PatchContact>> contacts;  ///< workspace, one per body (no allocation per step)
  std::vector<StepLoads> loads;  ///< workspace: per body, its step's loads
  RowWork row;                   ///< workspace of the row stage (part contacts)
};

/// The state at time t with body i at poses[i] on the table and twists[i] relative to it
/// (sizes: the model's body count, else InvalidParameter naming "poses" or "twists"). Parts of a
/// row must not overlap: InvalidParameter naming "poses[i]" (i the front part of the contact)
/// where (x_front - length_front) - x_rear < 0.
State make_state(const Model& model, double t, std::span<const PlanarPose> poses,
                 std::span<const PlanarTwist> twists);

}  // namespace selfalign::core
