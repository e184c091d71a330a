#include "selfalign/planar/planar_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/analysis/final_stick.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxTimeSteps
#include "step_sinks.hpp"

namespace selfalign {
namespace {

using detail::CensusSink;
using detail::compact;
using detail::LevelSink;
using detail::require_finite;

void run_periods(const PlanarProblem& p, PlanarRigidState& s, long long periods,
                 MotionObserver* sink = nullptr) {
  advance_planar_rigid(p.motion, p.field, p.law, p.part, p.options, s,
                       periods * steps_per_period(p), sink);
}


SweepOptions cells_options(const ProgressCallback& progress, int threads) {
  SweepOptions o;
  o.threads = threads;
  o.progress = progress;
  return o;
}

}  // namespace

double level_under_patch(const PlanarField& field, const ContactPatch& patch,
                         const PlanarPose& pose) {
  const double c = std::cos(pose.angle), sn = std::sin(pose.angle);
  double level = 0;
  for (const ContactPoint& r : patch)
    level += r.load * planar_level(field, pose.x + c * r.x - sn * r.y, pose.y + sn * r.x + c * r.y);
  return level;
}

void require_planar_steps(const char* name, double periods, const PlanarProblem& p) {
  const double steps = periods * static_cast<double>(steps_per_period(p));
  if (!(steps <= kMaxTimeSteps))
    throw InvalidParameter(name, periods, "gives " + compact(steps) + " steps per run; at most 1e9");
}

void PlanarCensus::add(PatchMode mode) noexcept {
  switch (mode) {
    case PatchMode::stick: ++stick; break;
    case PatchMode::pivot: ++pivot; break;
    case PatchMode::slip: ++slip; break;
  }
}

void validate(const PlanarProblem& p) {
  validate(p.motion);
  require_no_normal_motion(p.motion, "a planar problem");
  validate(p.field);
  require_planar_law(p.law);
  validate(p.part);
  validate(p.options);
  steps_per_period(p);
}

bool patch_integrator_applies(const PlanarProblem& p) {
  if (p.motion.rotation || p.motion.normal) return false;
  for (const TableProfile* profile : {p.motion.first, p.motion.second}) {
    if (!profile) continue;
    const PiecewisePolynomialProfile* pwp = profile->piecewise_polynomial();
    if (!pwp) return false;
    for (const AccelerationSegment& s : pwp->segments())
      if (s.jerk != 0) return false;
  }
  return true;
}

bool exact_point_applies(const PlanarProblem& p) {
  const ContactPatch& patch = p.part.patch;
  if (patch.size() != 1 || patch[0].x != 0 || patch[0].y != 0) return false;
  return std::holds_alternative<UniformPlanarField>(p.field) && patch_integrator_applies(p);
}

long long steps_per_period(const PlanarProblem& p) {
  const double period = planar_period(p.motion);
  const double n = period / p.options.step;
  if (!(n >= 2 && n <= 1e8) || !(std::abs(n - std::round(n)) <= 1e-9 * n))
    throw InvalidParameter("step", p.options.step,
                           "must divide the period " + std::to_string(period) +
                               " into 2 to 1e8 whole steps");
  return static_cast<long long>(std::llround(n));
}

PlanarSteadyResult planar_steady(const PlanarProblem& p, const PlanarPose& pose,
                                 const PlanarTwist& twist, int transient_periods,
                                 int window_periods) {
  validate(p);
  if (transient_periods < 0 || transient_periods > 100000)
    throw InvalidParameter("transient", std::to_string(transient_periods), "must be in [0, 100000]");
  if (window_periods < 1 || window_periods > 100000)
    throw InvalidParameter("window", std::to_string(window_periods), "must be in [1, 100000]");
  require_planar_steps("transient", transient_periods + 2.0 * window_periods, p);
  const double span = window_periods * planar_period(p.motion);
  PlanarRigidState s = make_planar_rigid_state(p.motion, 0, pose, twist);
  run_periods(p, s, transient_periods);
  const PlanarPose a = s.pose;
  LevelSink levels(p.field, p.part.patch);
  run_periods(p, s, window_periods, &levels);
  const PlanarPose b = s.pose;
  CensusSink census;
  levels.census = &census;
  run_periods(p, s, window_periods, &levels);
  PlanarSteadyResult r;
  r.drift_x = (s.pose.x - b.x) / span;
  r.drift_y = (s.pose.y - b.y) / span;
  r.rotation_rate = (s.pose.angle - b.angle) / span;
  r.change = std::hypot(r.drift_x - (b.x - a.x) / span, r.drift_y - (b.y - a.y) / span);
  r.census = census.census;
  r.end_pose = s.pose;
  r.level_min = levels.lo;
  r.level_max = levels.hi;
  return r;
}

std::vector<PlanarDriftSample> planar_drift_field(const PlanarProblem& p,
                                                  const std::vector<double>& xs,
                                                  const std::vector<double>& ys,
                                                  const std::vector<double>& angles, int periods,
                                                  const ProgressCallback& progress, int threads) {
  validate(p);
  if (periods < 1 || periods > 100000)
    throw InvalidParameter("periods", std::to_string(periods), "must be in [1, 100000]");
  if (xs.empty() || ys.empty() || angles.empty())
    throw InvalidParameter("grid", "empty", "needs at least one x, y and angle");
  const double samples = static_cast<double>(xs.size()) * static_cast<double>(ys.size()) *
                         static_cast<double>(angles.size());
  if (samples > 1e7)
    throw InvalidParameter("grid", compact(samples) + " samples", "must have at most 1e7");
  require_planar_steps("periods", periods, p);
  for (double v : xs) require_moderate("grid x", v);
  for (double v : ys) require_moderate("grid y", v);
  for (double v : angles) require_moderate("grid angle", v);
  std::vector<PlanarDriftSample> out(xs.size() * ys.size() * angles.size());
  const double span = periods * planar_period(p.motion);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::size_t ia = i % angles.size(), ix = (i / angles.size()) % xs.size(),
                      iy = i / (angles.size() * xs.size());
    out[i].x = xs[ix], out[i].y = ys[iy], out[i].angle = angles[ia];
  }
  detail::parallel_cells(
      out.size(), cells_options(progress, threads),
      [&](std::size_t i) {
        PlanarDriftSample& d = out[i];
        PlanarRigidState s = make_planar_rigid_state(p.motion, 0, {d.x, d.y, d.angle}, {});
        CensusSink census;
        run_periods(p, s, periods, &census);
        require_finite(s);
        d.drift_x = (s.pose.x - d.x) / span;
        d.drift_y = (s.pose.y - d.y) / span;
        d.rotation_rate = (s.pose.angle - d.angle) / span;
        d.census = census.census;
      },
      [&](std::size_t i, const std::string& why) {
        out[i].drift_x = out[i].drift_y = out[i].rotation_rate = NAN;
        out[i].census = {};
        out[i].failure = why;
      });
  return out;
}

