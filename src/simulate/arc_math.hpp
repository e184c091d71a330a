#pragma once
// Internal: the closed-form arc solutions shared by Arc::at and the exact solver.

#include <cmath>

#include "selfalign/simulate/arc.hpp"

namespace selfalign::detail {

struct PosVel {
  double x, xd;
};

/// State after tau on an arc starting at (x0, xd0).
inline PosVel arc_state(ArcKind kind, double x0, double xd0, double alpha, double omega,
                        double center, double tau) noexcept {
  switch (kind) {
    case ArcKind::stick:
      return {x0, 0.0};
    case ArcKind::parabolic:  // eqs. (15)-(20)
      return {x0 + tau * (xd0 + 0.5 * alpha * tau), xd0 + alpha * tau};
    case ArcKind::harmonic: {  // eqs. (43)-(46)
      const double c = std::cos(omega * tau), s = std::sin(omega * tau), d1 = x0 - center;
      return {center + d1 * c + xd0 / omega * s, -d1 * omega * s + xd0 * c};
    }
    case ArcKind::hyperbolic: {
      const double c = std::cosh(omega * tau), s = std::sinh(omega * tau), d1 = x0 - center;
      return {center + d1 * c + xd0 / omega * s, d1 * omega * s + xd0 * c};
    }
  }
  return {x0, xd0};
}

}  // namespace selfalign::detail
