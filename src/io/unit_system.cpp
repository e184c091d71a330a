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

double to_si(Dimension d, double v, const Scales& s) {
  switch (d) {
    case Dimension::length: return s.length_to_si(v);
    case Dimension::time: return s.time_to_si(v);
    case Dimension::velocity: return s.velocity_to_si(v);
    case Dimension::acceleration: return s.acceleration_to_si(v);
    case Dimension::jerk: return s.jerk_to_si(v);
    case Dimension::rate: return v / s.time();
    case Dimension::none: break;
  }
  return v;
}

double to_dimensionless(Dimension d, double v, const Scales& s) {
  switch (d) {
    case Dimension::length: return s.length_from_si(v);
    case Dimension::time: return s.time_from_si(v);
    case Dimension::velocity: return s.velocity_from_si(v);
    case Dimension::acceleration: return s.acceleration_from_si(v);
    case Dimension::jerk: return s.jerk_from_si(v);
    case Dimension::rate: return v * s.time();
    case Dimension::none: break;
  }
  return v;
}

}  // namespace selfalign
