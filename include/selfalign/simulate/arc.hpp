#pragma once
/// \file arc.hpp
/// One closed-form piece of the exact solution. Between two events the table acceleration is
/// affine in time, A(tau) = A0 + J tau (J = 0 for the paper's profiles), the motion is either
/// stick or slip in one direction sigma, and the friction level is one affine piece
/// m(x) = m0 + k (x - x0) of the table's field averaged over the object's footprint. With the
/// Coulomb law (friction_law.hpp) eq. (6) then reads
///   slip:   x'' = -sigma k_sigma m(x) - A0 - J tau          (a linear ODE, constant coefficients)
///   stick:  x' = 0, x constant, while |A0 + J tau| <= s m(x)
/// and its solution is one of a closed set of shapes, an ArcShape:
///   StickArc        x constant
///   PolynomialArc   k = 0:  x'' = a + b tau (parabolic for b = 0: eqs. 12-24; cubic in x with
///                   finite jerk)
///   HarmonicArc     kappa = sigma k_sigma k > 0: x'' = -omega^2 (x - c - d tau)  (eqs. 42-47;
///                   d = 0 for constant A: the drift of the centre comes from the jerk)
///   HyperbolicArc   kappa < 0: x'' = +omega^2 (x - c - d tau) (slip against rising friction)
/// Each shape supplies its state at tau, its acceleration and its state-transition matrix; the
/// exact solver, the saltation-matrix Floquet method and every analysis use these through
/// std::visit, never through a switch on a kind.

#include <cstddef>
#include <cstdint>
#include <variant>

#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/motion_observer.hpp"
#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

class FourierProfile;

/// Position and velocity relative to the table [-].
struct PosVel {
  double x, xd;
};

/// The 2x2 state-transition matrix d(x, x')(t1) / d(x, x')(t0) of one arc, row-major.
struct Transition {
  double xx = 1, xv = 0, vx = 0, vv = 1;
};

/// The object sticks to the table: x' = 0, x constant.
struct StickArc {
  PosVel state(double x0, double, double) const noexcept { return {x0, 0.0}; }
  double acceleration(double, double, double) const noexcept { return 0.0; }
  /// A stuck object forgets a velocity perturbation.
  Transition transition(double) const noexcept { return {1, 0, 0, 0}; }
};

/// Slip on a constant friction piece: x'' = accel + jerk tau (eqs. 15-20; cubic for jerk != 0).
struct PolynomialArc {
  double accel = 0;  ///< x'' at the arc's start [-]
  double jerk = 0;   ///< x''' on the arc (= -J, the table's jerk reversed) [-]

  PosVel state(double x0, double v0, double tau) const noexcept {
    if (jerk == 0) return {x0 + tau * (v0 + 0.5 * accel * tau), v0 + accel * tau};
    return {x0 + tau * (v0 + tau * (0.5 * accel + tau * jerk / 6.0)),
            v0 + tau * (accel + 0.5 * jerk * tau)};
  }
  double acceleration(double, double, double tau) const noexcept { return accel + jerk * tau; }
  Transition transition(double tau) const noexcept { return {1, tau, 0, 1}; }
};

/// Slip on falling friction (or forward on rising friction): x'' = -omega^2 (x - c(tau)),
/// c(tau) = center + drift tau (eqs. 43-47 for drift = 0).
struct HarmonicArc {
  double omega = 1;   ///< [-], > 0
  double center = 0;  ///< c(0) [-]
  double drift = 0;   ///< dc/dtau [-]; nonzero only under finite jerk

  PosVel state(double x0, double v0, double tau) const noexcept;
  double acceleration(double x, double, double tau) const noexcept {
    return -omega * omega * (x - center - drift * tau);
  }
  Transition transition(double tau) const noexcept;
};

/// Slip against rising friction: x'' = +omega^2 (x - c(tau)), c(tau) = center + drift tau.
struct HyperbolicArc {
  double omega = 1;
  double center = 0;
  double drift = 0;

  PosVel state(double x0, double v0, double tau) const noexcept;
  double acceleration(double x, double, double tau) const noexcept {
    return omega * omega * (x - center - drift * tau);
  }
  Transition transition(double tau) const noexcept;
};

