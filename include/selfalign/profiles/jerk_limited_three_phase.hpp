#pragma once
/// \file jerk_limited_three_phase.hpp
/// The three-phase profile (three_phase.hpp) with a finite jerk limit j (Sect. 8, item 2):
/// every acceleration switch becomes a linear ramp of duration |Δy''|/j. Over one period
///
///   y'' = 0 (T1) -> ramp to -a2 (a2/j) -> -a2 (T2h) -> ramp to +a3 ((a2+a3)/j)
///       -> +a3 (T3h) -> ramp to 0 (a3/j)
///
/// with period Δt, stroke Δy, min y = 0, y and y' periodic, and T1, T2h, T3h >= 0.
/// docs/jerk-limited-three-phase.md derives the solution: with D the velocity swing,
///   T2h = D/a2 - a2/j,  T3h = D/a3 - a3/j,  T1 = Δt - s D - (a2 + a3)/j   (s = 1/a2 + 1/a3),
/// and the stroke is strictly increasing in D on
///   [D_min, D_max] = [max(a2,a3)^2/j, (Δt - (a2+a3)/j)/s].
/// When both zero crossings of y' fall in the constant-acceleration parts (the usual case, and
/// always for large j) D is a closed form of two nested quadratics; otherwise a bisection on
/// D over that certified bracket. A profile exists iff (docs, eqs. J13-J16)
///   j >= j_p = (s max(a2,a3)^2 + a2 + a3)/Δt   and
///   S_min(j) <= Δy <= Δt^2/(8 s) - (a2+a3)^3/(24 j^2),
/// i.e. iff j >= min_jerk (reported in the solution). jerk = +inf reproduces ThreePhaseProfile
/// exactly (its segments, bit for bit).

#include <array>
#include <string>

#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The free parameters of the jerk-limited three-phase profile [-].
struct JerkLimitedThreePhaseParameters {
  double period;  ///< Δt [-], in [1e-50, 1e50]
  double stroke;  ///< Δy = max y - min y [-], in [1e-50, 1e50]
  double a2;      ///< y2'' > 0: the table accelerates with -a2 on its second plateau [-]
  double a3;      ///< y3'' > 0: the table accelerates with +a3 on its third plateau [-]
  double jerk;    ///< j > 0: |y'''| on the ramps [-]; +inf: jump accelerations (three-phase)
};

/// Why no jerk-limited profile exists ("case 0"), or none.
enum class JerkLimitedCase0 {
  none,                   ///< physical
  accelerations_too_low,  ///< no jerk helps: 1/a2 + 1/a3 > Δt^2/(8 Δy) (three-phase case 0)
  ramps_exceed_period,    ///< j < j_p: the ramps alone (with T1 = T2h = T3h = 0) outlast Δt
  stroke_too_large,       ///< Δy > Δt^2/(8s) - (a2+a3)^3/(24 j^2): the ramps eat the stroke
  stroke_too_small,       ///< Δy < S_min(j): reaching both plateaus overshoots the stroke
};

/// Short snake_case name of a reason ("none", "stroke_too_large", ...).
const char* to_string(JerkLimitedCase0 reason) noexcept;

/// Solution of the jerk-limited three-phase constraints, or case 0.
struct JerkLimitedThreePhaseSolution {
  bool physical = false;  ///< false: case 0; the durations and velocities below are then 0
  JerkLimitedCase0 reason = JerkLimitedCase0::none;  ///< why case 0 (none when physical)
  /// The six phase durations in order [-] (ramps are 0 for jerk = +inf):
  double hold0 = 0;      ///< T1, y'' = 0 (t1 = T1 is where the first ramp starts)
  double ramp_down = 0;  ///< a2/j, y'' from 0 to -a2
  double hold2 = 0;      ///< T2h, y'' = -a2
  double ramp_up = 0;    ///< (a2+a3)/j, y'' from -a2 to +a3
  double hold3 = 0;      ///< T3h, y'' = +a3
  double ramp_end = 0;   ///< a3/j, y'' from +a3 to 0
  double velocity_swing = 0;  ///< D = y'_max - y'_min = a2 (T2h + a2/j) = a3 (T3h + a3/j) [-]
  double yd_ini = 0;          ///< y' on the first hold, the largest velocity (= D L/(2Δt)) [-]
  /// Smallest jerk for which (period, stroke, a2, a3) has a profile [-]; +inf when no finite
  /// jerk has one (accelerations_too_low, or Δy = Δt^2/(8s) exactly: jumps only).
  double min_jerk = 0;
  /// true: closed form (docs eqs. J9, J10, or the three-phase closed form for jerk = +inf);
  /// false: bisection on D (a zero crossing of y' on a ramp, docs Sect. "Regime R").
  bool closed_form = false;

  std::array<double, 6> durations() const noexcept {
    return {hold0, ramp_down, hold2, ramp_up, hold3, ramp_end};
  }
};

/// Throws InvalidParameter unless period, stroke (in [1e-50, 1e50]), a2, a3 are finite and > 0
/// (as validate(ThreePhaseParameters)) and jerk > 0 (+inf allowed; NaN refused).
void validate(const JerkLimitedThreePhaseParameters& p);

/// Solves the constraints (docs/jerk-limited-three-phase.md). Validates p (throws on misuse);
/// returns physical = false with a reason (case 0) when no profile exists. min_jerk is set
/// whenever p is valid, physical or not.
JerkLimitedThreePhaseSolution solve_jerk_limited_three_phase(
    const JerkLimitedThreePhaseParameters& p);

/// A physical jerk-limited three-phase profile.
class JerkLimitedThreePhaseProfile final : public TableProfile {
 public:
  /// Throws InvalidParameter on misuse, and on case 0: naming "a2, a3" (accelerations too low
  /// for any jerk, as ThreePhaseProfile) or "jerk" with the smallest feasible jerk.
  explicit JerkLimitedThreePhaseProfile(const JerkLimitedThreePhaseParameters& p);

  const JerkLimitedThreePhaseParameters& parameters() const noexcept { return params_; }
  const JerkLimitedThreePhaseSolution& solution() const noexcept { return solution_; }

  double period() const override { return params_.period; }
  TableState state(double t) const override { return shape_.state(t); }
  double velocity(double t) const override { return shape_.velocity(t); }
  double peak_acceleration() const override { return shape_.peak_acceleration(); }
  double stroke() const override { return shape_.stroke(); }
  std::string kind() const override { return "jerk-limited-three-phase"; }
  const PiecewisePolynomialProfile* piecewise_polynomial() const override { return &shape_; }

 private:
  JerkLimitedThreePhaseParameters params_;
  JerkLimitedThreePhaseSolution solution_;
  PiecewisePolynomialProfile shape_;
};

}  // namespace selfalign
