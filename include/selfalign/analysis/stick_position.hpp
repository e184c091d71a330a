#pragma once
/// \file stick_position.hpp
/// Where the object can stop in the friction transition region (Sect. 7.2, 7.3).
///
///  - eq. (40): the object can stay stuck for good at x iff m(x) >= max |y''|;
///  - eq. (41): x_stick,min = x_mu + w (max|y''| - 1)/(c_mu - 1), the first such position;
///  - eq. (59): the map x_n -> x_{n+1} between successive stops of a three-phase profile in the
///    transition region, with fixed point (eq. 60) (b2 + y2'')/b1 and slope
///    cos(sqrt(b1) (t2 - t1)) there;
///  - the stick-position map: where the object is at rest at the next t1. It is eq. (59) where
///    friction holds the object at that stop (m >= y3''), and otherwise adds the slide back
///    that follows (on the diagonal y3'' = y2'' at every stop below x_stick,min);
///  - the proof of accumulation and the domain of Sect. 7.3's condition for every entry;
///  - the same stick-position map on any piecewise-affine level, by the exact solver
///    (PeriodStickPositionMap): where no closed form exists (a field, several steps, ramps).
/// Derivations: docs/accumulation.md.

#include <memory>
#include <optional>
#include <string>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

class PeriodMap;

/// eq. (40): true iff an object at rest at x is held by friction whatever the table does.
bool sticks_permanently(const FrictionMap& friction, double peak_acceleration, double x);
/// Eq. (40) under a Coulomb law: stuck for good at x iff s m(x) >= sup |y''| (s: the static
/// coefficient, which holds a stuck object).
bool sticks_permanently(const FrictionMap& friction, const FrictionLaw& law,
                        double peak_acceleration, double x);
/// The general x_mu: the start of the first piece whose level differs from the level far
/// behind (x -> -inf); +inf for a uniform level.
double friction_rise(const PiecewiseAffineFriction& friction);
/// Where a stopping run measures from: the two-region table's x_mu, else the rise of the
/// piecewise-affine level (InvalidParameter naming "friction" for a map without pieces).
double friction_rise(const FrictionMap& friction);
/// The general eq. (41): the smallest x >= friction_rise from which s m(x') >= peak for every
/// x' >= x (exact on the affine pieces); +inf when the level far ahead is too low.
double stick_position_min(const PiecewiseAffineFriction& friction, const FrictionLaw& law,
                          double peak_acceleration);


/// eq. (41) [-]: the smallest x >= x_mu at which eq. (40) holds. x_mu when the peak
/// acceleration is <= 1; +inf when it exceeds c_mu (the object never stops for good).
double stick_position_min(const TwoRegionTable& table, double peak_acceleration);

/// Sect. 7.3's statement "accumulation for every entry iff x_{n+1}(x_mu) < x_stick,min" at one
/// setting, with the domain where its derivation holds (docs/accumulation.md). Every entry
/// means every first stop x_1 in [x_mu, x_stick,min).
struct EveryEntryAccumulation {
  bool applies = false;      ///< the derivation holds; otherwise nothing is claimed
  bool accumulates = false;  ///< when applies: x_{n+1}(x_mu) < x_stick,min
  std::string reason;        ///< when it does not apply: the assumption that fails
};

/// The stick-position map of eq. (59) for a three-phase profile on a two-region table.
///
/// Between two sticks the object (stuck through [t2-, t3] and [t0, t1]) slides forward on
/// [t1, t2] on a harmonic arc about c1 = (b2 + y2'')/b1 and on [t2, ...] about
/// c2 = (b2 - y3'')/b1 until x' = 0 at the arc's crest:
///   x_{n+1} = c2 + sqrt( (K + d cos θ)^2 + (d sin θ)^2 ),   d = x_n - c1,
///   K = (y2'' + y3'')/b1,   θ = sqrt(b1) (t2 - t1).
class StickPositionMap {
 public:
  StickPositionMap(const ThreePhaseProfile& profile, const TwoRegionTable& table);

  double operator()(double x_n) const;  ///< x_{n+1}, eq. (59) [-]
  double fixed_point() const { return c1_; }  ///< eq. (60): (b2 + y2'')/b1 [-]
  double slope_at_fixed_point() const;  ///< d x_{n+1}/d x_n at the fixed point: cos θ [-]
  /// x_{n+1}(x) < fixed point iff x > this bound (for x < fixed point) [-].
  double basin_lower_bound() const;

