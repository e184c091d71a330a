#pragma once
/// \file arc.hpp
/// One closed-form piece of the exact solution: between two events the table acceleration A,
/// the slip direction sigma and the friction piece m(x) = m0 + k (x - x_b) are fixed, and
/// eq. (6) with the map of eqs. (7)-(9) reads   x'' = -sigma m(x) - A,   an ODE with constant
/// coefficients:
///   k = 0           parabolic arc, x'' = alpha                          (eqs. 12-24)
///   -sigma k < 0    harmonic arc,  x'' = -omega^2 (x - x_e)             (eqs. 42-47)
///   -sigma k > 0    hyperbolic arc, x'' = +omega^2 (x - x_e)  (backward slip on rising friction)
///   stick           x' = 0, x constant (|A| <= m(x))

#include <cstddef>
#include <cstdint>

#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

enum class ArcKind : std::uint8_t { stick, parabolic, harmonic, hyperbolic };

/// What ended an arc.
enum class ArcEnd : std::uint8_t {
  acceleration_switch,  ///< the table acceleration changed (segment end)
  velocity_zero,        ///< x' reached 0 (the stick/slip decision follows)
  friction_boundary,    ///< x reached the end of a friction piece (e.g. x_mu or x_mu + w)
  horizon               ///< the requested end time
};

struct Arc {
  double t0 = 0, t1 = 0;    ///< start and end time [-]
  double x0 = 0, xd0 = 0;   ///< state at t0 [-]
  double x1 = 0, xd1 = 0;   ///< state at t1 [-]
  double table_accel = 0;   ///< table acceleration A = y'' on the arc [-]
  double bound0 = 0;        ///< friction bound m(x0) [-]
  double slope = 0;         ///< friction slope k = dm/dx on the arc's piece [-]
  double alpha = 0;         ///< parabolic: x'' [-]
  double omega = 0;         ///< harmonic / hyperbolic: omega [-]
  double center = 0;        ///< harmonic / hyperbolic: x_e [-]
  ArcKind kind = ArcKind::stick;
  std::int8_t direction = 0;  ///< slip direction sigma: +1, -1, or 0 for stick
  ArcEnd end = ArcEnd::horizon;
  std::size_t segment = 0;  ///< index of the table-acceleration segment
  std::size_t piece = 0;    ///< index of the friction piece

  /// The closed-form state at time t in [t0, t1].
  ObjectState at(double t) const noexcept;
};

}  // namespace selfalign
