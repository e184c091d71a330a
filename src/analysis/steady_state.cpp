#include "selfalign/analysis/steady_state.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include "selfalign/error.hpp"
#include "selfalign/analysis/period_map.hpp"

namespace selfalign {

double objective_f(double v_bar, double c) {
  return v_bar == 0 ? std::numeric_limits<double>::infinity() : 1.0 / (c * v_bar * v_bar);
}

SteadyState steady_state(const TableProfile& profile, const SteadyStateOptions& o) {
  return steady_state(profile, FrictionLaw{}, o);
}

SteadyState steady_state(const TableProfile& profile, const FrictionLaw& law,
                         const SteadyStateOptions& o) {
  if (o.steps_per_period < 1)
    throw InvalidParameter("steps_per_period", o.steps_per_period, "must be >= 1");
  const PeriodMap map(profile, law, {o.steps_per_period, o.theta, o.integrator});
  return steady_state(map, o);
}

SteadyState steady_state(const PeriodMap& map, const SteadyStateOptions& o) {
  if (o.max_periods < 2) throw InvalidParameter("max_periods", o.max_periods, "must be >= 2");
  require_positive("velocity_tol", o.velocity_tol);
  const TableProfile& profile = map.profile();
  const double P = profile.period();
  SteadyState r;
  r.method = map.method();
  double tol = o.velocity_tol;
  if (r.method == Method::time_stepping)
    tol = o.stepping_tol > 0 ? o.stepping_tol : 10 * map.step();
  if (r.method == Method::integrator)
    tol = std::max(tol, 10 * map.integrator_options().relative_tolerance);
  const IntegratorStatistics work_before = map.integrator_statistics();
  // One period of the search: the state at t0 + Δt from x = 0, x' = v at t0. Every period
  // keeps its census and displacement: the best iterate's are the result's (no extra period).
  struct Period {
    double v, g, displacement;
    MotionCensus census;
  };
  auto evaluate = [&](double v) {
    Period p{v, 0.0, 0.0, {}};
    const ObjectState end = map(0, v, nullptr, &p.census);
    p.g = end.xd - v;
    p.displacement = end.x;
    return p;
  };

  // Secant iteration on g(v) = P(v) - v, started from rest: plain iterates first (they reach
  // the stick-determined fixed point exactly), then secant steps (affine slip-slip maps).
  // Safeguards: the steady x'_0s cannot exceed the velocity the table can impart in a period,
  // V = max|y''| Δt + Δt (friction included), so a secant step is taken only on a clearly
  // contracting slope and only if it lands within 2V; tolerances are relative to at most V.
  //
  // Stopping rule: on the estimated error of v, not on the residual. Near the fixed point v*
  // P is affine with slope λ in [0, 1) (constant after a stick, λ2 = c4 in slip-slip), so
  // |v - v*| = |g(v)| / (1 - λ), with g' = λ - 1 the secant slope of g. With λ2 near 1 the
  // residual understates the error by 1/(1 - λ2) (issue 9: λ2 = 0.9965, residual 4e-12, error
  // 1.15e-9). g itself carries the period map's rounding, about eps (|v| + V), so
  //   * the slope is taken only from iterates whose residuals differ by far more than that
  //     (kSlopeResolution roundings): slopes of nearby iterates are rounding noise;
  //   * the error estimate is max(|g|, rounding) / (1 - λ), and where that floor exceeds the
  //     tolerance the search stops once secant steps no longer halve the residual (twice in a
  //     row, with the residual already at rounding level: kRoundingLevel), returning the best
  //     iterate with its estimate.
  constexpr double kSlopeResolution = 1e3;
  constexpr double kStallFactor = 0.5;  // a secant step on an affine map gains far more
  constexpr int kStallsToStop = 2;
  constexpr double kRoundingLevel = 1e-9;  // |g| / (1 + |v|): far above rounding, far below
                                           // any residual a secant step leaves off the floor
  constexpr double kInf = std::numeric_limits<double>::infinity();
  require_moderate("initial_velocity", o.initial_velocity);
  const double V = (profile.peak_acceleration() + 1) * P;
  auto scale = [&](double v) { return 1 + std::min(std::abs(v), V); };
  auto rounding = [&](double v) {
    return std::numeric_limits<double>::epsilon() * (std::abs(v) + V);
  };
  // |v - v*| from the residual and the slope of g (NaN: unknown; then only g = 0, a fixed point
  // in floating point, counts, as a stick-determined one with λ = 0).
  auto error_estimate = [&](double v, double g, double slope) {
    const double r = std::max(std::abs(g), rounding(v));
    if (std::isfinite(slope) && slope < 0) return r / std::min(-slope, 1.0);
    return g == 0 ? r : kInf;
  };
  const double v_start = o.initial_velocity;
  Period best = evaluate(v_start);
  double v_prev = v_start, g_prev = best.g;
  r.periods = 1;
  // A neighbour's slope (with its x'_0s as the start) makes the first step a secant step.
  const bool hinted = std::isfinite(o.initial_slope) && o.initial_slope < 0;
  double slope = hinted ? o.initial_slope : std::numeric_limits<double>::quiet_NaN();
  bool done = g_prev == 0;
  double v = v_prev + g_prev;  // plain iterate
  if (hinted && slope < -1e-3 && std::abs(v_prev - g_prev / slope) <= 2 * V)
    v = v_prev - g_prev / slope;  // secant step on the neighbour's slope
  bool secant_step = false;
  int stalls = 0;
  bool probed = false;
  constexpr double kProbeStep = 1e-6;  // relative: far above rounding, far below |v|'s scale
  // The tightest bracket the iterates give (g decreasing through the fixed point: g > 0 below
  // it, g < 0 above it): secant steps must land inside it, else it is bisected.
  double above = 0, below = 0;
  bool have_above = false, have_below = false;
  auto note_side = [&](double vv, double gg) {
    if (gg > 0 && (!have_below || vv > below)) below = vv, have_below = true;
    if (gg < 0 && (!have_above || vv < above)) above = vv, have_above = true;
  };
  note_side(v_prev, g_prev);
  while (!done && r.periods < o.max_periods) {
    Period current = evaluate(v);
    const double g = current.g;
    ++r.periods;
    note_side(v, g);
    if (std::abs(g - g_prev) > kSlopeResolution * (rounding(v) + rounding(v_prev)))
      slope = (g - g_prev) / (v - v_prev);
    const bool stalled = secant_step && !(std::abs(g) <= kStallFactor * std::abs(best.g));
    stalls = stalled ? stalls + 1 : 0;
    if (std::abs(g) <= std::abs(best.g)) best = std::move(current);
    if (g == 0 || error_estimate(best.v, best.g, slope) <= tol * scale(best.v) ||
        (stalls >= kStallsToStop && std::abs(best.g) <= kRoundingLevel * scale(best.v))) {
      done = true;
      break;
    }
    double next = v + g;  // plain iterate
    secant_step = false;
    // Residuals too close to each other to give a slope (a start near the fixed point, a map
    // with λ near 1): one probe a resolvable distance towards the fixed point measures it, and
    // the secant takes over (plain iterates would crawl at rate λ).
    if (!std::isfinite(slope) && !probed && r.periods >= 3 && g != 0) {
      next = v + std::copysign(kProbeStep * scale(v), g);
      probed = true;
    }
    if ((r.periods > 3 || hinted) && std::isfinite(slope) && slope < -1e-3) {
      const double secant = v - g / slope;
      if (std::abs(secant) <= 2 * V) {
        next = secant;
        secant_step = true;
      }
    }
    // A secant step that leaves the bracket, or one that stalled far above the rounding floor
    // (a kink in g between iterates can trap the secant in a cycle), is replaced by bisection.
    const bool bracketed = have_above && have_below && below < above;
    if (bracketed && std::abs(best.g) > kRoundingLevel * scale(best.v) &&
        (stalls >= 1 || (secant_step && !(next > below && next < above)))) {
      next = 0.5 * (above + below);
      secant_step = false;
    }
    v_prev = v;
    g_prev = g;
    v = next;
  }
  v = done ? best.v : v;
  r.x_dot_0s_error = done ? error_estimate(best.v, best.g, slope) : kInf;
  r.slope = slope;
  done = done && std::abs(v) <= 2 * V;
  r.converged = done;
  r.x_dot_0s = v;
  if (!(v == best.v)) {  // not converged: the last iterate's period, simulated once more
    best = evaluate(v);
    ++r.periods;
  }
  r.displacement = best.displacement;
  r.motion_case = best.census.motion_case();
  r.pattern = best.census.pattern();
  r.v_bar = r.displacement / P;  // eq. (10)
  r.f = objective_f(r.v_bar);    // eq. (11)
  r.integrator = map.integrator_statistics();
  r.integrator -= work_before;
  return r;
}

}  // namespace selfalign
