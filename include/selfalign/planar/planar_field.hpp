#pragma once
/// \file planar_field.hpp
/// Friction levels over the table plane for planar motion (issue 13, first slice): the level
/// m(x, y) the kinetic and static coefficients multiply (as FrictionMap's m(x) in 1-D, units of
/// mu_1). A closed set, each exact: uniform; rough regions with a linear transition band of
/// width w inside their boundary (m = 1 + (c_mu - 1) clamp(depth / w, 0, 1), depth = the signed
/// distance into the region): a half-plane (the two-region table of eqs. 7-9 along any
/// direction), a strip, a rectangular and a circular pocket; a sampled grid (bilinear); and the
/// 1-D friction field along an axis (AxisField: the 1-D FrictionField is the family's one-axis
/// case).

#include <variant>
#include <vector>

#include "selfalign/friction/friction_field.hpp"

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

/// A rough strip: the points with |n . (p - origin)| <= half_width, n = (cos angle, sin angle)
/// (the strip runs across n); depth = half_width - |n . (p - origin)|.
struct StripField {
  double origin_x = 0, origin_y = 0;  ///< a point on the strip's centre line [-]
  double angle = 0;                   ///< direction across the strip [rad]
  double half_width = 1;              ///< [-], > 0
  double width = 0.1;                 ///< transition band [-], > 0
  double c_mu = 2.5;                  ///< [-], >= 1
};

/// A rough rectangular pocket centred at (centre_x, centre_y), half sides a (along the
/// direction `angle`) and b; depth = min(a - |xi|, b - |eta|) in the pocket's axes.
struct RectangularPocketField {
  double centre_x = 0, centre_y = 0;
  double angle = 0;
  double half_length = 1, half_width = 1;  ///< a, b [-], > 0
  double width = 0.1;                      ///< transition band [-], > 0
  double c_mu = 2.5;
};

/// A rough circular pocket: depth = radius - |p - centre|.
struct CircularPocketField {
  double centre_x = 0, centre_y = 0;
  double radius = 1;   ///< [-], > 0
  double width = 0.1;  ///< transition band [-], > 0
  double c_mu = 2.5;
};

/// Levels sampled on a regular grid: node (i, j) at origin + i dx e_a + j dy e_b (e_a = (cos
/// angle, sin angle), e_b its normal), value levels[j nx + i]; bilinear inside, the nearest edge
/// value outside (clamped). Values finite and > 0; nx, ny >= 2.
struct GridField {
  double origin_x = 0, origin_y = 0, angle = 0;
  double dx = 1, dy = 1;  ///< spacings [-], > 0
  int nx = 2, ny = 2;
  std::vector<double> levels = {1, 1, 1, 1};
};

/// The 1-D table's friction field (friction_field.hpp: steps, ramps, the samples of a CSV file)
/// laid along the direction n = (cos angle, sin angle) from `origin`, constant across it:
///   m(x, y) = field(n . (p - origin)).
/// The 1-D field is the one-axis case of the planar family: a point contact at angle 0 and
/// origin 0 reads field(x) itself, and a contact patch averages the field over its points as
/// eq. (7)'s footprint averages it in 1-D. Levels in (0, 1e6] everywhere (as a grid's).
struct AxisField {
  FrictionField field;
  double origin_x = 0, origin_y = 0;  ///< where the field's position 0 lies [-]
  double angle = 0;                   ///< direction of increasing position [rad]
  bool operator==(const AxisField&) const = default;
};

using PlanarField = std::variant<UniformPlanarField, HalfPlaneStepField, StripField,
                                 RectangularPocketField, CircularPocketField, GridField,
                                 AxisField>;

/// Throws InvalidParameter naming the first field out of range (a grid level that is NaN, not
/// positive or a count that does not match nx ny names "levels").
void validate(const PlanarField& field);

/// The level at (x, y) [-].
double planar_level(const PlanarField& field, double x, double y);

/// The largest level anywhere on the table [-]: the uniform level, c_mu of a rough region (>= 1
/// outside it), the largest grid value (bilinear stays below it), an axis field's max_level.
double max_planar_level(const PlanarField& field);

/// The field rotated by `angle` about the origin (frame invariance: rotating the setup).
PlanarField rotated_field(const PlanarField& field, double angle);

}  // namespace selfalign
