#pragma once
/// \file table_profile.hpp
/// The prescribed periodic table motion y(t) (Sect. 4.4): the interface every profile family
/// implements.
///
/// All quantities are dimensionless (Sect. 3.2). A profile is periodic with period Δt; its
/// velocity has zero mean (the table returns to its start position), and by convention
/// min y = 0 (Sect. 4.4.3, constraint 1), so the stroke is Δy = max y.

#include <array>
#include <limits>
#include <string>

namespace selfalign {

class PiecewisePolynomialProfile;
class FourierProfile;
class ThreePhaseProfile;

/// A smooth table motion with y and its first three derivatives in closed form and bounds on
/// its third and fourth derivatives: what the exact solver for smooth profiles needs
/// (simulate/smooth_exact.hpp). Under a constant friction level the slip velocity is then
/// closed-form, x'(t) = x'(t0) - (y'(t) - y'(t0)) - sigma k m (t - t0), and its events are
/// isolated by these bounds.
class SmoothMotion {
 public:
  virtual ~SmoothMotion() = default;
  /// y, y', y'', y^(3) at any real t [-].
  virtual std::array<double, 4> derivatives(double t) const = 0;
  /// Upper bounds of sup_t |y^(3)(t)| and sup_t |y^(4)(t)| [-].
  virtual double jerk_bound() const = 0;
  virtual double snap_bound() const = 0;
  /// An upper bound of sup_t |y^(5)(t)| [-]; +inf (the default) when unknown, which turns off
  /// the a posteriori longer steps of the smooth solver (smooth_exact.cpp).
  virtual double fifth_derivative_bound() const {
    return std::numeric_limits<double>::infinity();
  }
  /// The motion as a Fourier series, when it is one: then its slips on affine friction pieces
  /// (transition regions) are closed-form too (DrivenAffineArc, simulate/arc.hpp).
  virtual const FourierProfile* fourier_series() const { return nullptr; }
};

/// Table position, velocity and acceleration at one time [-].
struct TableState {
  double y;    ///< table position y [-]
  double yd;   ///< table velocity y' [-]
  double ydd;  ///< table acceleration y'' [-] (right limit at a switch)
};

/// A periodic table motion profile (open set: implement it for new profile families).
class TableProfile {
 public:
  virtual ~TableProfile() = default;

  /// Period Δt [-], > 0.
  virtual double period() const = 0;
  /// y, y', y'' at time t [-], any real t (periodic extension). y'' is right-continuous.
  virtual TableState state(double t) const = 0;
  /// y'(t) alone; the time-stepping solver's hot path (override when cheaper than state()).
  virtual double velocity(double t) const { return state(t).yd; }
  /// sup over the period of |y''| [-]: the peak acceleration used by eq. (40).
  virtual double peak_acceleration() const = 0;
  /// Stroke Δy = max y - min y over a period [-].
  virtual double stroke() const = 0;
  /// Short family name ("three-phase", "fourier", ...), for summaries.
  virtual std::string kind() const = 0;
  /// The profile as a piecewise-polynomial acceleration of degree <= 1 (piecewise constant or
  /// piecewise linear in time), when it is one (then the exact event-driven solver applies);
  /// nullptr otherwise.
  virtual const PiecewisePolynomialProfile* piecewise_polynomial() const { return nullptr; }
  /// The profile as a smooth motion, when it is one (then the exact solver for smooth profiles
  /// applies on piecewise-constant friction levels); nullptr otherwise.
  virtual const SmoothMotion* smooth() const { return nullptr; }
  /// The profile as the paper's three-phase profile (Sect. 4.4.3), when it is one: the
  /// analytic Floquet matrix (eqs. 25-33) and the stick-position map (eq. 59) need its
  /// parameters. nullptr otherwise (a capability query: no caller casts a profile).
  virtual const ThreePhaseProfile* three_phase() const { return nullptr; }
};

}  // namespace selfalign
