#pragma once
/// \file planar_field.hpp
/// Friction levels over the table plane for planar motion (issue 13, first slice): the level
/// m(x, y) the kinetic and static coefficients multiply (as FrictionMap's m(x) in 1-D, units of
/// mu_1). A closed set, each exact: uniform, and a half-plane step with a linear transition band
/// (the two-region table of eqs. 7-9 along any direction).

#include <variant>

namespace selfalign {

/// m(x, y) = level everywhere.
struct UniformPlanarField {
  double level = 1;
};

/// The two-region table along the unit normal n = (cos angle, sin angle): with
/// d = n . (p - origin), m = 1 for d <= 0, c_mu for d >= width, linear in between (eq. 7 of a
/// point contact; eq. 9's footprint average for an object of that width).
struct HalfPlaneStepField {
  double origin_x = 0, origin_y = 0;  ///< a point on the boundary where the rise starts [-]
  double angle = 0;                   ///< direction of the rise [rad]
  double width = 1;                   ///< transition band [-], > 0
  double c_mu = 2.5;                  ///< mu_2/mu_1 [-], >= 1
};

using PlanarField = std::variant<UniformPlanarField, HalfPlaneStepField>;

/// Throws InvalidParameter naming the first field out of range.
void validate(const PlanarField& field);

/// The level at (x, y) [-].
double planar_level(const PlanarField& field, double x, double y);

/// The field rotated by `angle` about the origin (frame invariance: rotating the setup).
PlanarField rotated(const PlanarField& field, double angle);

}  // namespace selfalign
