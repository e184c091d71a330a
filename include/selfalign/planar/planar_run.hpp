#pragma once
/// \file planar_run.hpp
/// One recorded planar run: the run driver the CLI (`planar simulate`) and Python
/// (simulate_planar) share, so neither front end contains a step loop. From a pose and twist
/// at t = 0, Moreau's rigid-part stepper (planar_rigid.hpp) advances `steps` steps; the state
/// is recorded at t = 0, every `every` steps, and at the last step. With Method::exact the
/// exact point solver (planar_exact_point.hpp) computes the same run where it applies
/// (exact_point_applies), and with Method::integrator the patch integrator
/// (planar_patch_integrator.hpp) for any part on a translating table with piecewise-constant
/// accelerations, recorded at the same times (the step h then only sets them).

#include <cstdint>
#include <functional>
#include <vector>

#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/simulate/slip_integrator.hpp"  // IntegratorStatistics

namespace selfalign {

/// The recorded samples, one entry per sample in every column.
struct PlanarTrajectory {
  std::vector<double> t;                   ///< time [-]
  std::vector<double> x, y, angle;         ///< pose on the table [-], [rad]
  std::vector<double> ux, uy, omega;       ///< twist relative to the table, table axes [-]
  std::vector<double> table_x, table_y, table_angle;  ///< the table's world pose
  std::vector<PatchMode> mode;             ///< how the step that ended there ended
  std::vector<std::int32_t> pivot;         ///< the pivot contact for mode pivot, else -1
  PlanarCensus census;                     ///< every step of the run (not only the samples)
  IntegratorStatistics integration;        ///< the patch integrator's work (Method::integrator)
  PlanarRigidState end;                    ///< the state after the last step
  std::size_t size() const noexcept { return t.size(); }
};

/// Steps of a run of `periods` table periods (InvalidParameter naming "periods" for a negative
/// count or a table at rest, which has no period: give a duration).
long long planar_steps_of_periods(const PlanarProblem& problem, long long periods);
/// Steps of a run of `duration` [-] (InvalidParameter naming "duration" unless it is >= 0 and a
/// whole number of steps to 1e-9).
long long planar_steps_of_duration(const PlanarProblem& problem, double duration);

/// Called between chunks of steps with (steps done, steps): progress reports, and a front end's
/// cancellation (it may throw; the run stops there and the exception propagates).
using PlanarRunProgress = std::function<void(long long done, long long total)>;

/// The run. Validates the field, the part, the step and the law; InvalidParameter naming "every"
/// (< 1, or more than kMaxRecordedSamples samples) or "steps" (more than kMaxTimeSteps).
/// `progress` is called after every chunk of at most one period and 1e4 steps. A run whose
/// state or table motion leaves the finite numbers ends at that step: the trajectory's last
/// sample is the failing step and `end.status` is core::StepStatus::non_finite.
/// `method`: time_stepping (Moreau, any problem) or exact (the exact point solver: a point part
/// at its centre of mass on a uniform field, a translating table with piecewise-constant
/// accelerations; InvalidParameter naming "method" otherwise, and for integrator). An exact run
/// records the exact state at the sample times: mode stick where the relative velocity is 0,
/// else slip; the angle turns at the start's constant omega (no torque about a centred point);
/// the census stays empty (no steps). Method::integrator: the patch integrator
/// (planar_patch_integrator.hpp) with problem.integrator's tolerances, any part and field on a
/// translating table with piecewise-constant accelerations (InvalidParameter naming "method"
/// for a rotating table, else the integrator's own parameter), sampled at the same times with
/// the current mode and pivot; `integration` holds its work, the census stays empty.
PlanarTrajectory simulate_planar(const PlanarProblem& problem, const PlanarPose& pose,
                                 const PlanarTwist& twist, long long steps, long long every = 1,
                                 const PlanarRunProgress& progress = {},
                                 Method method = Method::time_stepping);

}  // namespace selfalign
