#include "selfalign/simulate/arc.hpp"

#include "arc_math.hpp"

namespace selfalign {

ObjectState Arc::at(double t) const noexcept {
  const detail::PosVel s = detail::arc_state(kind, x0, xd0, alpha, omega, center, t - t0);
  return {t, s.x, s.xd};
}

}  // namespace selfalign
