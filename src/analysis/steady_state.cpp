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
  // Exact maps also give the local slope λ = dP/dv of the period they simulate (the saltation
  // product of its arcs, PeriodMap::saltation_monodromy), so every step is a Newton step on
  // the affine piece the iterate lies on; other maps measure λ by secants.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Period {
    double v, g, displacement, lambda;
    MotionCensus census;
  };
  auto evaluate = [&](double v) {
    Period p{v, 0.0, 0.0, kNaN, {}};
    ObjectState end;
    if (map.has_arcs()) {
      SaltationProduct product(map.law());
      end = map(0, v, &product, &p.census);
      p.lambda = product.finish_periodic()(1, 1);
    } else {
      end = map(0, v, nullptr, &p.census);
    }
    p.g = end.xd - v;
    p.displacement = end.x;
    return p;
  };

  // The fixed point v* of P is the root of g(v) = P(v) - v. P is nondecreasing (a scalar
  // velocity: responses from two starts merge in a stick but never cross) with slope λ < 1
  // (friction dissipates a velocity difference), so g is decreasing and a pair of iterates
  // with g > 0 (below v*) and g < 0 (above v*) brackets v*: the bracket's width bounds the
  // error of any point in it. P is piecewise affine for the paper's profiles (constant after a
  // stick, slope λ2 = c4 in slip-slip, eq. 32) and piecewise smooth in general, with kinks
  // where the event sequence changes (F05: a fixed point 8e-10 Δt from the case-3/4 kink).
  //
  // Steps: plain iterates from rest first (they reach a stick-determined fixed point exactly),
  // then Newton steps v - g / (λ - 1) on the local slope (exact maps) or secant steps; where
  // the local slope is near 1 (λ > 0.999: a piece far from v*, typically after a first Newton
  // step from rest overshot) and a bracket is known, false position across it; a step that
  // leaves the bracket, or one that fails to halve the residual twice, is replaced by
  // bisection. Once the local estimate |g| / (1 - λ) is within half the tolerance, the next
  // point is the mirror image across the estimated v*: where the estimate holds, g changes
  // sign there and the bracket, of width twice the estimate, certifies it; where a kink lies
  // between, the search goes on from the mirror point. Stops when
  //   * g = 0 in floating point (a stick-determined fixed point: error the map's rounding), or
  //   * the bracket is narrower than the tolerance, or than the map's rounding amplified by
  //     1 / (1 - λ) (kFloor roundings): no evaluation resolves the sign closer than that.
  // The reported error is the bracket's width, never less than the rounding floor: a bound,
  // not an estimate from a slope that may have been taken across a kink.
  // The steady x'_0s cannot exceed the velocity the table can impart in a period,
  // V = max|y''| Δt + Δt (friction included); steps beyond 2V are replaced by plain iterates.
  constexpr double kSlopeResolution = 1e3;  // residual differences below this many roundings
                                            // give no secant slope
  constexpr double kStallFactor = 0.5;      // a Newton/secant step on an affine map gains more
  constexpr int kStallsToBisect = 2;
  constexpr double kFloor = 2;              // roundings of g: closer to v*, g's sign is noise
  constexpr double kProbeStep = 1e-6;       // relative: far above rounding, below |v|'s scale
  require_moderate("initial_velocity", o.initial_velocity);
  const double V = (profile.peak_acceleration() + 1) * P;
  auto scale = [&](double v) { return 1 + std::min(std::abs(v), V); };
  auto rounding = [&](double v) {
    return std::numeric_limits<double>::epsilon() * (std::abs(v) + V);
  };
  const bool hinted = std::isfinite(o.initial_slope) && o.initial_slope < 0;
  double secant_slope = hinted ? o.initial_slope : kNaN;  // g' from iterates (or the hint)
  // g' = λ - 1 at an iterate: its own λ (exact maps), else the last secant slope.
  auto slope_at = [&](const Period& p) {
    return std::isfinite(p.lambda) ? p.lambda - 1 : secant_slope;
  };
  // 1 - λ from the slope of g (taken as at most 1; 1 where unknown), and the rounding floor
  // of v*: kFloor roundings of g over it.
  auto contraction = [&](const Period& p) {
    const double s = slope_at(p);
    return std::isfinite(s) && s < 0 ? std::min(-s, 1.0) : 1.0;
  };
  auto floor_at = [&](const Period& p) { return kFloor * rounding(p.v) / contraction(p); };


  double below = 0, above = 0;  // bracket: g(below) > 0 > g(above)
  double g_below = 0, g_above = 0;
  bool have_below = false, have_above = false;
  auto note_side = [&](const Period& p) {
    if (p.g > 0 && (!have_below || p.v > below)) below = p.v, g_below = p.g, have_below = true;
    if (p.g < 0 && (!have_above || p.v < above)) above = p.v, g_above = p.g, have_above = true;
  };
  auto bracketed = [&] { return have_below && have_above && below < above; };

  Period best = evaluate(o.initial_velocity);
  r.periods = 1;
  note_side(best);
  Period last = best;  // the latest iterate
  // At the rounding floor a Newton iterate on the map's own slope needs no certificate: no
  // evaluation could resolve g's sign closer to v* (a secant slope may come from across a kink,
  // so other maps always bracket).
  auto at_floor = [&](const Period& p) {
    return p.g == 0 || (std::isfinite(p.lambda) && std::abs(p.g) <= kFloor * rounding(p.v));
  };
  bool done = at_floor(best), probed = false;
  int stalls = 0;  // consecutive Newton/secant steps that failed to halve the residual
  while (!done && r.periods < o.max_periods) {
    const double v = last.v, g = last.g;
    const double s = slope_at(last);
    // The next point: Newton/secant where a slope is known and clearly contracting (not in
    // the first plain iterates from rest, which find stick-determined fixed points exactly),
    // else a plain iterate.
    double next = v + g;
    bool step = false, certify = false;
    const bool may_step = r.periods >= 3 || hinted || std::isfinite(last.lambda);
    if (may_step && std::isfinite(s) && s < -1e-3 && std::abs(v - g / s) <= 2 * V) {
      const double estimate = std::abs(g / s);
      // Certify: mirror across the estimated v*, at least the rounding floor away.
      certify = estimate <= 0.5 * tol * scale(v);
      next = v + std::copysign(certify ? std::max(2 * estimate, floor_at(last)) : estimate, g);
      step = !certify;
    } else if (bracketed() && std::isfinite(s) && s >= -1e-3) {
      // The slope here says nothing of v* (λ ≈ 1 on a piece far from it, e.g. a first Newton
      // step from rest that overshot): false position across the bracket instead of a plain
      // iterate, which would crawl at the rate 1 - λ.
      next = below + g_below * (above - below) / (g_below - g_above);
      step = true;
    } else if (!std::isfinite(s) && !probed && r.periods >= 3 && g != 0) {
      // Residuals too close to each other to give a slope (a start near the fixed point, a
      // map with λ near 1): one probe a resolvable distance towards v* measures it.
      next = v + std::copysign(kProbeStep * scale(v), g);
      probed = true;
    }
    if (bracketed() && (stalls >= kStallsToBisect || !(next > below && next < above))) {
      next = 0.5 * (below + above);
      step = certify = false;
      stalls = 0;
    }
    Period current = evaluate(next);
    ++r.periods;
    note_side(current);
    if (std::abs(current.g - g) > kSlopeResolution * (rounding(next) + rounding(v)))
      secant_slope = (current.g - g) / (next - v);
    if (step) stalls = std::abs(current.g) <= kStallFactor * std::abs(g) ? 0 : stalls + 1;
    if (std::abs(current.g) <= std::abs(best.g)) best = current;
    last = std::move(current);
    done = at_floor(best) ||
           (bracketed() && above - below <= std::max(tol * scale(best.v), floor_at(best)));
  }
  // |v - v*|: at the floor the residual (at least one rounding) over the local contraction,
  // else the bracket's width (never below the rounding over the contraction).
  const double residual_error =
      std::max(std::abs(best.g), rounding(best.v)) / contraction(best);
  r.x_dot_0s_error = !done           ? kInf
                     : at_floor(best) ? residual_error
                                      : std::max(above - below, rounding(best.v) / contraction(best));
  r.slope = slope_at(best);
  done = done && std::abs(best.v) <= 2 * V;
  r.converged = done;
  if (!done) best = last;  // not converged: the last iterate (fields hold it)
  r.x_dot_0s = best.v;
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
