#pragma once
/// \file three_phase.hpp
/// The table motion with three constant-acceleration intervals (Sect. 4.4.3, Fig. 7, Appendix):
///   [t0, t1]: y'' = 0,   [t1, t2]: y'' = -y2'',   [t2, t3]: y'' = +y3''   (t0 = 0, t3 = Δt)
/// with min y = 0, stroke Δy, and y, y' periodic.
///
/// The appendix solves its equations (61)-(67) symbolically and omits the result as "too long".
/// selfalign uses the short closed form derived in docs/three-phase-profile.md: with
///   s = 1/y2'' + 1/y3'',   G = sqrt(2 s Δy) / Δt,
/// a physical profile exists iff G <= 1/2 (i.e. 1/y2'' + 1/y3'' <= Δt^2 / (8 Δy)), and then
///   u = 1 - sqrt(1 - 2G)            (fraction of the period spent accelerating)
///   D = u Δt / s                    (velocity swing y'_max - y'_min)
///   t1 = (1 - u) Δt,  t2 = t1 + D/y2'',  t3 = Δt,
///   y'_ini = u^2 Δt / (2 s) >= 0,   y_ini = y'_ini^2 / (2 y3'').
/// The appendix's second branch y'_ini < 0 is empty: with y'' <= 0 until t2 and the velocity
/// returning to y'_ini at t3, y'_ini is the largest velocity of the period, and a zero-mean
/// velocity (periodic y) makes it >= 0. The quadratic's other root u = 1 + sqrt(1 - 2G) gives
/// t1 < 0. Both facts are proven in the docs and checked by tests.

#include <string>

#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The free parameters of the three-phase profile [-].
struct ThreePhaseParameters {
  double period;  ///< Δt = t3 - t0 [-], in [1e-50, 1e50]
  double stroke;  ///< Δy = max y - min y [-], in [1e-50, 1e50]
  double a2;      ///< y2'' > 0: the table accelerates with -y2'' on [t1, t2] [-]
  double a3;      ///< y3'' > 0: the table accelerates with +y3'' on [t2, t3] [-]
};

/// Solution of eqs. (61)-(67), or "case 0" (non-physical) when none exists.
struct ThreePhaseSolution {
  bool physical = false;  ///< false: case 0, no real solution; the times below are then 0
  double t1 = 0, t2 = 0, t3 = 0;  ///< switch times [-] (t0 = 0)
  double y_ini = 0;               ///< y(t0) [-]
  double yd_ini = 0;              ///< y'(t0) = y' on [t0, t1] [-], >= 0
  double velocity_swing = 0;      ///< D = y'_max - y'_min = y2'' (t2 - t1) = y3'' (t3 - t2) [-]
  double t_yd0_1 = 0;             ///< time of y' = 0 in [t1, t2] (table at its maximum y) [-]
  double t_yd0_2 = 0;             ///< time of y' = 0 in [t2, t3] (table at y = 0) [-]
  double inverse_accel_sum = 0;   ///< s = 1/y2'' + 1/y3'' [-]
  double inverse_accel_limit = 0; ///< largest physical s: Δt^2 / (8 Δy) [-]
};

/// Throws InvalidParameter unless period, stroke, a2, a3 are finite and > 0.
void validate(const ThreePhaseParameters& p);

/// Closed-form solution of the appendix's eqs. (61)-(67). Validates p (throws on misuse);
/// returns physical = false (case 0) when the requested stroke cannot be reached.
ThreePhaseSolution solve_three_phase(const ThreePhaseParameters& p);

/// A physical three-phase profile.
class ThreePhaseProfile final : public TableProfile {
 public:
  /// Throws InvalidParameter on misuse, and on a non-physical (case 0) request, naming
  /// "a2, a3" and the allowed range 1/a2 + 1/a3 <= period^2/(8 stroke).
  explicit ThreePhaseProfile(const ThreePhaseParameters& p);

  const ThreePhaseParameters& parameters() const noexcept { return params_; }
  const ThreePhaseSolution& solution() const noexcept { return solution_; }

  double period() const override { return params_.period; }
  TableState state(double t) const override { return shape_.state(t); }
  double velocity(double t) const override { return shape_.velocity(t); }
  double peak_acceleration() const override { return shape_.peak_acceleration(); }
  double stroke() const override { return shape_.stroke(); }
  std::string kind() const override { return "three-phase"; }
  const PiecewisePolynomialProfile* piecewise_polynomial() const override { return &shape_; }
  const ThreePhaseProfile* three_phase() const override { return this; }

 private:
  ThreePhaseParameters params_;
  ThreePhaseSolution solution_;
  PiecewisePolynomialProfile shape_;
};

}  // namespace selfalign
