#include "selfalign/friction/friction_law.hpp"

#include <cmath>
#include <utility>

#include "selfalign/error.hpp"

namespace selfalign {

FrictionLaw::FrictionLaw(double static_coefficient, double kinetic)
    : FrictionLaw(static_coefficient, kinetic, kinetic) {}

FrictionLaw::FrictionLaw(double static_coefficient, double kinetic_forward,
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

FrictionLaw FrictionLaw::with_stribeck(double stribeck_velocity, double exponent) const {
  FrictionLaw law = *this;
  law.stribeck_velocity_ = require_positive_moderate("stribeck_velocity", stribeck_velocity);
  if (!(exponent > 0 && exponent <= 100))
    throw InvalidParameter("stribeck_exponent", exponent, "must be in (0, 100]");
  law.exponent_ = exponent;
  return law;
}

FrictionLaw FrictionLaw::with_viscous(double viscous) const {
  if (!(viscous >= 0 && viscous <= 1e50))
    throw InvalidParameter("viscous", viscous, "must be in [0, 1e50]");
  FrictionLaw law = *this;
  law.viscous_ = viscous;
  return law;
}

double FrictionLaw::kinetic(int sigma, double speed) const noexcept {
  const double k = kinetic(sigma);
  if (!(stribeck_velocity_ > 0)) return k;
  return k + (static_ - k) * std::exp(-std::pow(speed / stribeck_velocity_, exponent_));
}

std::string FrictionLaw::describe() const {
  std::string s = "static " + format_number(static_) + ", kinetic ";
  if (forward_ == backward_) s += format_number(forward_);
  else s += "forward " + format_number(forward_) + ", backward " + format_number(backward_);
  if (stribeck_velocity_ > 0)
    s += ", Stribeck v_s " + format_number(stribeck_velocity_) + " delta " +
         format_number(exponent_);
  if (viscous_ > 0) s += ", viscous " + format_number(viscous_);
  return s;
}

FrictionLaw law_of_coefficients(double mu, std::optional<double> mu_static,
                                std::optional<double> mu_backward) {
  require_positive_moderate("mu", mu);
  const double s = require_positive_moderate("mu_static", mu_static.value_or(mu));
  const double back = require_positive_moderate("mu_backward", mu_backward.value_or(mu));
  if (!(s >= mu))
    throw InvalidParameter("mu_static", s, "must be >= mu = " + format_number(mu) +
                                               " (the static coefficient is >= the kinetic one)");
  if (!(s >= back))
    throw InvalidParameter("mu_backward", back,
                           "must be <= mu_static = " + format_number(s) +
                               " (the static coefficient is >= the kinetic one)");
  // The ratios FrictionLaw holds stay within [1e-50, 1e50] (its own range).
  if (!(s <= kMaxMagnitude * mu))
    throw InvalidParameter("mu_static", s, "must be <= 1e50 mu = " + format_number(kMaxMagnitude * mu));
  if (!(back >= mu / kMaxMagnitude))
    throw InvalidParameter("mu_backward", back,
                           "must be >= 1e-50 mu = " + format_number(mu / kMaxMagnitude));
  return FrictionLaw(s / mu, 1.0, back / mu);
}

}  // namespace selfalign
