#include "selfalign/simulate/object_state.hpp"

#include "selfalign/error.hpp"

namespace selfalign {

void validate(const ObjectState& start) {
  require_finite("t0", start.t);
  require_moderate("x0", start.x);
  require_moderate("v0", start.xd);
}

void Trajectory::reserve(std::size_t n) {
  for (auto* v : {&t, &x, &xd, &y, &yd, &ydd}) v->reserve(n);
  stick.reserve(n);
}

void Trajectory::push(double t_, double x_, double xd_, double y_, double yd_, double ydd_,
                      bool stick_) {
  t.push_back(t_);
  x.push_back(x_);
  xd.push_back(xd_);
  y.push_back(y_);
  yd.push_back(yd_);
  ydd.push_back(ydd_);
  stick.push_back(stick_ ? 1 : 0);
}

}  // namespace selfalign
