#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

namespace {

// The fixed quantities of one request (finite jerk), names as in docs/jerk-limited-three-phase.md.
struct Setup {
  double dt, dy, a, b, j;
  double s;       // 1/a + 1/b
  double ra, rb;  // ramp durations a/j, b/j
  double m;       // max(a, b)
};

Setup make_setup(double dt, double dy, double a, double b, double j) {
  return {dt, dy, a, b, j, 1.0 / a + 1.0 / b, a / j, b / j, std::max(a, b)};
}

// Ψ_c(v0), eq. (J6): the area of y' > 0 on the branch of the plateau c beyond the first hold.
// Written with the ramp duration r = c/j so that c^3/j^2 = c r^2 cannot overflow early.
double psi(double v0, double c, double r) {
  const double w = v0 / c;  // v0/c, v0^2/j = c w r: no product of two large factors
  if (v0 <= 0.5 * c * r) return (2.0 / 3.0) * v0 * std::sqrt(2.0 * w * r);  // on the ramp
  return 0.5 * v0 * w + 0.5 * v0 * r - c * r * r / 24.0;                    // on the plateau
}

// Stroke of the profile with velocity swing D, eqs. (J3)-(J6). Strictly increasing in D on
// [D_min, D_max] (eq. J12).
double stroke_at(const Setup& k, double D) {
  const double L = D / k.a + D / k.b + (k.ra + k.rb);
  const double T1 = k.dt - L;
  const double v0 = D * (L / (2.0 * k.dt));
  return v0 * T1 + psi(v0, k.a, k.ra) + psi(v0, k.b, k.rb);
}

double d_min(const Setup& k) { return k.m * (k.m / k.j); }             // eq. (J2)
double d_max(const Setup& k) { return (k.dt - (k.ra + k.rb)) / k.s; }  // eq. (J3)
// What the ramps cost in stroke, S_max(∞) - S_max(j) = (a + b)^3/(24 j^2), eq. (J13).
double ramp_stroke_loss(const Setup& k) {
  const double c0 = k.ra + k.rb;
  return (k.a + k.b) * c0 * c0 / 24.0;
}

// Smallest feasible jerk, eq. (J16), for valid inputs with Δy <= Δt^2/(8s) (G <= 1/2).
double min_feasible_jerk(double dt, double dy, double a, double b) {
  const double s = 1.0 / a + 1.0 / b;
  const double gap = dt * dt / (8.0 * s) - dy;  // S_max(∞) - Δy
  if (!(gap > 0)) return kInf;                  // jumps only (or rounding at G = 1/2)
  const double m = std::max(a, b), n = std::min(a, b);
  const double jp = (m / dt) * (2.0 + m / n) + n / dt;  // eq. (J14): (s m^2 + a + b)/Δt
  if (!std::isfinite(jp)) return kInf;
  const double j_stroke = (a + b) * std::sqrt((a + b) / (24.0 * gap));  // S_max(j) = Δy
  // S_min(j_p) = S_max(j_p): above it the stroke bound decides, below it S_min does.
  const double loss_p = ramp_stroke_loss(make_setup(dt, dy, a, b, jp));
  if (std::isfinite(loss_p) && loss_p >= gap) return std::max(jp, j_stroke);
  // S_min(j) = stroke_at(D_min(j)) decreases strictly from S_max(j_p) > Δy to 0 (eq. J15):
  // bracket [lo, hi] with S_min(lo) > Δy >= S_min(hi), then bisect. The test is written as
  // the solver's (!(S_min <= Δy): case 0), so that a stroke that overflows counts as too large
  // and min_jerk agrees with solve_jerk_limited_three_phase even at absurd scales.
  auto feasible = [&](double j) {
    const Setup k = make_setup(dt, dy, a, b, j);
    return stroke_at(k, d_min(k)) <= dy;
  };
  double lo = jp, hi = 2.0 * jp;
  while (!feasible(hi)) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) return kInf;
  }
  for (int it = 0; it < 4000; ++it) {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) break;
    (feasible(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

const char* to_string(JerkLimitedCase0 reason) noexcept {
  switch (reason) {
    case JerkLimitedCase0::none:
      return "none";
    case JerkLimitedCase0::accelerations_too_low:
      return "accelerations_too_low";
    case JerkLimitedCase0::ramps_exceed_period:
      return "ramps_exceed_period";
    case JerkLimitedCase0::stroke_too_large:
      return "stroke_too_large";
    case JerkLimitedCase0::stroke_too_small:
      return "stroke_too_small";
  }
  return "?";
}

void validate(const JerkLimitedThreePhaseParameters& p) {
  validate(ThreePhaseParameters{p.period, p.stroke, p.a2, p.a3});
  if (!(p.jerk > 0))
    throw InvalidParameter("jerk", p.jerk, "must be > 0 (+inf: jump accelerations)");
}

JerkLimitedThreePhaseSolution solve_jerk_limited_three_phase(
    const JerkLimitedThreePhaseParameters& p) {
  validate(p);
  JerkLimitedThreePhaseSolution r;
  const double dt = p.period, dy = p.stroke, a = p.a2, b = p.a3, j = p.jerk;
  // G <= 1/2 exactly as solve_three_phase decides it, so that jerk = +inf agrees bit for bit.
  const double s = 1.0 / a + 1.0 / b;
  const double G = std::sqrt(2.0 * s * dy) / dt;
  if (!(G <= 0.5)) {
    r.reason = JerkLimitedCase0::accelerations_too_low;
    r.min_jerk = kInf;
    return r;
  }
  r.min_jerk = min_feasible_jerk(dt, dy, a, b);

  if (std::isinf(j)) {  // jump accelerations: the three-phase closed form, ramps of length 0
    const ThreePhaseSolution t = solve_three_phase({dt, dy, a, b});
    if (!t.physical) {  // unreachable: the same test G <= 1/2 as above
      r.reason = JerkLimitedCase0::accelerations_too_low;
      return r;
    }
    r.physical = true;
    r.closed_form = true;
    r.hold0 = t.t1;
    r.hold2 = t.velocity_swing / a;
    r.hold3 = t.velocity_swing / b;
    r.velocity_swing = t.velocity_swing;
    r.yd_ini = t.yd_ini;
    return r;
  }

  const Setup k = make_setup(dt, dy, a, b, j);
  const double c0 = k.ra + k.rb;  // (a + b)/j, all ramps together
  const double D_lo = d_min(k), D_hi = d_max(k);
  if (!(D_lo <= D_hi)) {
    r.reason = JerkLimitedCase0::ramps_exceed_period;
    return r;
  }
  // Δy <= S_max(j), compared as loss <= gap: at G = 1/2 (gap 0) a finite jerk never passes.
  const double gap = dt * dt / (8.0 * s) - dy;
  if (!(ramp_stroke_loss(k) <= gap)) {
    r.reason = JerkLimitedCase0::stroke_too_large;
    return r;
  }
  if (!(stroke_at(k, D_lo) <= dy)) {
    r.reason = JerkLimitedCase0::stroke_too_small;
    return r;
  }

  // Regime P (both zero crossings of y' on the plateaus): eqs. (J9), (J10).
  const double eps = c0 / dt;
  const double kappa = 2.0 * s * (a * k.ra * k.ra + b * k.rb * k.rb) / (24.0 * dt * dt);
  const double g2k = 2.0 * s * dy / (dt * dt) + kappa;  // G^2 + κ
  const double eta = 2.0 * g2k / (eps + std::sqrt(eps * eps + 4.0 * g2k));
  const double pp = 1.0 - 0.5 * eps;
  const double u = 2.0 * eta / (pp + std::sqrt(std::max(0.0, pp * pp - 2.0 * eta)));
  double D = u * dt / s;
  const double v0_closed = 0.5 * D * (u + eps);
  r.closed_form = v0_closed >= 0.5 * k.m * (k.m / j) && D >= D_lo && D <= D_hi;  // eq. (J11)
  if (!r.closed_form) {
    // Regime R: bisection on the strictly increasing stroke (eq. J12), bracket certified above:
    // stroke_at(D_lo) <= Δy <= stroke_at(D_hi) = S_max(j).
    double lo = D_lo, hi = D_hi;
    for (int it = 0; it < 4000; ++it) {
      const double mid = lo + 0.5 * (hi - lo);
      if (!(mid > lo && mid < hi)) break;
      (stroke_at(k, mid) <= dy ? lo : hi) = mid;
    }
    D = std::abs(stroke_at(k, hi) - dy) < std::abs(stroke_at(k, lo) - dy) ? hi : lo;
  }
  const double L = D / a + D / b + c0;  // eq. (J3)
  r.physical = true;
  r.velocity_swing = D;
  r.hold0 = std::max(0.0, dt - L);
  r.ramp_down = k.ra;
  r.hold2 = std::max(0.0, D / a - k.ra);  // eq. (J2); >= 0 up to rounding at D = D_min
  r.ramp_up = c0;
  r.hold3 = std::max(0.0, D / b - k.rb);
  r.ramp_end = k.rb;
  r.yd_ini = D * L / (2.0 * dt);  // eq. (J4)
  return r;
}

namespace {
PiecewisePolynomialProfile jerk_limited_shape(const JerkLimitedThreePhaseParameters& p,
                                              const JerkLimitedThreePhaseSolution& r) {
  if (!r.physical) {
    if (r.reason == JerkLimitedCase0::accelerations_too_low) {
      const double s = 1.0 / p.a2 + 1.0 / p.a3;
      throw InvalidParameter(
          "a2, a3", format_number(p.a2) + ", " + format_number(p.a3),
          "non-physical profile (case 0) for any jerk: need 1/a2 + 1/a3 <= period^2/(8 stroke) = " +
              format_number(p.period * p.period / (8.0 * p.stroke)) + ", got " + format_number(s));
    }
    const char* why = r.reason == JerkLimitedCase0::ramps_exceed_period
                          ? "the ramps outlast the period"
                      : r.reason == JerkLimitedCase0::stroke_too_large
                          ? "the ramps leave too little stroke"
                          : "reaching both plateaus overshoots the stroke";
    throw InvalidParameter("jerk", p.jerk,
                           std::string("too low for period, stroke, a2, a3 (case 0: ") + why +
                               "): need jerk >= " + format_number(r.min_jerk) +
                               (std::isinf(r.min_jerk) ? " (jump accelerations only)" : ""));
  }
  const double a = p.a2, b = p.a3;
  const auto d = r.durations();
  const double begin[6] = {0.0, 0.0, -a, -a, b, b};
  const double end[6] = {0.0, -a, -a, b, b, 0.0};
  return PiecewisePolynomialProfile::from_linear_accelerations(d, begin, end,
                                                               "jerk-limited-three-phase");
}
}  // namespace

JerkLimitedThreePhaseProfile::JerkLimitedThreePhaseProfile(const JerkLimitedThreePhaseParameters& p)
    : params_(p),
      solution_(solve_jerk_limited_three_phase(p)),
      shape_(jerk_limited_shape(p, solution_)) {}

}  // namespace selfalign
