#pragma once
/// \file planar_analysis.hpp
/// Analyses of planar motion (issue 13) on the rigid-part stepper (planar_rigid.hpp): the
/// steady drift velocity and rotation rate of a periodic excitation, the drift field over table
/// positions and orientations, the stick/pivot/slip census per period, and stopping in a rough
/// region with the end pose, the process time and the positioning error as a 2-D region plus an
/// orientation error, over a set of entry poses. Every time is a whole number of table periods;
/// absent values (a part that never stops) are NaN.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "selfalign/analysis/sweep.hpp"  // ProgressCallback
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/simulate/slip_integrator.hpp"  // IntegratorOptions

namespace selfalign {

/// Everything one planar run needs. The motion's profiles must outlive the problem.
struct PlanarProblem {
  PlanarTableMotion motion;
  PlanarField field = UniformPlanarField{};
  FrictionLaw law;
  RigidPart part;
  TimeSteppingOptions options;
  IntegratorOptions integrator;  ///< the patch integrator's tolerances (Method::integrator)
};

/// Throws InvalidParameter naming the first invalid part (motion, field, law, part, step); the
/// step must divide the motion's period into 2 .. 1e8 whole steps (to 1e-9).
void validate(const PlanarProblem& problem);

/// Steps per table period.
long long steps_per_period(const PlanarProblem& problem);

/// Whether the exact point solver (planar_exact_point.hpp) takes the problem: a point part at
/// its centre of mass, a uniform field, a table that translates (no rotation) with
/// piecewise-constant accelerations along both directions.
bool exact_point_applies(const PlanarProblem& problem);

/// Whether the patch integrator (planar_patch_integrator.hpp) takes the problem: a table that
/// translates (no rotation, no normal motion) with piecewise-constant accelerations along both
/// directions; any part, field and planar law.
bool patch_integrator_applies(const PlanarProblem& problem);

/// Throws InvalidParameter naming `name` when `periods` periods of one run exceed the
/// time-stepping cap of simulate.hpp (kMaxTimeSteps = 1e9 steps).
void require_planar_steps(const char* name, double periods, const PlanarProblem& problem);

/// The mean friction level under the patch at `pose`: the load-weighted field level at the
/// contact points [-] (the planar counterpart of eq. 7's average over the footprint).
double level_under_patch(const PlanarField& field, const ContactPatch& patch,
                         const PlanarPose& pose);

/// Whether a level under the patch that ranged over [lo, hi] changed: by more than 1e-9 of it.
inline bool levels_differ(double lo, double hi) noexcept {
  return hi - lo > 1e-9 * std::max(hi, 1e-300);
}

/// Steps of each kind.
struct PlanarCensus {
  long long stick = 0, pivot = 0, slip = 0;
  long long total() const noexcept { return stick + pivot + slip; }
  /// Counts one step that ended in `mode`.
  void add(PatchMode mode) noexcept;
};

struct PlanarSteadyResult {
  double drift_x = 0, drift_y = 0;  ///< mean velocity over the last window, table frame [-]
  double rotation_rate = 0;         ///< mean spin relative to the table [-]
  double change = 0;  ///< |drift(last window) - drift(window before)| [-]: the transient's trace
  PlanarCensus census;              ///< over the last window
  PlanarPose end_pose;
  /// The least and largest mean friction level under the patch (the load-weighted field level
  /// at the contact points) over both windows [-]. Equal where the field is uniform along the
  /// way; apart when the part met a friction change while the drift was averaged, and then the
  /// drift and rotation rate are no steady state (level_changed()).
  double level_min = 0, level_max = 0;
  /// Whether the level under the patch changed during the windows (levels_differ).
  bool level_changed() const noexcept { return levels_differ(level_min, level_max); }
};

/// Runs `transient_periods` periods from (pose, twist) at t = 0, then two windows of
/// `window_periods`; reports the last window's drift, spin and census, and the range of the
/// friction level under the patch over both windows (a window average is a steady state only
/// where that level does not change).
PlanarSteadyResult planar_steady(const PlanarProblem& problem, const PlanarPose& pose,
                                 const PlanarTwist& twist, int transient_periods,
                                 int window_periods);

/// One drift-field sample: from rest at (x, y, angle), the mean drift over `periods` periods.
struct PlanarDriftSample {
  double x = 0, y = 0, angle = 0;
  double drift_x = NAN, drift_y = NAN, rotation_rate = NAN;  ///< [-]; NaN when it failed
  PlanarCensus census;
  /// Empty when computed; otherwise why this sample could not be (e.g. the state left the
  /// finite numbers). A failed sample never aborts the field.
  std::string failure;
};

/// The drift field on the grid xs x ys x angles (angle fastest, then x, then y), in parallel
/// on `threads` workers (0: all cores) through the studies' one parallel loop (each sample
/// computed into its own slot: results independent of the thread count; a sample that fails
/// is kept with its failure, the others computed). `progress` (optional, one call at a time)
/// gets (samples done, samples); an exception it throws stops the study and propagates.
std::vector<PlanarDriftSample> planar_drift_field(const PlanarProblem& problem,
                                                  const std::vector<double>& xs,
                                                  const std::vector<double>& ys,
                                                  const std::vector<double>& angles, int periods,
                                                  const ProgressCallback& progress = {},
                                                  int threads = 0);

/// One stopping run.
struct PlanarStopRun {
  PlanarPose entry;
  bool stopped = false;
  PlanarPose end;               ///< NaN when it did not stop
  /// T_p: when the final stick began, to the step h: the end of the last step that did not end
  /// in stick (0 for a part that never moved) [-]; NaN when it did not stop.
  double process_time = NAN;
  long long periods = 0;        ///< periods simulated
  /// Empty when the run was computed; otherwise why it could not be (then stopped is false).
  std::string failure;
};

/// The positioning error over the stopped runs: the 2-D region of end positions (bounding box,
/// largest distance from their mean) and the orientation error (range of end angles).
struct PlanarStopSummary {
  std::vector<PlanarStopRun> runs;
  long long stopped = 0;
  long long failed = 0;          ///< runs that could not be computed (their failure says why)
  double mean_x = NAN, mean_y = NAN, mean_angle = NAN;
  double min_x = NAN, max_x = NAN, min_y = NAN, max_y = NAN;
  double radius = NAN;           ///< max |end - mean| [-]
  double angle_range = NAN;      ///< max - min end angle [rad]
  double max_process_time = NAN; ///< over the stopped runs [-]; NaN when none stopped
  /// Proven that no part is ever stuck for a whole period (as the 1-D StoppingRun's
  /// never_stops): on a table that does not turn, a part at rest on it needs a friction impulse
  /// equal to the table's velocity change over each step, and its patch gives at most
  /// h s max m (the loads sum to 1); some step of the period asks more
/// (largest_step_velocity_change, as the time-stepped 1-D run's). The runs are then not
  /// simulated (not stopped, 0 periods).
  bool never_stops = false;
};

/// From rest at each entry pose, runs until the part sticks for a whole period (stopped: the
/// one stopping criterion, analysis/final_stick.hpp, as the 1-D stopping run's) or max_periods
/// pass, unless no part can ever be held (never_stops); the entries in parallel as
/// planar_drift_field's samples (a failed run kept with its failure). `progress` (optional)
/// gets (entries done, entries).
PlanarStopSummary planar_stop(const PlanarProblem& problem, const std::vector<PlanarPose>& entries,
                              int max_periods, const ProgressCallback& progress = {},
                              int threads = 0);

}  // namespace selfalign