/// Slip on a constant friction level under a smooth table motion (profiles/table_profile.hpp,
/// SmoothMotion): x'' = accel - y''(t), in closed form for any motion with y, y' known:
///   x' = x'0 - (y'(t0 + tau) - y'0) + accel tau
///   x  = x0 + x'0 tau - (y(t0 + tau) - y0 - y'0 tau) + accel tau^2 / 2.
struct DrivenArc {
  const SmoothMotion* motion = nullptr;  ///< the table motion (borrowed)
  double t0 = 0;                         ///< absolute start time, the motion's clock [-]
  double y0 = 0, yd0 = 0;                ///< y, y' at t0 [-]
  double accel = 0;                      ///< friction's part of x'': -sigma k m [-]

  PosVel state(double x0, double v0, double tau) const noexcept {
    const auto d = motion->derivatives(t0 + tau);
    return {x0 + v0 * tau - (d[0] - y0 - yd0 * tau) + 0.5 * accel * tau * tau,
            v0 - (d[1] - yd0) + accel * tau};
  }
  double acceleration(double, double, double tau) const noexcept {
    return accel - motion->derivatives(t0 + tau)[2];
  }
  Transition transition(double tau) const noexcept { return {1, tau, 0, 1}; }
};

/// Slip on an affine friction piece (a transition region) under a Fourier table motion:
///   x'' = -kappa (x - center) - y''(t),   kappa = sigma k_sigma dm/dx,  m(center) = 0,
/// in closed form harmonic by harmonic (docs/fourier-transition-region.md, eqs. F1-F8): with
/// u = x - center, the homogeneous part (cos/sin of omega tau for kappa = omega^2 > 0,
/// cosh/sinh of lambda tau for kappa = -lambda^2 < 0) plus, for every harmonic Omega_j = j w of
/// -y'' = sum Omega_j^2 (A_j cos + B_j sin), its zero-state response written with
/// sinc((Omega_j - omega) tau / 2): exact and free of cancellation at and near resonance
/// (Omega_j = omega).
struct DrivenAffineArc {
  const FourierProfile* series = nullptr;  ///< the table motion (borrowed)
  double t0 = 0;                           ///< absolute start time [-]
  double kappa = 1;                        ///< sigma k_sigma dm/dx [-], != 0
  double center = 0;                       ///< where the piece's level extrapolates to 0 [-]

  PosVel state(double x0, double v0, double tau) const noexcept;
  double acceleration(double x, double, double tau) const noexcept;
  Transition transition(double tau) const noexcept;
};

/// The closed set of arc shapes. Add a shape here (with state, acceleration, transition and
/// its events in src/simulate/arc_events.hpp) and every visitor must handle it.
using ArcShape =
    std::variant<StickArc, PolynomialArc, HarmonicArc, HyperbolicArc, DrivenArc, DrivenAffineArc>;

/// The shape's index, for tables and bindings (ArcKind(shape.index())).
enum class ArcKind : std::uint8_t { stick, parabolic, harmonic, hyperbolic, driven, driven_affine };

/// One piece of the motion (t0, t1, states, direction, end: motion_observer.hpp) with its
/// closed form.
struct Arc : MotionInterval {
  double table_accel = 0;   ///< table acceleration A = y'' at t0 [-]
  double table_jerk = 0;    ///< table jerk J = y''' on the arc [-]
  double bound0 = 0;        ///< friction level m(x0) of the field over the footprint [-]
  double slope = 0;         ///< dm/dx on the arc's friction piece [-]
  ArcShape shape;           ///< the closed-form solution
  std::size_t segment = 0;  ///< index of the table-acceleration segment
  std::size_t piece = 0;    ///< index of the friction piece

  ArcKind kind() const noexcept { return static_cast<ArcKind>(shape.index()); }
  /// The closed-form state at time t in [t0, t1].
  ObjectState at(double t) const noexcept;
  /// x'' at the arc's start (right limit) and end (left limit), from (x0, xd0) and (x1, xd1).
  double start_acceleration() const noexcept;
  double end_acceleration() const noexcept;
  /// State-transition matrix over [t0, t1].
  Transition transition() const noexcept;
};

}  // namespace selfalign
