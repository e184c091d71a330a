#include "selfalign/analysis/stopping.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "selfalign/analysis/final_stick.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/analysis/period_map.hpp"

namespace selfalign {

const char* to_string(StopKind kind) {
  switch (kind) {
    case StopKind::permanent_stick: return "permanent-stick";
    case StopKind::accumulation: return "accumulation";
    case StopKind::not_stopped: return "not-stopped";
  }
  return "?";
}

namespace {


// Watches the motion: entry into x >= x_mu, stops at x >= x_mu, and for each target the time
// from which x stays at or beyond it (reset whenever an arc ends below it). It takes the exact
// solver's arcs (crossings by bisection on their closed form) and the slip integrator's
// intervals (crossings located by the integrator as events on its dense output: watch()).
// The final stick's start is the one stopping criterion's (FinalStick, final_stick.hpp).
struct StopWatch final : MotionObserver {
  double x_mu;
  std::vector<double> targets;  // positions to time
  StoppingRun& run;
  FinalStick stick;
  std::vector<std::pair<double, double>> crossed;  // (position, time) in the open interval
  // A target's crossing on an arc, timed only when the run ends (resolve): a part that walks
  // stick-slip across a target crosses it again after every slide back, and only the last
  // crossing stands. nullopt: none pending (its time, if any, is in run.time_to_fraction).
  std::vector<std::optional<Arc>> pending;
  // The range of x since the last look (the period the run just advanced).
  double lo = kNaN, hi = kNaN;
  StopWatch(double x_mu_, std::vector<double> targets_, StoppingRun& r, double t0)
      : x_mu(x_mu_), targets(std::move(targets_)), run(r), stick(t0), pending(targets.size()) {}

  // The times of the crossings still pending.
  void resolve() {
    for (std::size_t k = 0; k < targets.size(); ++k)
      if (pending[k]) {
        run.time_to_fraction[k] = crossing(*pending[k], targets[k]);
        pending[k].reset();
      }
  }

  // The positions whose crossings the integrator should report, sorted.
  std::vector<double> watch() const {
    std::vector<double> w = targets;
    w.push_back(x_mu);
    std::sort(w.begin(), w.end());
    return w;
  }

  // First time on the arc at which x >= X (x is monotone on an arc): bisection on the closed
  // form, to a relative 1e-15 of the arc's length.
  static double crossing(const Arc& a, double X) {
    if (a.x0 >= X) return a.t0;
    double lo = a.t0, hi = a.t1;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * (1 + std::abs(hi)); ++i) {
      const double mid = 0.5 * (lo + hi);
      (a.at(mid).x >= X ? hi : lo) = mid;
    }
    return hi;
  }

  // One arc, interval or time step from x0 to x1 (x monotone on it), ending at t1 at rest
  // after moving (`stops`); crossing(X) is the first time at which x >= X on it, called only
  // when x0 < X <= x1.
  // `arc`: the piece's closed form, where it has one (its crossings are then timed lazily).
  template <class Crossing>
  void record(double x0, double x1, bool stops, const Arc* arc, Crossing crossing) {
    const double x_hi = std::max(x0, x1);
    if (std::isnan(run.entry_time) && x_hi >= x_mu) run.entry_time = crossing(x_mu);
    for (std::size_t k = 0; k < targets.size(); ++k) {
      double& t = run.time_to_fraction[k];
      if (x1 < targets[k]) {
        t = kNaN;  // back below (a slide back): not arrived yet
        pending[k].reset();
      } else if (std::isnan(t) && !pending[k]) {
        if (arc)
          pending[k] = *arc;
        else
          t = crossing(targets[k]);
      }
    }
    if (stops && x1 >= x_mu) run.stick_positions.push_back(x1);
  }
  // A piece ends at rest after moving: a slip ending at a velocity zero, or a time step that
  // ends at x' = 0 from x' != 0.
  static bool stops(const MotionInterval& i) {
    return i.end == ArcEnd::velocity_zero ||
           (i.end == ArcEnd::time_step && i.direction == 0 && i.xd0 != 0);
  }

  void on_crossing(double position, double time, int direction) override {
    if (direction > 0) crossed.emplace_back(position, time);
  }
  void on_motion(const MotionInterval& i, const Arc* arc) override {
    stick.on_motion(i, arc);
    lo = std::fmin(lo, std::fmin(i.x0, i.x1));  // x is monotone on a piece
    hi = std::fmax(hi, std::fmax(i.x0, i.x1));
    if (arc) {
      record(i.x0, i.x1, stops(i), arc, [&](double X) { return crossing(*arc, X); });
      return;
    }
    record(i.x0, i.x1, stops(i), nullptr, [&](double X) {
      if (i.x0 >= X) return i.t0;
      for (const auto& [position, time] : crossed)
        if (position == X) return time;
      return i.t1;  // reached at the interval's end (x1 == X to rounding)
    });
    crossed.clear();
  }
};

// Rest positions rising to x_stick,min with shrinking steps (the last three), the latest within
// kObservedAccumulationTol of the span x_stick,min - x_mu.
bool observed_accumulation(const std::vector<double>& x, double x_stick_min, double x_mu) {
  const std::size_t n = x.size();
  if (n < 5 || !std::isfinite(x_stick_min)) return false;  // three steps and the one before
  const double span = std::max(x_stick_min - x_mu, 0.0) + 1e-300;
  for (std::size_t i = n - 3; i < n; ++i)
    if (!(x[i] >= x[i - 1]) || !(x[i] - x[i - 1] <= x[i - 1] - x[i - 2] || x[i] == x[i - 1]))
      return false;
  return std::abs(x_stick_min - x[n - 1]) <= kObservedAccumulationTol * span;
}

}  // namespace

