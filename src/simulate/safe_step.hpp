#pragma once
// Internal: safe steps, the certified scan of the stepping exact solvers (smooth_exact.cpp,
// the feeder's smooth solver): the longest step over which a function known by its value, its
// slope and a bound of its curvature provably stays >= 0, so that no root is stepped over.

#include <cmath>

#include "selfalign/special_values.hpp"

namespace selfalign::detail {

// The largest d >= 0 with f + f1 d - (bound / 2) d^2 >= 0, for f >= 0 (a safe step: a function
// with value f, slope f1 and |second derivative| <= bound stays >= 0 over [0, d]). Written
// without cancellation on both signs of f1.
inline double safe_step(double f, double f1, double bound) {
  if (f < 0 || (f == 0 && f1 <= 0)) return 0.0;
  if (bound == 0) return f1 < 0 ? f / -f1 : kInf;
  const double root = std::sqrt(f1 * f1 + 2 * bound * f);
  return f1 >= 0 ? (f1 + root) / bound : 2 * f / (root - f1);
}

// The largest d with f + f1 d - c2 d^2 - c3 d^3 >= 0 (c2, c3 >= 0, f >= 0: a concave cubic,
// one positive root), from below: Newton from the right converges monotonically onto the root
// of a concave function; the last iterate is checked and, if rounding left it past the root,
// pulled back. Used with c2 = |y^(3)(t)|/2 and c3 = Y4/6, a local bound often far tighter than
// Y3 d^2/2 (Y3 sums every harmonic's amplitude).
inline double safe_step_local(double f, double f1, double c2, double c3, double from_above) {
  auto P = [&](double d) { return f + d * (f1 - d * (c2 + c3 * d)); };
  double d = from_above;
  if (!(d > 0) || !std::isfinite(d)) return 0.0;
  for (int i = 0; i < 8 && P(d) < 0; ++i) {
    const double slope = f1 - d * (2 * c2 + 3 * c3 * d);
    if (!(slope < 0)) break;
    d -= P(d) / slope;
  }
  for (int i = 0; i < 4 && P(d) < 0; ++i) d *= 0.5;
  return P(d) >= 0 ? d : 0.0;
}

}  // namespace selfalign::detail
