#pragma once
// A second method for a part launched on a table at rest: fixed-step RK4 on the smooth
// sliding-and-spinning equations of a contact patch, run to its common stop (the planar
// Moreau stepper's and the patch integrator's tests compare with it).

#include <algorithm>
#include <cmath>

#include "selfalign/planar/contact_patch.hpp"

namespace selfalign::testing_support {

// RK4 on v' = -sum w_i u_i/|u_i|, j omega' = -sum w_i p_i x u_i/|u_i| (k = m = 1, table at
// rest, u_i = v + omega J p_i, the points turning with the body) until |v| + R|omega| < 1e-9.
inline double rk4_stop_time(const ContactPatch& patch, double inertia, double v0, double w0, double dt) {
  struct S { double vx, vy, w, a; };
  const auto rate = [&](const S& s) {
    S d{0, 0, 0, s.w};
    const double c = std::cos(s.a), sn = std::sin(s.a);
    for (const auto& p : patch) {
      const double px = c * p.x - sn * p.y, py = sn * p.x + c * p.y;
      const double ux = s.vx - s.w * py, uy = s.vy + s.w * px, u = std::hypot(ux, uy);
      if (u == 0) continue;
      d.vx -= p.load * ux / u, d.vy -= p.load * uy / u;
      d.w -= p.load * (px * uy - py * ux) / u / inertia;
    }
    return d;
  };
  const auto axpy = [](const S& s, double h, const S& d) {
    return S{s.vx + h * d.vx, s.vy + h * d.vy, s.w + h * d.w, s.a + h * d.a};
  };
  S s{v0, 0, w0, 0};
  double t = 0;
  while (std::hypot(s.vx, s.vy) + 0.2 * std::abs(s.w) > 1e-9) {
    // the last step is shortened so the speeds reach ~0 (they fall at a rate of order 1)
    const double h = std::min(dt, 0.5 * (std::hypot(s.vx, s.vy) + 0.2 * std::abs(s.w)));
    const S k1 = rate(s), k2 = rate(axpy(s, h / 2, k1)), k3 = rate(axpy(s, h / 2, k2)),
            k4 = rate(axpy(s, h, k3));
    s = {s.vx + h / 6 * (k1.vx + 2 * k2.vx + 2 * k3.vx + k4.vx),
         s.vy + h / 6 * (k1.vy + 2 * k2.vy + 2 * k3.vy + k4.vy),
         s.w + h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w),
         s.a + h / 6 * (k1.a + 2 * k2.a + 2 * k3.a + k4.a)};
    t += h;
  }
  return t;
}

}  // namespace selfalign::testing_support
