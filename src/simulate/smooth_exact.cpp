#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/stick_slip_decision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_events.hpp"
#include "safe_step.hpp"
#include "smooth_stick.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/fourier.hpp"

namespace selfalign {

namespace {

using detail::kInf;

using detail::safe_step;
using detail::safe_step_local;

using detail::time_resolution;

// The work budget of one arc or stick: safe steps (each a few derivative evaluations). Never
// reached by resolvable motions; a motion whose derivative bounds make every safe step tiny
// (thousands of harmonics with huge coefficients) ends in an error, not in a wrong arc
// (issue 20, D26: the loops used to fall through as if the horizon had been reached).
constexpr long long kMaxSteps = 100'000'000;

namespace {
[[noreturn]] void exceed_step_budget(double t) {
  throw InvalidParameter("profile", "smooth motion",
                         "the exact smooth solver needs more than 1e8 safe steps for one arc at t = " +
                             format_number(t) +
                             " (derivative bounds too large for the time scale: lower the order "
                             "or the coefficients, or use time-stepping)");
}
}  // namespace

// The friction piece a slip in direction sigma from x runs on (moving left from a boundary:
// the piece below it).
std::size_t slip_piece_index(const PiecewiseAffineFriction& f, double x, int sigma) {
  std::size_t pi = f.piece_index(x);
  if (sigma < 0 && pi > 0 && x == f.pieces()[pi].begin) --pi;
  return pi;
}

struct AffineSlip {
  double t1, x1, v1;
  ArcEnd end;
  DrivenAffineArc arc;
};

// One slip on an affine piece m = m0 + b (x - x0) under a Fourier motion: the closed form of
// DrivenAffineArc, x'' = -kappa (x - center) - y'', its events isolated by safe steps as on a
// constant level. While slipping g = sigma x' > 0 and g'' = sigma x^(3) = -kappa g - sigma
// y^(3), so |g''| <= K |x'| + Y3 (K = |kappa|); over a step of length d, Taylor's bound on |x'|
// with that remainder gives sup|x'| <= (|g| + |g1| d + Y3 d^2/2) / (1 - K d^2/2) =: G(d), so
// B(d) = K G(d) + Y3 bounds |g''| there (docs/fourier-transition-region.md, eq. F9). The rising
// bound likewise: |g^(3)| <= K (|g1| + d B(d)) + Y4.
AffineSlip slip_on_affine_piece(const FourierProfile& series, const AffinePiece& pc,
                                const FrictionLaw& law, int sigma, bool from_break,
                                const ObjectState& s0, const std::array<double, 4>& d0,
                                double t_end) {
  const double kappa = sigma * law.kinetic(sigma) * pc.slope;
  const double center = pc.begin - pc.bound_at_begin / pc.slope;  // m(center) = 0
  const DrivenAffineArc arc{&series, s0.t, kappa, center};
  const double K = std::abs(kappa), Y3 = series.jerk_bound(), Y4 = series.snap_bound();
  const double d_max = 1 / std::sqrt(K);  // keeps 1 - K d^2/2 >= 1/2
  const double X = sigma > 0 ? pc.end : pc.begin;
  const double T = t_end - s0.t;
  double tau = 0, g = sigma * s0.xd + 0.0;
  double g1 = sigma * (-kappa * (s0.x - center) - d0[2]), g2 = sigma * (-kappa * s0.xd - d0[3]);
  if (from_break) g1 = std::max(g1, 0.0);
  auto bound = [&](double d) {  // B(d) of the comment
    const double G = (std::abs(g) + std::abs(g1) * d + 0.5 * Y3 * d * d) / (1 - 0.5 * K * d * d);
    return K * G + Y3;
  };
  AffineSlip r{t_end, s0.x, s0.xd, ArcEnd::horizon, arc};
  for (long long i = 0;; ++i) {
    if (i == kMaxSteps) exceed_step_budget(s0.t + tau);
    double d = std::min(safe_step(g, g1, K * std::abs(g) + Y3), d_max);
    d = std::min(d, safe_step(g, g1, bound(d)));  // valid on [0, d]: B(d) covers it
    double rise = 0;
    if (g1 >= 0) {
      rise = std::min(safe_step(g1, g2, K * std::abs(g1) + Y4), d_max);
      rise = std::min(rise, safe_step(g1, g2, K * (std::abs(g1) + rise * bound(rise)) + Y4));
    }
    const double step = std::max(d, rise);
    const double tn = std::min(tau + step, T);
    const PosVel p = arc.state(s0.x, s0.xd, tn);
    if (std::isfinite(X) && sigma * (p.x - X) >= 0) {  // the boundary: one crossing
      auto position = [&](double q) {
        const PosVel z = arc.state(s0.x, s0.xd, q);
        return std::pair{sigma * (z.x - X), sigma * z.xd};
      };
      tau = detail::bracketed_root(position, tau, tn, 0.5 * (tau + tn), std::abs(s0.t) + tn);
      const PosVel z = arc.state(s0.x, s0.xd, tau);
      r = {s0.t + tau, X, sigma * z.xd > 0 ? z.xd : 0.0, ArcEnd::friction_boundary, arc};
      return r;
    }
    if (tn >= T) return {t_end, p.x, sigma * p.xd > 0 ? p.xd : 0.0, ArcEnd::horizon, arc};
    tau = tn;
    g = sigma * p.xd;
    if (!(g > 0) || step <= time_resolution(s0.t + tau))
      return {s0.t + tau, p.x, 0.0, ArcEnd::velocity_zero, arc};
    const std::array<double, 4> dn = series.derivatives(s0.t + tau);
    g1 = sigma * (-kappa * (p.x - center) - dn[2]);
    g2 = sigma * (-kappa * p.xd - dn[3]);
  }
  return r;
}

// Minimum over [0, L] of the cubic Hermite interpolant of g from g(0) = g0, g'(0) = d0,
// g(L) = g1, g'(L) = d1 (in u = s/L: a u^3 + b u^2 + c u + e, stationary points from its
// derivative's quadratic).
double hermite_minimum(double g0, double d0, double g1, double d1, double L) {
  const double e = g0, c = L * d0, b = -3 * g0 - 2 * L * d0 + 3 * g1 - L * d1,
               a = 2 * g0 + L * d0 - 2 * g1 + L * d1;
  double lowest = std::min(g0, g1);
  auto at = [&](double u) { return ((a * u + b) * u + c) * u + e; };
  const double qa = 3 * a, qb = 2 * b, qc = c;
  if (qa == 0) {
    if (qb != 0 && -qc / qb > 0 && -qc / qb < 1) lowest = std::min(lowest, at(-qc / qb));
    return lowest;
  }
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return lowest;
  const double r = std::sqrt(disc);
  for (const double u : {(-qb - r) / (2 * qa), (-qb + r) / (2 * qa)})
    if (u > 0 && u < 1) lowest = std::min(lowest, at(u));
  return lowest;
}

}  // namespace

namespace detail {

StickEnd smooth_stick_end(const SmoothMotion& M, double ms, double t, double t_end) {
  const double Y4 = M.snap_bound();
  const std::array<double, 4> d0 = M.derivatives(t);
  double tau = 0, ydd = d0[2], yddd = d0[3];
  for (long long i = 0;; ++i) {
    if (i == kMaxSteps) exceed_step_budget(t + tau);
    const double up = safe_step(ms - ydd, -yddd, Y4), down = safe_step(ms + ydd, yddd, Y4);
    const double step = std::min(up, down);
    if (t + tau + step >= t_end) return {t_end, 0};
    if (step <= time_resolution(t + tau)) {
      const double rate = up <= down ? -yddd : yddd;  // d/dt of the margin that closes
      if (rate >= 0) {  // a touch of the bound, not a crossing: step past it
        tau += 1024 * time_resolution(t + tau);
        const auto d = M.derivatives(t + tau);
        ydd = d[2];
        yddd = d[3];
        continue;
      }
      return {t + tau + step, up <= down ? -1 : 1};  // y'' reached +ms: slip backward
    }
    tau += step;
    const auto d = M.derivatives(t + tau);
    ydd = d[2];
    yddd = d[3];
  }
  return {t_end, 0};
}

}  // namespace detail

bool piecewise_constant_level(const PiecewiseAffineFriction& friction) noexcept {
  for (const AffinePiece& p : friction.pieces())
    if (p.slope != 0) return false;
  return true;
}

bool smooth_solver_applies(const SmoothMotion& motion,
                           const PiecewiseAffineFriction& friction) noexcept {
  return motion.fourier_series() != nullptr || piecewise_constant_level(friction);
}

std::size_t advance_smooth(const SmoothSetup& setup, ObjectState& state, double t_end,
                           MotionObserver* observer) {
  if (!smooth_solver_applies(setup.motion, setup.friction))
    throw InvalidParameter("friction", "sloped pieces",
                           "the smooth-profile solver takes sloped friction pieces under a Fourier "
                           "motion only (use the slip integrator or time-stepping)");
  validate(state);
  if (!std::isfinite(t_end)) throw InvalidParameter("t_end", t_end, "must be finite");
  const SmoothMotion& M = setup.motion;
  const auto pieces = setup.friction.pieces();
  const FrictionLaw& law = setup.law;
  const double Y3 = M.jerk_bound(), Y4 = M.snap_bound(), Y5 = M.fifth_derivative_bound();
  double t = state.t, x = state.x, v = state.xd;
  std::size_t count = 0;
  int breaking = 0;  // after a stick break: the direction the slip takes
  bool from_break = false;
  while (t < t_end) {
    const std::array<double, 4> d0 = M.derivatives(t);
    int sigma = 0;
    std::size_t pi = 0;
    double m = 0, t1 = t_end, x1 = x, v1 = 0;
    ArcEnd end = ArcEnd::horizon;
    ArcShape shape;
    from_break = false;
    if (v == 0) {
      pi = setup.friction.piece_index(x);
      m = pieces[pi].bound(x);
      const double ms = law.static_coefficient() * m;
      sigma = decide_at_rest(d0[2], ms, breaking);
      from_break = breaking != 0;
      breaking = 0;
      if (sigma == 0) {  // stuck until y'' reaches +ms or -ms
        const detail::StickEnd e = detail::smooth_stick_end(M, ms, t, t_end);
        t1 = e.t;
        if (e.direction != 0) {
          end = ArcEnd::stick_break;
          breaking = e.direction;
        }
        shape = StickArc{};
      }
    } else {
      sigma = v > 0 ? 1 : -1;
    }

    if (sigma != 0 &&
        pieces[slip_piece_index(setup.friction, x, sigma)].slope != 0) {  // transition region
      pi = slip_piece_index(setup.friction, x, sigma);
      const AffinePiece& pc = pieces[pi];
      m = pc.bound(x);
      const AffineSlip r = slip_on_affine_piece(*M.fourier_series(), pc, law, sigma, from_break,
                                                {t, x, v}, d0, t_end);
      if (observer) {
        Arc a{{t, r.t1, x, v, r.x1, r.v1}, d0[2], d0[3], m, pc.slope, r.arc};
        a.direction = static_cast<std::int8_t>(sigma);
        a.end = r.end;
        a.piece = pi;
        observer->on_motion(a, &a);
      }
      ++count;
      t = r.t1;
      x = r.x1;
      v = r.v1;
      continue;
    }
    if (sigma != 0) {  // slip: g = sigma x' >= 0, |g''| <= Y3
      pi = setup.friction.piece_index(x);
      if (sigma < 0 && pi > 0 && x == pieces[pi].begin) --pi;  // moving left from a boundary
      const AffinePiece& pc = pieces[pi];
      m = pc.bound_at_begin;
      const double X = sigma > 0 ? pc.end : pc.begin;
      const DrivenArc arc{&M, t, d0[0], d0[1], -sigma * law.kinetic(sigma) * m};
      const double T = t_end - t;
      // At each step point: g = sigma x' >= 0, g1 = sigma x'', g2 = sigma x^(3) = -sigma y^(3).
      // Two lower bounds keep g >= 0 over the next step: g + g1 d - Y3 d^2/2 >= 0, and, while
      // g1 >= 0, g1 + g2 d - Y4 d^2/2 >= 0 (g still rising: this one carries a slip that
      // starts with x'' = 0, static = kinetic at a break). The longer of the two is safe.
      double tau = 0, g = sigma * v + 0.0, g1 = sigma * (arc.accel - d0[2]), g2 = -sigma * d0[3];
      if (from_break) g1 = std::max(g1, 0.0);  // |y''| = s m at a break: x'' >= 0 but rounding
      double long_step = 0;  // the a posteriori step below (0: none tried yet)
      for (long long i = 0;; ++i) {
        if (i == kMaxSteps) exceed_step_budget(t + tau);
        const double quadratic = safe_step(g, g1, Y3);
        // |g''| <= |y^(3)(t)| + Y4 d: a tighter, local cubic bound, tried from twice the
        // quadratic step (Newton comes down onto its root from above).
        const double local = safe_step_local(g, g1, 0.5 * std::abs(g2), Y4 / 6,
                                             std::max(2 * quadratic, 1e-300));
        const double step = std::max({quadratic, local, g1 >= 0 ? safe_step(g1, g2, Y4) : 0.0});
        // A longer step checked a posteriori: on a constant level g'''' = -sigma y^(5), so the
        // cubic Hermite interpolant of g from both ends of [0, L] is within Y5 L^4/384 of g
        // (the interpolation error bound); where its minimum clears that, g > 0 on all of it.
        // Grown by 1.5 after a success, halved after a failure, and kept short enough that the
        // error bound stays below g/4 (near a zero the safe steps above converge instead).
        std::array<double, 4> d{};
        double tn = 0;
        bool long_taken = false;
        // L keeps the interpolation error below g/4: (96 g / Y5)^(1/4).
        const double L = std::min({long_step, T - tau, std::sqrt(std::sqrt(96 * g / Y5))});
        const double hermite_error = Y5 * L * L * L * L / 384;
        if (L > 1.25 * step) {
          d = M.derivatives(t + tau + L);
          const double gl = sigma * (v - (d[1] - arc.yd0) + arc.accel * (tau + L));
          const double g1l = sigma * (arc.accel - d[2]);
          long_taken = hermite_minimum(g, g1, gl, g1l, L) > hermite_error;
          long_step = long_taken ? 1.5 * long_step : std::max(step, 0.5 * long_step);
          if (long_taken) tn = tau + L;
        }
        if (!long_taken) {
          tn = std::min(tau + step, T);
          d = M.derivatives(t + tn);
          long_step = std::max(long_step, 2 * step);
        }
        const double xn = x + v * tn - (d[0] - arc.y0 - arc.yd0 * tn) + 0.5 * arc.accel * tn * tn;
        const double vn = v - (d[1] - arc.yd0) + arc.accel * tn;
        if (std::isfinite(X) && sigma * (xn - X) >= 0) {  // the boundary: one crossing
          auto position = [&](double s) {
            const PosVel q = arc.state(x, v, s);
            return std::pair{sigma * (q.x - X), sigma * q.xd};
          };
          tau = detail::bracketed_root(position, tau, tn, 0.5 * (tau + tn), std::abs(t) + tn);
          end = ArcEnd::friction_boundary;
          break;
        }
        if (tn >= T) {
          tau = T;
          break;
        }
        const double taken = tn - tau;
        tau = tn;
        g = sigma * vn;
        if (!(g > 0) || taken <= time_resolution(t + tau)) {
          end = ArcEnd::velocity_zero;
          break;
        }
        g1 = sigma * (arc.accel - d[2]);
        g2 = -sigma * d[3];
      }
      const PosVel p = arc.state(x, v, tau);
      x1 = end == ArcEnd::friction_boundary ? X : p.x;
      v1 = end == ArcEnd::velocity_zero ? 0.0 : p.xd;
      if ((v1 > 0 && sigma < 0) || (v1 < 0 && sigma > 0)) v1 = 0;
      t1 = end == ArcEnd::horizon ? t_end : t + tau;
      shape = arc;
    }

    if (observer) {
      Arc a{{t, t1, x, v, x1, v1}, d0[2], d0[3], m, 0.0, shape};
      a.direction = static_cast<std::int8_t>(sigma);
      a.end = end;
      a.piece = pi;
      observer->on_motion(a, &a);
    }
    ++count;
    t = t1;
    x = x1;
    v = v1;
  }
  state = {t, x, v};
  return count;
}

}  // namespace selfalign
