#include "selfalign/friction/coulomb_friction.hpp"

#include <utility>

#include "selfalign/error.hpp"

namespace selfalign {

CoulombFriction::CoulombFriction(double static_coefficient, double kinetic)
    : CoulombFriction(static_coefficient, kinetic, kinetic) {}

CoulombFriction::CoulombFriction(double static_coefficient, double kinetic_forward,
                                 double kinetic_backward)
    : static_(require_positive_moderate("mu_static", static_coefficient)),
      forward_(require_positive_moderate("mu_kinetic", kinetic_forward)),
      backward_(require_positive_moderate("mu_kinetic_backward", kinetic_backward)) {
  for (const auto& [name, k] : {std::pair{"mu_kinetic", forward_},
                                std::pair{"mu_kinetic_backward", backward_}})
    if (k > static_)
      throw InvalidParameter(std::string("mu_static, ") + name,
                             format_number(static_) + ", " + format_number(k),
                             std::string("the static coefficient must be >= the kinetic one (") +
                                 name + " <= mu_static)");
}

std::string CoulombFriction::describe() const {
  std::string s = "static " + format_number(static_) + ", kinetic ";
  if (forward_ == backward_) return s + format_number(forward_);
  return s + "forward " + format_number(forward_) + ", backward " + format_number(backward_);
}

}  // namespace selfalign
