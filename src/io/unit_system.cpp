#include "selfalign/io/unit_system.hpp"

#include "selfalign/error.hpp"

namespace selfalign {

UnitSystem parse_unit_system(const std::string& text) {
  if (text == "dimensionless") return UnitSystem::dimensionless;
  if (text == "si") return UnitSystem::si;
  throw InvalidParameter("units", text, "must be one of: dimensionless, si");
}

std::string to_string(UnitSystem units) {
  return units == UnitSystem::si ? "si" : "dimensionless";
}

}  // namespace selfalign