  /// Where an object at rest at x_n through [t0, t1] is at rest at the next t1 [-]: the stop of
  /// eq. (59) where m there >= y3''; otherwise that stop, the slide back under +y3'' (about
  /// (b2 + y3'')/b1) and under y'' = 0 (about b2/b1) until x' = 0 before the next t1. x_n for
  /// x_n >= fixed point where m(x_n) >= y3'' (held). NaN where the motion leaves these arcs:
  /// the forward slip ends inside [t1, t2] or after t3, the slide back does not end before
  /// t1, or it leaves the transition region.
  double next_stick_position(double x_n) const;
  /// d next_stick_position / d x_n at the fixed point [-]: cos θ for y3'' < y2'' (the stop
  /// holds there), cos θ cosh(sqrt(b1) (t3 - t2)) on the diagonal y3'' = y2''. NaN where the
  /// fixed point is not x_stick,min (y3'' > y2'', y2'' <= 1 or y2'' > c_mu).
  double contraction_at_fixed_point() const;

  /// Sect. 7.3's condition for accumulation from every entry, where it applies.
  EveryEntryAccumulation every_entry_accumulation() const;
  /// every_entry_accumulation() as a value: x_{n+1}(x_mu) < x_stick,min, or nullopt where the
  /// condition does not apply (no x_stick,min, y3'' > y2'', ...).
  std::optional<bool> accumulates_for_every_entry() const;
  /// Whether an object at rest at x_n through [t0, t1] provably accumulates to the fixed point
  /// x_stick,min: the stops of eq. (59) are held and rise (m >= y3''), or the slides back
  /// after them are bounded by a contraction (docs/accumulation.md lists the conditions; they
  /// then hold along the whole sequence). False where neither is proven.
  bool proves_accumulation_from(double x_n) const;
  /// Time from t1 to the stop x_{n+1}, i.e. (t2 - t1) + eq. (58)'s arc time [-].
  double slip_duration(double x_n) const;

 private:
  bool held_at(double x) const;               // m(x) >= y3''
  bool slide_back_contracts(double s) const;  // the contraction bound at c1 - x_n = s
  ThreePhaseParameters p_;
  double x_mu_, w_, c_mu_, b1_, omega_, T1_, T2_, T3_, c1_, c2_, K_, x_stick_min_;
  bool shape_ok_;  // the assumptions that do not depend on x_n
};

/// The phase of a stopping run's looks (stopping.hpp) and of the stick-position maps [-]: t1 for
/// the three-phase profile, the start of its -y2'' segment as the solver forms the switch (the
/// object has rested through [t0, t1] there); 0 for other profiles.
double stopping_look_phase(const TableProfile& profile);

/// The stick-position map of any piecewise-affine level under any Coulomb law, by the exact
/// solver (issue 21: accumulation on any field): where an object at rest at x_n at the look
/// phase of the profile is one period later, when it is at rest there; NaN when it is moving
/// then (its motion is not a sequence of stops at that phase). The look is the stopping run's
/// (stopping.hpp): phase t1 for the three-phase profile (the start of its -y2'' segment, where
/// the object has rested through [t0, t1]), phase 0 for other profiles. On the paper's table
/// under the paper's law it is StickPositionMap::next_stick_position (eq. 59 and the slide back
/// that follows; tests/test_stick_position.cpp compares them), where the closed form exists;
/// elsewhere it is the map itself, its fixed points x with s m(x) >= max |y''| (held for good,
/// eq. 40), the lowest of them stick_position_min (eq. 41's general form), where stops below
/// accumulate.
class PeriodStickPositionMap {
 public:
  /// Borrows profile and friction (they must outlive the map). The profile must be piecewise
  /// polynomial and the level piecewise affine, the law velocity-independent (the exact
  /// solver; InvalidParameter naming "profile", "friction" or "law" otherwise).
  PeriodStickPositionMap(const TableProfile& profile, const FrictionMap& friction,
                         const FrictionLaw& law = {});
  ~PeriodStickPositionMap();
  PeriodStickPositionMap(const PeriodStickPositionMap&) = delete;
  PeriodStickPositionMap& operator=(const PeriodStickPositionMap&) = delete;

  /// x_{n+1}: the position at rest one period after rest at x_n at the look [-]; NaN when the
  /// object is moving then (x_n must be finite and moderate, InvalidParameter otherwise).
  double operator()(double x_n) const;
  double look_phase() const noexcept { return phase_; }  ///< the look's phase [-]

 private:
  std::unique_ptr<PeriodMap> map_;
  double phase_ = 0, period_ = 0;
};

}  // namespace selfalign