StoppingRun stopping_run(const TableProfile& profile, const FrictionMap& friction,
                         const ObjectState& start, const StoppingOptions& o) {
  return stopping_run(profile, friction, FrictionLaw{}, start, o);
}

StoppingRun stopping_run(const TableProfile& profile, const FrictionMap& friction,
                         const FrictionLaw& law, const ObjectState& start,
                         const StoppingOptions& o) {
  if (o.max_periods < 1) throw InvalidParameter("max_periods", o.max_periods, "must be >= 1");
  if (o.steps_per_period < 1)
    throw InvalidParameter("steps_per_period", o.steps_per_period, "must be >= 1");
  for (double p : o.fractions)
    if (!(p >= 0 && p <= 1)) throw InvalidParameter("fraction p", p, "must be in [0, 1]");

  const PiecewiseAffineFriction* pieces = friction.piecewise_affine();
  if (!pieces)
    throw InvalidParameter("friction", "not piecewise affine",
                           "a stopping run needs a piecewise-affine friction level (exact solver)");
  const double P = profile.period();
  PeriodMapOptions map_options;
  map_options.integrator = o.integrator;
  map_options.steps_per_period = o.steps_per_period;
  map_options.method = o.method;
  const PeriodMap period_map(profile, friction, law, map_options);
  // The largest |y''| a part at rest must resist: the profile's peak for the continuous motion
  // (eq. 40); for Moreau's scheme the largest velocity change of a step over h (the step holds
  // a part at rest at x exactly when h s m(x) bounds it: eq. 40 of the scheme, as the planar
  // stop's never-stops proof), on the run's own grid t0 + k h.
  const bool stepped = period_map.method() == Method::time_stepping;
  if (stepped && static_cast<double>(o.steps_per_period) * o.max_periods > kMaxTimeSteps)
    throw InvalidParameter("steps_per_period", o.steps_per_period,
                           "times max_periods (" + std::to_string(o.max_periods) +
                               ") must be at most 1e9 time steps");
  const double peak =
      stepped ? largest_step_velocity_change(PlanarTableMotion{&profile}, start.t,
                                             period_map.step(), o.steps_per_period) /
                    period_map.step()
              : profile.peak_acceleration();
  // The paper's table under the paper's law: eqs. (41), (59), (60) as written; otherwise their
  // general forms (the rise of the level, s m(x) >= peak), and no accumulation proof (nor for a
  // time-stepped run: eqs. 59, 60 are of the continuous motion).
  const TwoRegionTable* two = friction.two_region();
  const bool paper = two && law.is_unit();
  const double x_mu = friction_rise(friction);
  StoppingRun r;
  r.method = period_map.method();
  r.x_stick_min = paper ? stick_position_min(*two, peak) : stick_position_min(*pieces, law, peak);
  r.entry_time = kNaN;
  r.end_position = r.process_time = kNaN;  // absent until a proof of the stop is found
  r.time_to_fraction.assign(o.fractions.size(), kNaN);
  r.periods_to_fraction.assign(o.fractions.size(), -1);
  std::vector<double> targets;
  for (double p : o.fractions)
    targets.push_back(x_mu + p * (r.x_stick_min - x_mu));

  // The accumulation proof needs the three-phase structure behind eq. (59). Its stick
  // positions are where the object rests through [t0, t1], so the run looks at the object at
  // phase t1, the end of that rest (phase 0 for other profiles): on the diagonal y3'' = y2''
  // the object is still sliding back at phase 0 (docs/accumulation.md). The look's time is
  // formed as the solver forms the switch's, n Δt + begin with the segments' own Δt (their
  // durations' sum, which may differ from the profile's nominal period by rounding), so that
  // it lands on the switch itself, not an ulp past it (where the slip under -y2'' has begun).
  const ThreePhaseProfile* three_phase = profile.three_phase();
  const PiecewisePolynomialProfile* pwc = profile.piecewise_polynomial();
  std::unique_ptr<StickPositionMap> map;
  if (three_phase && paper && !stepped)
    map = std::make_unique<StickPositionMap>(*three_phase, *two);
  const double phase = stopping_look_phase(profile);

  PeriodMap::Run run = period_map.start(start);
  StopWatch watch(x_mu, targets, r, start.t);  // at rest at t0: stopped since t0
  const double P_segments = pwc ? pwc->period() : P;
  const bool integrated = period_map.method() == Method::integrator;
  const std::vector<double> watched = integrated ? watch.watch() : std::vector<double>{};
  long long n_first = period_map.method() == Method::exact && pwc
                          ? run.exact_state().period_index
                          : static_cast<long long>(std::floor(start.t / P_segments));
  if (static_cast<double>(n_first) * P_segments + phase <= start.t) ++n_first;
  ObjectState previous{0, std::numeric_limits<double>::quiet_NaN(), 0};
  long long look = n_first;
  auto advance_to_look = [&] {  // the next look (phase t1)
    const double t_look = static_cast<double>(look++) * P_segments + phase;
    run.advance_to(t_look, &watch, watched);
  };
  double last_look = std::numeric_limits<double>::quiet_NaN();  // a period before this look
  const bool can_jump = period_map.method() == Method::exact && pwc;
  for (int k = 0; k < o.max_periods && r.kind == StopKind::not_stopped; ++k) {
    watch.lo = watch.hi = run.state().x;
    advance_to_look();
    const ObjectState& obj = run.state();
    const double window_start = last_look;
    last_look = obj.t;
    // The one stopping criterion (final_stick.hpp): at rest through the whole period since the
    // last look. The closed forms below prove it sooner where they apply (eq. 40 at the first
    // rest); this catches the others (a time-stepped run's stick).
    if (obj.xd == 0 && obj.x >= x_mu && watch.stick.stuck_since(window_start)) {
      r.kind = StopKind::permanent_stick;
      r.end_position = obj.x;
      r.process_time = watch.stick.since();
      break;
    }
    if (obj.x == previous.x && obj.xd == previous.xd) break;  // periodic orbit, not a stop
    // No position holds the object (eq. 41 gives +inf): it can never stop for good. Once its
    // entry is known there is nothing left to find.
    if (std::isinf(r.x_stick_min) && !std::isnan(r.entry_time)) {
      r.never_stops = true;
      break;
    }
    // Below the rise, at rest at this look and the one before: the next periods repeat the
    // last one's motion shifted by its displacement (the same start at the same phase on the
    // same level) while they stay on one constant level below x_mu. Jump over them at once,
    // one period short of the level's end (nothing is observed there: no target, entry or
    // rest position lies below x_mu).
    if (can_jump && obj.xd == 0 && previous.xd == 0 && obj.x > previous.x && obj.x < x_mu) {
      const double dx = obj.x - previous.x;
      const AffinePiece& pc = pieces->pieces()[pieces->piece_index(watch.lo)];
      const double room = std::min(pc.end, x_mu) - watch.hi;
      const double whole = std::floor(room / dx) - 1;
      const long long periods = static_cast<long long>(
          std::min(whole, static_cast<double>(o.max_periods - k - 1)));
      if (pc.slope == 0 && pc.begin <= watch.lo && periods >= 2 &&
          run.jump_periods(periods, static_cast<double>(periods) * dx)) {
        look += periods;
        k += static_cast<int>(periods);
        watch.stick = FinalStick(watch.stick.since() + static_cast<double>(periods) * P_segments);
        previous = run.state();
        last_look = previous.t;
        continue;
      }
    }
    previous = obj;
    if (obj.xd != 0 || obj.x < x_mu) continue;
    if (sticks_permanently(friction, law, peak, obj.x)) {  // eq. (40)
      r.kind = StopKind::permanent_stick;
      r.end_position = obj.x;
      r.process_time = watch.stick.since();
    } else if (map && map->proves_accumulation_from(obj.x)) {  // eqs. (59), (60)
      r.kind = StopKind::accumulation;
      r.accumulation_proven = true;
      r.end_position = map->fixed_point();
      r.process_time = std::numeric_limits<double>::infinity();
    } else if (!map && observed_accumulation(r.stick_positions, r.x_stick_min, x_mu)) {
      r.kind = StopKind::accumulation;
      r.end_position = r.x_stick_min;
      r.process_time = std::numeric_limits<double>::infinity();
    }
  }
  // Accumulation: keep going (finite for p < 1) until the object rests at or beyond every
  // target below the end position. The stick positions then only rise, and every motion
  // between two of them stays above the first, so the times recorded are final.
  if (r.kind == StopKind::accumulation)
    for (int k = 0; k < o.max_periods; ++k) {
      bool pending = false;
      for (double target : targets)
        pending = pending || (run.state().x < target && target < r.end_position);
      if (!pending) break;
      advance_to_look();
    }
  watch.resolve();
  for (std::size_t i = 0; i < targets.size(); ++i)
    if (!std::isnan(r.time_to_fraction[i]) && !std::isnan(r.entry_time))
      r.periods_to_fraction[i] =
          static_cast<int>(std::ceil((r.time_to_fraction[i] - r.entry_time) / P - 1e-12));
  return r;
}

}  // namespace selfalign
