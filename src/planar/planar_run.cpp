#include "selfalign/planar/planar_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/planar/planar_patch_integrator.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxTimeSteps, kMaxRecordedSamples

namespace selfalign {
namespace {

// Records the state every `every` steps, and counts every step's mode.
struct Recorder final : MotionObserver {
  PlanarTrajectory& out;
  long long every;
  long long last = -1;  // step index of the last sample
  Recorder(PlanarTrajectory& o, long long e) : out(o), every(e) {}
  // One sample: the time and step, the table, and the body (a PlanarRigidState or the core's
  // BodyState: both have pose, twist, mode and pivot).
  template <class Body>
  void record(double t, long long step_index, const PlanarTablePose& table, const Body& b) {
    out.t.push_back(t);
    out.x.push_back(b.pose.x), out.y.push_back(b.pose.y), out.angle.push_back(b.pose.angle);
    out.ux.push_back(b.twist.ux), out.uy.push_back(b.twist.uy);
    out.omega.push_back(b.twist.omega);
    out.table_x.push_back(table.x), out.table_y.push_back(table.y);
    out.table_angle.push_back(table.angle);
    out.mode.push_back(b.mode);
    out.pivot.push_back(b.pivot);
    last = step_index;
  }
  void record(const PlanarRigidState& s) { record(s.t, s.step_index, s.table, s); }
  void on_step(const core::State& s) override {
    out.census.add(s.bodies[0].mode);
    if (s.step_index % every == 0) record(s.t, s.step_index, s.table, s.bodies[0]);
  }
};

}  // namespace

long long planar_steps_of_periods(const PlanarProblem& p, long long periods) {
  if (!p.motion.first && !p.motion.second && !p.motion.rotation)
    throw InvalidParameter("periods", static_cast<double>(periods),
                           "needs a table profile (a table at rest: give duration)");
  if (periods < 0) throw InvalidParameter("periods", static_cast<double>(periods), "must be >= 0");
  const double steps = static_cast<double>(periods) * static_cast<double>(steps_per_period(p));
  if (steps > kMaxTimeSteps)
    throw InvalidParameter("steps", steps, "the run must have at most 1e9 steps");
  return static_cast<long long>(steps);
}

long long planar_steps_of_duration(const PlanarProblem& p, double duration) {
  require_non_negative("duration", duration);
  const double step = p.options.step;
  const double steps = std::round(duration / step);
  if (!(std::abs(duration / step - steps) <= 1e-9 * std::max(1.0, steps)))
    throw InvalidParameter("duration", duration,
                           "must be a whole number of steps (step " + format_number(step) + ")");
  if (steps > kMaxTimeSteps)
    throw InvalidParameter("steps", steps, "the run must have at most 1e9 steps");
  return static_cast<long long>(steps);
}

namespace {

// A run of an event-driven solver recorded at the step times k h (every `every` steps and the
// last), as the stepped runs are: advance(t, end) brings the solver to t and sets end's pose,
// twist, mode and pivot.
template <class Advance>
void sampled_run(const PlanarProblem& p, const PlanarPose& pose, const PlanarTwist& twist,
                 long long steps, long long every, const PlanarRunProgress& progress,
                 PlanarTrajectory& out, const Advance& advance) {
  Recorder rec(out, every);
  PlanarRigidState end = make_planar_rigid_state(p.motion, 0, pose, twist);
  const auto sample = [&](long long k) {
    const double t = static_cast<double>(k) * p.options.step;
    advance(t, end);
    end.t = t, end.step_index = k, end.table = table_pose(p.motion, t);
    rec.record(end);
  };
  sample(0);
  for (long long k = every; k < steps + every; k += every) {
    sample(std::min(k, steps));
    if (progress) progress(std::min(k, steps), steps);
  }
  out.end = end;
}

// The exact point solver's run (simulate_planar, Method::exact).
void exact_run(const PlanarProblem& p, const PlanarPose& pose, const PlanarTwist& twist,
               long long steps, long long every, const PlanarRunProgress& progress,
               PlanarTrajectory& out) {
  const UniformPlanarField& field = std::get<UniformPlanarField>(p.field);
  PlanarExactState s{0, pose.x, pose.y, twist.ux, twist.uy};
  sampled_run(p, pose, twist, steps, every, progress, out, [&](double t, PlanarRigidState& end) {
    advance_planar_exact_point(p.motion, field, p.law, s, t);
    end.pose = {s.x, s.y, pose.angle + twist.omega * t};
    end.twist = {s.ux, s.uy, twist.omega};
    end.mode = s.ux == 0 && s.uy == 0 ? PatchMode::stick : PatchMode::slip;
  });
}

// The patch integrator's run (simulate_planar, Method::integrator).
void integrated_run(const PlanarProblem& p, const PlanarPose& pose, const PlanarTwist& twist,
                    long long steps, long long every, const PlanarRunProgress& progress,
                    PlanarTrajectory& out) {
  PlanarPatchState s = make_planar_patch_state(0, pose, twist);
  sampled_run(p, pose, twist, steps, every, progress, out, [&](double t, PlanarRigidState& end) {
    advance_planar_integrated(p.motion, p.field, p.law, p.part, p.integrator, s, t,
                              &out.integration);
    end.pose = s.pose, end.twist = s.twist, end.mode = s.mode, end.pivot = s.pivot;
  });
}

}  // namespace

PlanarTrajectory simulate_planar(const PlanarProblem& p, const PlanarPose& pose,
                                 const PlanarTwist& twist, long long steps, long long every,
                                 const PlanarRunProgress& progress, Method method) {
  validate(p.field);
  validate(p.part);
  validate(p.options);
  require_planar_law(p.law);
  if (every < 1) throw InvalidParameter("every", static_cast<double>(every), "must be >= 1");
  if (!(steps >= 0 && static_cast<double>(steps) <= kMaxTimeSteps))
    throw InvalidParameter("steps", static_cast<double>(steps), "must be in [0, 1e9]");
  if (std::floor(static_cast<double>(steps) / static_cast<double>(every)) + 2 >
      kMaxRecordedSamples)
    throw InvalidParameter("every", static_cast<double>(every),
                           "the run would record more than 1e7 samples: raise every");
  PlanarTrajectory out;
  if (method == Method::exact) {
    if (!exact_point_applies(p))
      throw InvalidParameter("method", "exact",
                             "the exact point solver needs a point part at its centre of mass on "
                             "a uniform field, on a translating table with piecewise-constant "
                             "accelerations (use time-stepping)");
    exact_run(p, pose, twist, steps, every, progress, out);
    return out;
  }
  if (method == Method::integrator) {
    if (!patch_integrator_applies(p))
      throw InvalidParameter("method", "integrator",
                             "the patch integrator needs a translating table with "
                             "piecewise-constant accelerations (use time-stepping)");
    integrated_run(p, pose, twist, steps, every, progress, out);
    return out;
  }
  if (method != Method::time_stepping)
    throw InvalidParameter("method", to_string(method),
                           "must be time-stepping, exact or integrator");
  Recorder rec(out, every);
  PlanarRigidState s = make_planar_rigid_state(p.motion, 0, pose, twist);
  rec.record(s);
  // Chunks of at most one period and 1e4 steps between progress reports (a prompt Ctrl-C).
  constexpr long long kMaxChunk = 10000;
  const bool moving = p.motion.first || p.motion.second || p.motion.rotation;
  const long long chunk =
      moving ? std::clamp(static_cast<long long>(std::ceil(planar_period(p.motion) /
                                                           p.options.step)),
                          1LL, kMaxChunk)
             : kMaxChunk;
  for (long long done = 0; done < steps;) {
    const long long n = std::min(chunk, steps - done);
    advance_planar_rigid(p.motion, p.field, p.law, p.part, p.options, s, n, &rec);
    done += n;
    if (progress) progress(done, steps);
    if (s.status != core::StepStatus::ok) break;  // the core stopped at the failing step
  }
  if (rec.last != s.step_index) rec.record(s);
  out.end = s;
  return out;
}

}  // namespace selfalign
