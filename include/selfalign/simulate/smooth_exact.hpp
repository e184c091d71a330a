#pragma once
/// \file smooth_exact.hpp
/// Exact event-driven solution of eq. (6) for smooth table motions (Fourier series of any
/// order, or any profile that is a SmoothMotion) on piecewise-constant friction levels, under a
/// Coulomb law with static >= kinetic coefficients.
///
/// On a constant level m the slip velocity is closed-form for any motion with y' known:
///   x'(t) = x'(t0) - (y'(t) - y'(t0)) - sigma k_sigma m (t - t0)          (DrivenArc, arc.hpp)
/// and x(t) needs only y(t). The events are roots of these closed forms, isolated so that none
/// is missed:
///   - x' = 0: while slipping, g = sigma x' > 0 and |g''| = |y'''| <= Y3 (the motion's jerk
///     bound), so g(t + d) >= g + g' d - Y3 d^2 / 2. The solver steps by the largest d keeping
///     that lower bound >= 0: it never steps over a zero of x', and near a simple zero the
///     steps converge quadratically (d ~ g/|g'|). A zero is declared when the step falls below
///     1e-15 of the time;
///   - stick breaking: while stuck, s m - y'' >= 0 and s m + y'' >= 0, each with a bound on its
///     second derivative |y''''| <= Y4: the same safe steps on both;
///   - longer steps, checked a posteriori (a motion with a fifth-derivative bound Y5, such as a
///     Fourier series): on a constant level g'''' = -sigma y^(5), so the cubic Hermite
///     interpolant of g from both ends of a step of length L is within Y5 L^4 / 384 of g; a
///     step whose interpolant's minimum clears that has no zero of x'. L is grown after a
///     success, halved after a failure, and kept where that bound stays below g/4;
///   - friction-level boundaries: x is monotone while slipping, so the first step that passes a
///     boundary brackets its only crossing, found by safeguarded Newton steps.
/// Affine pieces (the transition region) under a Fourier motion are closed-form too: the
/// slip is a DrivenAffineArc (arc.hpp; docs/fourier-transition-region.md), its events isolated
/// by the same safe steps with the bound of eq. (F9). Other smooth motions on sloped pieces
/// are refused here (PeriodMap and simulate() give them to the slip integrator).

#include <cstddef>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {

/// What the smooth solver integrates: a smooth motion (borrowed) on a piecewise-constant level
/// (borrowed) under a law.
struct SmoothSetup {
  const SmoothMotion& motion;
  const PiecewiseAffineFriction& friction;
  FrictionLaw law{};
};

/// True when every piece of the level has slope 0 (any smooth motion then; with slopes, Fourier
/// motions only).
bool piecewise_constant_level(const PiecewiseAffineFriction& friction) noexcept;

/// True when the smooth solver takes this motion on this level: a piecewise-constant level
/// (any smooth motion), or any piecewise-affine level under a Fourier series.
bool smooth_solver_applies(const SmoothMotion& motion,
                           const PiecewiseAffineFriction& friction) noexcept;

/// Advances `state` to t_end (>= state.t), calling observer->on_motion(arc, &arc) (if any) for
/// every arc (DrivenArc for
/// slips on constant pieces, DrivenAffineArc on sloped ones, StickArc for sticks). Returns the
/// number of arcs. Throws InvalidParameter for a level with sloped pieces under a motion that
/// is not a Fourier series, a non-finite state or t_end.
std::size_t advance_smooth(const SmoothSetup& setup, ObjectState& state, double t_end,
                           MotionObserver* observer = nullptr);

}  // namespace selfalign
