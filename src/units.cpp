#include "selfalign/units.hpp"

#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

Scales::Scales(double length_m, double mu, double gravity)
    : length_(require_positive("length_scale", length_m)),
      mu_(require_positive("mu", mu)),
      gravity_(require_positive("g", gravity)),
      time_(std::sqrt(length_ / (mu_ * gravity_))) {}

}  // namespace selfalign
