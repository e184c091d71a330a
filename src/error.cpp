#include "selfalign/error.hpp"

#include <charconv>
#include <cmath>

namespace selfalign {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

InvalidParameter::InvalidParameter(std::string name, std::string value, std::string allowed)
    : std::invalid_argument("invalid " + name + " = " + value + ": " + allowed),
      name_(std::move(name)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InvalidParameter::InvalidParameter(std::string name, double value, std::string allowed)
    : InvalidParameter(std::move(name), format_number(value), std::move(allowed)) {}

double require_finite(const std::string& name, double value) {
  if (!std::isfinite(value)) throw InvalidParameter(name, value, "must be a finite number");
  return value;
}

double require_positive(const std::string& name, double value) {
  if (!(std::isfinite(value) && value > 0)) throw InvalidParameter(name, value, "must be > 0");
  return value;
}

double require_non_negative(const std::string& name, double value) {
  if (!(std::isfinite(value) && value >= 0)) throw InvalidParameter(name, value, "must be >= 0");
  return value;
}

double require_greater(const std::string& name, double value, double bound) {
  if (!(std::isfinite(value) && value > bound))
    throw InvalidParameter(name, value, "must be > " + format_number(bound));
  return value;
}

double require_in_half_open(const std::string& name, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value > lo && value <= hi))
    throw InvalidParameter(name, value,
                           "must be in (" + format_number(lo) + ", " + format_number(hi) + "]");
  return value;
}

}  // namespace selfalign
