#pragma once
// Internal: the next event of a slip arc (x' reaching 0, or x reaching a friction boundary X),
// for every ArcShape. Constant table acceleration: the closed forms of eqs. (21), (47) and their
// hyperbolic and boundary counterparts, polished by Newton steps. Finite jerk: a certified scan
// (below). Every time is relative to the arc's start, in the frame where the slip direction
// sigma makes sigma x' > 0 on the open arc.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "selfalign/simulate/arc.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign::detail {

using selfalign::kInf;

// A step shorter than this at time t has converged onto its event (16 roundings of t): the
// stepping solvers' (smooth_exact.cpp, slip_integrator.cpp) test for "no shorter step left".
inline double time_resolution(double t) {
  return 16 * std::numeric_limits<double>::epsilon() * (std::abs(t) + 1e-300);
}

struct SlipEvent {
  double tau = kInf;                   ///< time of the event after the arc's start [-]
  ArcEnd end = ArcEnd::horizon;        ///< velocity_zero, friction_boundary, or horizon: none
};

// ---- Closed forms for constant table acceleration (eqs. 15-21, 42-47) ----------------------

// Parabolic arc xi'' = a in the mirrored frame xi' = sigma x' >= 0.
inline double parabolic_stop(double v, double a) { return a < 0 ? v / -a : kInf; }  // eq. (21)
inline double parabolic_reach(double v, double a, double dist) {
  if (a == 0) return v > 0 ? dist / v : kInf;
  const double disc = v * v + 2 * a * dist;
  if (disc < 0) return kInf;
  const double den = v + std::sqrt(disc);
  return den > 0 ? 2 * dist / den : kInf;  // smallest positive root, without cancellation
}
// Harmonic arc xi = C cos(w tau) + S sin(w tau), S >= 0: xi = R cos(w tau - phi).
inline double harmonic_stop(double C, double S, double w) { return std::atan2(S, C) / w; }
inline double harmonic_reach(double C, double S, double w, double target) {
  const double R = std::hypot(C, S);
  if (target > R) return kInf;
  const double theta = std::atan2(S, C) - std::acos(std::max(-1.0, target / R));
  return std::max(theta, 0.0) / w;
}
// Hyperbolic arc xi = C cosh(w tau) + S sinh(w tau), S >= 0.
inline double hyperbolic_stop(double C, double S, double w) {
  return (C < 0 && S < -C) ? std::atanh(S / -C) / w : kInf;
}
inline double hyperbolic_reach(double C, double S, double w, double target) {
  // With E = exp(w tau): (C + S) E^2 - 2 target E + (C - S) = 0; smallest root with E >= 1.
  const double a = C + S, c = C - S;
  double best = kInf;
  auto consider = [&](double E) {
    if (E >= 1.0 && std::isfinite(E)) best = std::min(best, std::log(E) / w);
  };
  if (a == 0) {
    if (target != 0) consider(c / (2 * target));
  } else {
    const double disc = target * target - a * c;
    if (disc < 0) return kInf;
    const double q = target + std::copysign(std::sqrt(disc), target);
    consider(q / a);
    if (q != 0) consider(c / q);
  }
  return best;
}

// Newton polish of the time at which an arc reaches position X (f = x - X, f' = x').
template <class Shape>
double polish_reach(const Shape& arc, double x0, double v0, double X, double tau,
                    double tau_max) {
  for (int i = 0; i < 2; ++i) {
    const PosVel s = arc.state(x0, v0, tau);
    if (s.xd == 0) break;
    const double next = tau - (s.x - X) / s.xd;
    if (!(next >= 0 && next <= tau_max)) break;
    tau = next;
  }
  return tau;
}

// ---- The certified scan (finite jerk) --------------------------------------------------------
//
// Between consecutive zeros of the acceleration x'' (the "critical times" of x', listed in
// closed form per shape) x' is monotone, so on each such interval
//   * x' has a zero iff sigma x' changes sign between the interval's ends (one zero at most;
//     a double zero sits at an interval end, where it is tested directly: none is missed);
//   * up to the first zero of x', x is monotone, so it meets X at most once.
// The intervals are visited in time order and the first event wins; each root is found in its
// bracket by safeguarded Newton steps (bisection whenever Newton leaves the bracket) to a
// bracket width of kRootTolerance relative to the absolute time, so no root is found twice and
// none is skipped.

inline constexpr double kRootTolerance = 1e-15;  // bracket width / (|t| + tau) at convergence

