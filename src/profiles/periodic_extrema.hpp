#pragma once
// Internal: extrema over one period of a smooth periodic function with a known derivative.
// Samples the derivative on a uniform grid and refines every sign change by bisection to
// machine precision, so an extremum is bounded, not just sampled.

#include <algorithm>
#include <cmath>

namespace selfalign::detail {

struct Extrema {
  double min, max;
};

template <class Value, class Derivative>
Extrema periodic_extrema(const Value& f, const Derivative& df, double period, int samples) {
  // f is evaluated once per point (for a Fourier series of order N each evaluation is O(N)).
  const double f0 = f(0.0);
  Extrema e{f0, f0};
  auto include = [&e](double v) {
    e.min = std::min(e.min, v);
    e.max = std::max(e.max, v);
  };
  const double h = period / samples;
  double t_prev = 0.0, d_prev = df(0.0);
  for (int i = 1; i <= samples; ++i) {
    const double t = i * h;
    const double d = df(t);
    include(f(t));
    if ((d_prev < 0) != (d < 0)) {  // a root of f' lies in [t_prev, t]
      double lo = t_prev, hi = t;
      const bool rising = d_prev < 0;
      for (int k = 0; k < 200 && hi - lo > 0; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        ((df(mid) < 0) == rising ? lo : hi) = mid;
      }
      for (double r : {lo, hi}) include(f(r));
    }
    t_prev = t;
    d_prev = d;
  }
  return e;
}

}  // namespace selfalign::detail