namespace {

// Whether no part can ever be stuck for a whole period (PlanarStopSummary::never_stops): the
// table does not turn, and at some step of a period (the steps repeat every period: h divides
// it) the table's velocity change exceeds the largest friction impulse of a patch at rest,
// h s max m, by more than the rounding of the velocities.
bool never_held(const PlanarProblem& p) {
  if (p.motion.rotation) return false;
  const double h = p.options.step;
  const double capacity = h * p.law.static_coefficient() * max_planar_level(p.field);
  return largest_step_velocity_change(p.motion, 0.0, h, steps_per_period(p)) >
         capacity * (1 + 1e-9) + 1e-15;
}

}  // namespace

PlanarStopSummary planar_stop(const PlanarProblem& p, const std::vector<PlanarPose>& entries,
                              int max_periods, const ProgressCallback& progress, int threads) {
  validate(p);
  if (max_periods < 1 || max_periods > 1000000)
    throw InvalidParameter("max_periods", std::to_string(max_periods), "must be in [1, 1000000]");
  if (entries.empty()) throw InvalidParameter("entries", "none", "needs at least one entry pose");
  if (entries.size() > 10000000)
    throw InvalidParameter("entries", std::to_string(entries.size()), "must be at most 1e7");
  require_planar_steps("max_periods", max_periods, p);
  PlanarStopSummary sum;
  sum.runs.resize(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    sum.runs[i].entry = entries[i];
    sum.runs[i].end = {NAN, NAN, NAN};
  }
  sum.never_stops = never_held(p);
  if (sum.never_stops) {
    if (progress) progress(entries.size(), entries.size());
    return sum;
  }
  detail::parallel_cells(
      entries.size(), cells_options(progress, threads),
      [&](std::size_t i) {
        PlanarStopRun& run = sum.runs[i];
        PlanarRigidState s = make_planar_rigid_state(p.motion, 0, entries[i], {});
        FinalStick stick(0.0);  // the one stopping criterion (analysis/final_stick.hpp)
        for (long long k = 1; k <= max_periods; ++k) {
          const double period_start = s.t;
          run_periods(p, s, 1, &stick);
          require_finite(s);
          run.periods = k;
          if (stick.stuck_since(period_start)) {  // stuck for a whole period
            run.stopped = true;
            run.end = s.pose;
            run.process_time = stick.since();  // the final stick's start, to the step
            break;
          }
        }
      },
      [&](std::size_t i, const std::string& why) {
        PlanarStopRun& run = sum.runs[i];
        run.stopped = false;
        run.end = {NAN, NAN, NAN};
        run.process_time = NAN;
        run.failure = why;
      });
  double sx = 0, sy = 0, sa = 0;
  for (const auto& r : sum.runs) sum.failed += !r.failure.empty();
  for (const auto& r : sum.runs)
    if (r.stopped) {
      ++sum.stopped;
      sx += r.end.x, sy += r.end.y, sa += r.end.angle;
    }
  if (sum.stopped == 0) return sum;
  sum.mean_x = sx / sum.stopped, sum.mean_y = sy / sum.stopped, sum.mean_angle = sa / sum.stopped;
  sum.min_x = sum.min_y = HUGE_VAL, sum.max_x = sum.max_y = -HUGE_VAL;
  double amin = HUGE_VAL, amax = -HUGE_VAL;
  sum.radius = 0, sum.max_process_time = 0;
  for (const auto& r : sum.runs)
    if (r.stopped) {
      sum.min_x = std::min(sum.min_x, r.end.x), sum.max_x = std::max(sum.max_x, r.end.x);
      sum.min_y = std::min(sum.min_y, r.end.y), sum.max_y = std::max(sum.max_y, r.end.y);
      amin = std::min(amin, r.end.angle), amax = std::max(amax, r.end.angle);
      sum.radius = std::max(sum.radius, std::hypot(r.end.x - sum.mean_x, r.end.y - sum.mean_y));
      sum.max_process_time = std::max(sum.max_process_time, r.process_time);
    }
  sum.angle_range = amax - amin;
  return sum;
}

}  // namespace selfalign