// Root of an increasing f on [lo, hi] with f(lo) <= 0 <= f(hi); fd(tau) returns {f, f'}.
template <class F>
double bracketed_root(const F& fd, double lo, double hi, double guess, double time_scale) {
  const double tol = kRootTolerance * time_scale;
  double tau = guess > lo && guess < hi ? guess : 0.5 * (lo + hi);
  for (int i = 0; i < 200 && hi - lo > tol; ++i) {
    const auto [f, df] = fd(tau);
    if (f == 0) return tau;
    (f < 0 ? lo : hi) = tau;
    double next = df > 0 ? tau - f / df : 0.5 * (lo + hi);
    // Converged first: a Newton step that lands on the bracket's end has converged, not left
    // the bracket (testing the bracket first bisected ~15 times a root; benchmark, jerk 12).
    if (std::abs(next - tau) <= 0.5 * tol) return std::clamp(next, lo, hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    tau = next;
  }
  return hi;  // the event is on the far side of the bracket: never before the true root
}

// Critical times of x' (zeros of x'') after `after`, per shape.
inline double next_critical(const PolynomialArc& a, double, double, double after) {
  if (a.jerk == 0) return kInf;
  const double tc = -a.accel / a.jerk;
  return tc > after ? tc : kInf;
}
template <class Curved>
double curved_coefficients(const Curved& a, double x0, double v0, double& D, double& E) {
  D = x0 - a.center;
  E = (v0 - a.drift) / a.omega;
  return a.omega;
}
// x'' = -w^2 (D cos + E sin) = -w^2 R cos(w tau - phi): zeros at w tau = phi + pi/2 + n pi.
inline double next_critical(const HarmonicArc& a, double x0, double v0, double after) {
  double D, E;
  const double w = curved_coefficients(a, x0, v0, D, E);
  if (D == 0 && E == 0) return kInf;
  const double phi = std::atan2(E, D) + 0.5 * std::numbers::pi;
  const double n = std::floor((w * after - phi) / std::numbers::pi) + 1;
  double tc = (phi + n * std::numbers::pi) / w;
  if (!(tc > after)) tc = (phi + (n + 1) * std::numbers::pi) / w;
  return tc;
}
// x'' = w^2 (D cosh + E sinh): one zero at most, where tanh(w tau) = -D/E.
inline double next_critical(const HyperbolicArc& a, double x0, double v0, double after) {
  double D, E;
  const double w = curved_coefficients(a, x0, v0, D, E);
  if (E == 0 || std::abs(D) >= std::abs(E)) return kInf;
  const double tc = std::atanh(-D / E) / w;
  return tc > after ? tc : kInf;
}

template <class Shape>
SlipEvent scan_events(const Shape& arc, double x0, double v0, int sigma, double X, double T,
                      double time_scale) {
  const double s = sigma;
  auto velocity = [&](double tau) {  // increasing on an interval where sigma x' falls to 0
    const PosVel p = arc.state(x0, v0, tau);
    return std::pair{-s * p.xd, -s * arc.acceleration(p.x, p.xd, tau)};
  };
  auto position = [&](double tau) {
    const PosVel p = arc.state(x0, v0, tau);
    return std::pair{s * (p.x - X), s * p.xd};
  };
  const bool bounded = std::isfinite(X);
  double lo = 0;
  for (long long guard = 0; guard < 100'000'000; ++guard) {
    const double hi = std::min(next_critical(arc, x0, v0, lo), T);
    const PosVel end = arc.state(x0, v0, hi);
    if (s * end.xd <= 0) {  // x' reaches 0 in (lo, hi]
      const double tau_v = bracketed_root(velocity, lo, hi, 0.5 * (lo + hi), time_scale);
      if (bounded && s * (arc.state(x0, v0, tau_v).x - X) > 0)
        return {bracketed_root(position, lo, tau_v, 0.5 * (lo + tau_v), time_scale),
                ArcEnd::friction_boundary};
      return {tau_v, ArcEnd::velocity_zero};
    }
    if (bounded && s * (end.x - X) >= 0)
      return {bracketed_root(position, lo, hi, 0.5 * (lo + hi), time_scale),
              ArcEnd::friction_boundary};
    if (hi >= T) return {};
    lo = hi;
  }
  return {};
}

// ---- Per shape: the next event within T (closed form when the table's jerk is 0) ------------

inline SlipEvent next_event(const PolynomialArc& arc, double x0, double v0, int sigma, double X,
                            double T, double time_scale) {
  if (arc.jerk != 0) return scan_events(arc, x0, v0, sigma, X, T, time_scale);
  const double vs = sigma * v0 + 0.0, as = sigma * arc.accel;  // + 0.0: never -0.0
  SlipEvent e;
  const double tau_b = std::isfinite(X) ? parabolic_reach(vs, as, sigma * (X - x0)) : kInf;
  const double tau_v = parabolic_stop(vs, as);
  if (tau_b < T) e = {tau_b, ArcEnd::friction_boundary};
  if (tau_v <= std::min(T, e.tau)) e = {tau_v, ArcEnd::velocity_zero};
  return e;
}

template <class Curved>
SlipEvent curved_event(const Curved& arc, double x0, double v0, int sigma, double X, double T,
                       double time_scale, bool harmonic) {
  if (arc.drift != 0) return scan_events(arc, x0, v0, sigma, X, T, time_scale);
  // + 0.0: from rest, sigma x'0 is -0.0 for sigma = -1, and atan2 / the hyperbolic stop read
  // its sign (a negative stop time: a backward slip from rest on falling friction ran time
  // backwards; tests/test_friction_field.cpp, staircase).
  const double C = sigma * (x0 - arc.center), S = sigma * v0 / arc.omega + 0.0, w = arc.omega;
  const double tau_v = harmonic ? harmonic_stop(C, S, w) : hyperbolic_stop(C, S, w);
  double tau_b = kInf;
  if (std::isfinite(X)) {
    const double target = sigma * (X - arc.center);
    tau_b = harmonic ? harmonic_reach(C, S, w, target) : hyperbolic_reach(C, S, w, target);
    if (std::isfinite(tau_b))
      tau_b = polish_reach(arc, x0, v0, X, tau_b, std::min(tau_v, 2 * tau_b + 1));
  }
  SlipEvent e;
  if (tau_b < T) e = {tau_b, ArcEnd::friction_boundary};
  if (tau_v <= std::min(T, e.tau)) e = {tau_v, ArcEnd::velocity_zero};
  return e;
}
inline SlipEvent next_event(const HarmonicArc& arc, double x0, double v0, int sigma, double X,
                            double T, double time_scale) {
  return curved_event(arc, x0, v0, sigma, X, T, time_scale, true);
}
inline SlipEvent next_event(const HyperbolicArc& arc, double x0, double v0, int sigma, double X,
                            double T, double time_scale) {
  return curved_event(arc, x0, v0, sigma, X, T, time_scale, false);
}

}  // namespace selfalign::detail
