#include "selfalign/analysis/convergence.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/analysis/period_map.hpp"

namespace selfalign {
namespace {

struct ResponseArcs {
  std::vector<Arc> arcs;
  // The arc containing t (arcs are contiguous and sorted); t in [t0, t_end].
  const Arc& at(double t) const {
    auto it = std::upper_bound(arcs.begin(), arcs.end(), t,
                               [](double value, const Arc& a) { return value < a.t1; });
    return it == arcs.end() ? arcs.back() : *it;
  }
};

// The selected friction force's class on an arc: +1 / -1 while slipping, 0 while sticking.
int friction_class(const Arc& a) { return a.kind() == ArcKind::stick ? 0 : a.direction; }

// One response under the slip integrator (speed-dependent laws): its stick and slip intervals,
// contiguous and sorted, with their friction class (the interval's direction).
struct IntervalList {
  std::vector<MotionInterval> intervals;
  const MotionInterval& at(double t) const {
    auto it = std::upper_bound(intervals.begin(), intervals.end(), t,
                               [](double value, const MotionInterval& i) { return value < i.t1; });
    return it == intervals.end() ? intervals.back() : *it;
  }
};

// A response's friction class and velocity wherever the analysis asks: the exact solver's arcs
// (closed form at any t), or the integrator's intervals (class) and a second run that stops at
// every sample time (velocity; the integrator places its events the same way whatever the
// stops, to its tolerance).
struct Response final : MotionObserver {
  ResponseArcs arcs;
  IntervalList intervals;
  std::vector<double> v;  // at the sample times (integrator)
  void on_motion(const MotionInterval& piece, const Arc* arc) override {
    if (piece.t1 <= piece.t0) return;
    if (arc) arcs.arcs.push_back(*arc);
    else intervals.intervals.push_back(piece);
  }
  int friction_class_at(double t, bool exact) const {
    return exact ? friction_class(arcs.at(t)) : intervals.at(t).direction;
  }
  bool stuck_at(double t, bool exact) const { return friction_class_at(t, exact) == 0; }
};

}  // namespace

VelocityConvergence velocity_convergence(const TableProfile& profile, const ConvergenceOptions& o) {
  return velocity_convergence(profile, FrictionLaw{}, o);
}

VelocityConvergence velocity_convergence(const TableProfile& profile, const FrictionLaw& law,
                                         const ConvergenceOptions& o) {
  require_exact_profile(profile, "convergence");
  require_moderate("v1", o.v1);
  require_moderate("v2", o.v2);
  require_moderate("t0", o.t0);
  // Every arc and sample is kept: at most 1e6 periods and 1e7 samples (~1 GB).
  constexpr double kMaxPeriods = 1e6, kMaxSamples = 1e7;
  const double P = profile.period();
  require_positive("duration", o.duration);
  if (!(o.duration <= kMaxPeriods * P))
    throw InvalidParameter("duration", o.duration,
                           "must be <= 1e6 table periods (" + format_number(kMaxPeriods * P) + ")");
  if (o.samples_per_period < 1 || o.samples_per_period > 1'000'000)
    throw InvalidParameter("samples_per_period", o.samples_per_period, "must be in [1, 1e6]");
  if (!(std::ceil(o.duration / P) * o.samples_per_period <= kMaxSamples))
    throw InvalidParameter("samples_per_period", o.samples_per_period,
                           "gives more than 1e7 samples over the run (periods x "
                           "samples_per_period <= 1e7)");

  const PeriodMap map(profile, law, PeriodMapOptions{.integrator = o.integrator});
  const double t_end = o.t0 + o.duration;
  // Both responses need at least one arc: a run shorter than the rounding of t0 has none
  // (t0 = 1e-300 with duration 5e-324 read past an empty arc list; Python API fuzz, seed 8).
  if (!(o.duration >= 1e-9 * P && t_end > o.t0 && std::abs(o.t0) <= 1e8 * P))
    throw InvalidParameter("duration", o.duration,
                           "must be >= 1e-9 table periods and resolvable at t0 (|t0| <= 1e8 "
                           "periods)");
  const bool exact = map.has_arcs();
  if (!exact && map.method() != Method::integrator)
    throw InvalidParameter("profile", profile.kind(),
                           "convergence needs the exact solver or the slip integrator");
  Response r1, r2;
  for (auto [resp, v0] : {std::pair{&r1, o.v1}, std::pair{&r2, o.v2}}) {
    PeriodMap::Run run = map.start({o.t0, 0, v0});
    run.advance_to(t_end, resp);
  }

  // Breakpoints: every arc (interval) boundary of either trajectory.
  std::vector<double> breaks{o.t0, t_end};
  for (const Response* resp : {&r1, &r2}) {
    for (const Arc& a : resp->arcs.arcs) breaks.push_back(a.t1);
    for (const MotionInterval& i : resp->intervals.intervals) breaks.push_back(i.t1);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  while (!breaks.empty() && breaks.back() > t_end) breaks.pop_back();

  VelocityConvergence r;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double mid = 0.5 * (breaks[i] + breaks[i + 1]);
    const bool same = r1.friction_class_at(mid, exact) == r2.friction_class_at(mid, exact);
    if (!r.intervals.empty() && r.intervals.back().same == same)
      r.intervals.back().t_end = breaks[i + 1];
    else
      r.intervals.push_back({breaks[i], breaks[i + 1], same});
    const bool both_stuck = r1.stuck_at(mid, exact) && r2.stuck_at(mid, exact);
    if (both_stuck && !r.t_coincide) r.t_coincide = breaks[i];
  }

  // Samples: a uniform grid merged with the breakpoints.
  std::vector<double> times = breaks;
  const double dt = profile.period() / o.samples_per_period;
  for (double t = o.t0 + dt; t < t_end; t += dt) times.push_back(t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (!exact) {
    for (auto [resp, v0] : {std::pair{&r1, o.v1}, std::pair{&r2, o.v2}}) {
      PeriodMap::Run run = map.start({o.t0, 0, v0});
      for (double t : times) resp->v.push_back(t == o.t0 ? v0 : run.advance_to(t, nullptr, {}).xd);
    }
  }
  for (std::size_t j = 0; j < times.size(); ++j) {
    const double t = times[j];
    const double v1 = exact ? r1.arcs.at(t).at(t).xd : r1.v[j];
    const double v2 = exact ? r2.arcs.at(t).at(t).xd : r2.v[j];
    r.t.push_back(t);
    r.v1.push_back(v1);
    r.v2.push_back(v2);
    r.lyapunov.push_back(0.5 * (v1 - v2) * (v1 - v2));  // eq. (35)
  }
  return r;
}

}  // namespace selfalign
