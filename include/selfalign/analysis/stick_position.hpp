#pragma once
/// \file stick_position.hpp
/// Where the object can stop in the friction transition region (Sect. 7.2, 7.3).
///
///  - eq. (40): the object can stay stuck for good at x iff m(x) >= max |y''|;
///  - eq. (41): x_stick,min = x_mu + w (max|y''| - 1)/(c_mu - 1), the first such position;
///  - eq. (59): the map x_n -> x_{n+1} between successive stick positions of a three-phase
///    profile in the transition region, with fixed point (eq. 60) (b2 + y2'')/b1 and slope
///    cos(sqrt(b1) (t2 - t1)) there (docs/accumulation.md).

#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

/// eq. (40): true iff an object at rest at x is held by friction whatever the table does.
bool sticks_permanently(const FrictionMap& friction, double peak_acceleration, double x);

/// eq. (41) [-]: the smallest x >= x_mu at which eq. (40) holds. x_mu when the peak
/// acceleration is <= 1; +inf when it exceeds c_mu (the object never stops for good).
double stick_position_min(const TwoRegionFriction& friction, double peak_acceleration);

/// The stick-position map of eq. (59) for a three-phase profile on a two-region table.
///
/// Between two sticks the object (stuck through [t2-, t3] and [t0, t1]) slides forward on
/// [t1, t2] on a harmonic arc about c1 = (b2 + y2'')/b1 and on [t2, ...] about
/// c2 = (b2 - y3'')/b1 until x' = 0 at the arc's crest:
///   x_{n+1} = c2 + sqrt( (K + d cos θ)^2 + (d sin θ)^2 ),   d = x_n - c1,
///   K = (y2'' + y3'')/b1,   θ = sqrt(b1) (t2 - t1).
class StickPositionMap {
 public:
  StickPositionMap(const ThreePhaseProfile& profile, const TwoRegionFriction& friction);

  double operator()(double x_n) const;  ///< x_{n+1}, eq. (59) [-]
  double fixed_point() const { return c1_; }  ///< eq. (60): (b2 + y2'')/b1 [-]
  double slope_at_fixed_point() const;  ///< d x_{n+1}/d x_n at the fixed point: cos θ [-]
  /// x_{n+1}(x) < fixed point iff x > this bound (for x < fixed point) [-].
  double basin_lower_bound() const;
  /// Sect. 7.3: accumulation for every entry iff x_{n+1}(x_mu) < x_stick,min.
  bool accumulates_for_every_entry() const;
  /// Whether an object stuck at x_n at the start of a period (before t1) provably accumulates
  /// to the fixed point: the map's assumptions hold at x_n and along the (increasing) sequence
  /// (docs/accumulation.md lists them). False where the map does not describe the motion.
  bool proves_accumulation_from(double x_n) const;
  /// Time from t1 to the stop x_{n+1}, i.e. (t2 - t1) + eq. (58)'s arc time [-].
  double slip_duration(double x_n) const;

 private:
  ThreePhaseParameters p_;
  double x_mu_, w_, c_mu_, b1_, omega_, T2_, T3_, c1_, c2_, K_, x_stick_min_;
  bool shape_ok_;  // the assumptions that do not depend on x_n
};

}  // namespace selfalign
