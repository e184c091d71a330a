#pragma once
/// \file unit_system.hpp
/// Which unit system a run's inputs and outputs use, and the output conversion it implies.
///
/// selfalign computes in the dimensionless variables of Sect. 3.2 (units.hpp). A run configured
/// in SI converts its inputs with one Scales and its outputs back with the same Scales;
/// OutputUnits is that output conversion (the identity for dimensionless runs).

#include <optional>
#include <string>

#include "selfalign/units.hpp"

namespace selfalign {

enum class UnitSystem {
  dimensionless,  ///< inputs and outputs in the variables of eq. (4) [-]
  si              ///< inputs and outputs in [m], [s], [m/s], [m/s^2]
};

/// Parses "dimensionless" or "si"; throws InvalidParameter("units", ...) otherwise.
UnitSystem parse_unit_system(const std::string& text);
std::string to_string(UnitSystem units);


/// One value of dimension `d` converted from dimensionless to SI, and from SI to dimensionless
/// (Sect. 3.2); values of Dimension::none are returned unchanged.
double to_si(Dimension d, double value, const Scales& scales);
double to_dimensionless(Dimension d, double value, const Scales& scales);

/// Converts a run's inputs to dimensionless model values [-]: the one input adapter of the 1-D
/// and planar configs (the identity for dimensionless runs).
class InputUnits {
 public:
  /// Dimensionless input: every conversion is the identity.
  InputUnits() = default;
  /// SI input with the run's scales.
  explicit InputUnits(const Scales& scales) : scales_(scales) {}
  InputUnits(UnitSystem units, const Scales& scales)
      : scales_(units == UnitSystem::si ? std::optional<Scales>(scales) : std::nullopt) {}

  bool si() const noexcept { return scales_.has_value(); }
  /// The SI scales (si() only).
  const Scales& scales() const { return scales_.value(); }
  /// `value` of dimension `d` in model units [-].
  double operator()(Dimension d, double value) const noexcept {
    return scales_ ? to_dimensionless(d, value, *scales_) : value;
  }

 private:
  std::optional<Scales> scales_;
};

/// Converts dimensionless results [-] to the run's unit system.
class OutputUnits {
 public:
  /// Dimensionless output: every conversion is the identity.
  OutputUnits() = default;
  /// SI output with the run's scales.
  explicit OutputUnits(const Scales& scales) : scales_(scales) {}

  bool si() const noexcept { return scales_.has_value(); }
  double time(double t) const noexcept { return scales_ ? scales_->time_to_si(t) : t; }
  double length(double x) const noexcept { return scales_ ? scales_->length_to_si(x) : x; }
  double velocity(double v) const noexcept { return scales_ ? scales_->velocity_to_si(v) : v; }
  double acceleration(double a) const noexcept {
    return scales_ ? scales_->acceleration_to_si(a) : a;
  }

 private:
  std::optional<Scales> scales_;
};

}  // namespace selfalign
