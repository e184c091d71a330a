#pragma once
/// \file stick_slip_decision.hpp
/// The stick/slip decision at a velocity zero: the one function every 1-D solver calls when
/// the object is at rest relative to the table (the exact solvers for piecewise-polynomial and
/// smooth motions, the slip integrator; time-stepping decides stick inside its set-valued
/// projection instead, time_stepping.hpp).
///
/// The set-valued law (2) at x' = 0: the object sticks iff the friction force needed to hold
/// it, |y''| (per unit mass and normal load), is within the static bound s m(x) (eqs. 3-5);
/// otherwise it slips against the table's push, in direction -sign(y'') (eqs. 15, 18).

namespace selfalign {

/// What the object at rest does next: 0 sticks, -1 slips backward, +1 slips forward.
///   table_accel   y'' at the instant [-]
///   static_bound  s m(x) >= 0 at the object's position [-]
///   breaking      the direction of a stick that just ended at a stick_break event (0: none).
///                 It decides: at the break |y''| equals the bound up to rounding, and the
///                 test below could answer "stick" again at the same instant.
///   stalled       the previous arc was a slip from rest that left t, x and x' unchanged (it
///                 lasted less than the resolution of t: t + tau == t). The object stays stuck
///                 until |y''| reaches the bound again; without this the decision and that slip
///                 would alternate forever at one instant (tests/test_finite_jerk.cpp,
///                 AStallingSlip...).
/// A NaN acceleration sticks (never a slip in a direction chosen by a NaN).
constexpr int decide_at_rest(double table_accel, double static_bound, int breaking = 0,
                             bool stalled = false) noexcept {
  if (breaking != 0) return breaking;
  if (stalled) return 0;
  if (table_accel > static_bound) return -1;
  if (-table_accel > static_bound) return 1;
  return 0;
}

}  // namespace selfalign
