// Second-method oracle for the slip integrator under a Stribeck law (issue 20, F06): fixed-step
// classical RK4 on x'' = -sigma mu(|x'|) - A, mu(v) = k + (s - k) exp(-(v / v_s)^delta), on a
// piecewise-constant table acceleration (segments of durations d_i with accelerations A_i),
// event by event. A step never crosses x' = 0: where one would, the zero is located by
// bisection on the length of a single RK4 step from the last grid point (so no stage of an
// accepted step lies past the kink of mu(|x'|)); at x' = 0 the object sticks while |A| <= s,
// else slips against A. Written from the model alone (docs/slip-integrator.md, S1-S2): no
// dense output, no error control, no Newton, nothing of src/simulate. Global error O(h^4)
// within modes; the events are placed to the bisection's resolution of one RK4 step. Measured
// on the F06 profile: v̄ moves by 1.4e-11 from h = 3e-5 to 1e-5.
// Self-contained (no selfalign includes).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace oracle {

struct StribeckRk4Case {
  std::vector<double> durations, accelerations;  // one period of the table acceleration
  double s = 1, k = 1, v_s = 1, delta = 1;       // static, kinetic, Stribeck velocity, exponent
};

// x at the end of each of `periods` periods from rest at x = 0, t = 0, step h.
inline std::vector<double> stribeck_rk4_positions(const StribeckRk4Case& c, int periods,
                                                  double h_max) {
  struct State { double x, v; };
  int sigma = 0;
  double A = 0;
  auto rhs = [&](State q) {
    const double mu = c.k + (c.s - c.k) * std::exp(-std::pow(std::abs(q.v) / c.v_s, c.delta));
    return State{q.v, -sigma * mu - A};
  };
  auto rk4 = [&](State q, double h) {
    const State k1 = rhs(q), k2 = rhs({q.x + h / 2 * k1.x, q.v + h / 2 * k1.v}),
                k3 = rhs({q.x + h / 2 * k2.x, q.v + h / 2 * k2.v}),
                k4 = rhs({q.x + h * k3.x, q.v + h * k3.v});
    return State{q.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
                 q.v + h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v)};
  };
  double period = 0;
  for (double d : c.durations) period += d;
  std::vector<double> ends;
  double t = 0;
  State q{0, 0};
  for (int n = 0; n < periods; ++n) {
    double seg_end = n * period;
    for (std::size_t i = 0; i < c.durations.size(); ++i) {
      A = c.accelerations[i];
      seg_end = i + 1 == c.durations.size() ? (n + 1) * period : seg_end + c.durations[i];
      while (t < seg_end) {
        if (q.v == 0 && std::abs(A) <= c.s) {  // stick to the segment's end
          t = seg_end;
          break;
        }
        sigma = q.v > 0 ? 1 : q.v < 0 ? -1 : (A > 0 ? -1 : 1);
        const double h = std::min(h_max, seg_end - t);
        const State next = rk4(q, h);
        if (sigma * next.v <= 0) {  // x' = 0 within the step: bisect the step's length
          double lo = 0, hi = h;
          for (int it = 0; it < 100; ++it) {
            const double mid = 0.5 * (lo + hi);
            (sigma * rk4(q, mid).v > 0 ? lo : hi) = mid;
          }
          q = {rk4(q, hi).x, 0.0};
          t += hi;
          continue;
        }
        q = next;
        t = seg_end - (t + h) < 1e-15 ? seg_end : t + h;
      }
    }
    ends.push_back(q.x);
  }
  return ends;
}

}  // namespace oracle
