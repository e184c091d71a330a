#pragma once
/// \file slip_integrator.hpp
/// Event-driven solution of eq. (6) under a velocity-dependent friction law (Stribeck decay,
/// viscous term: friction_law.hpp), which has no closed-form slip arcs.
///
/// Sticking stays set-valued and exact: while x' = 0 the object sticks as long as
/// |y''| <= s m(x), with x and x' = 0 held exactly (no regularisation, no creep), and the stick
/// ends at the closed-form or bound-isolated time where y'' leaves the static bound (segments
/// of a piecewise-polynomial profile: closed form; smooth motions: the safe steps of
/// smooth_exact.hpp). Only the slip arcs are integrated:
///   x' = v,   v' = -sigma mu_sigma(|v|) m(x) - c v - y''(t),   sigma fixed on the arc,
/// with Boost.Odeint's Dormand-Prince 5(4) stepper (runge_kutta_dopri5) under its standard
/// error control (per step: |err_i| <= abs + rel (|x_i| + dt |x_i'|)) and its 4th-order dense
/// output. Why that stepper: it is the one error-controlled Runge-Kutta method of Odeint with
/// dense output (events are located on the interpolant, not by shortening steps), the method
/// is the de-facto standard for non-stiff problems (MATLAB ode45, SciPy RK45), and Odeint is
/// header-only in Debian's libboost-dev. Its global error is, empirically and by the usual
/// tolerance proportionality of such controllers, about proportional to the tolerance
/// (docs/slip-integrator.md, tested over three decades).
///
/// The right-hand side is kept smooth on every integration window: the table acceleration of
/// the current segment is extended past its end, the friction piece's affine level past its
/// ends, so the dense output is accurate up to each event, which is then located on it:
///   - x' = 0 (velocity_zero): sigma x' sampled at 4 points of every step, the first sign
///     change bracketed and refined by TOMS 748 (Boost.Math) to 4 roundings of t;
///   - x crossing a friction-piece boundary (friction_boundary): likewise on sigma (x - X);
///   - a segment end of the table acceleration: the window ends there and the slip restarts
///     with the next segment's acceleration (the event time does not depend on the state).
/// A velocity zero is then placed more precisely: the step that holds it has stages past it,
/// where a Stribeck law's mu(|x'|) has a kink, so its interpolant is no better than that kink
/// allows. The slip is integrated again from the step's start by a controlled dopri5 whose
/// steps end at the located time, and the time is corrected by Newton on x'(t) = 0 from the
/// accurate state there, until the correction is below the resolution of t (issue 20, F06:
/// results no longer depend on whether output samples shorten the steps).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/arc.hpp"
#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

/// The integrator's tolerances (Odeint's abs_error, rel_error of the dense-output dopri5).
struct IntegratorOptions {
  double relative_tolerance = 1e-10;  ///< in (0, 1)
  double absolute_tolerance = 1e-12;  ///< in (0, 1) [-]
  /// Work budget: Runge-Kutta step attempts (accepted or rejected), and stick/slip intervals,
  /// per table period of a call's horizon (at least one period), in [1, 1e9]. A non-stiff slip
  /// at rtol 1e-12 takes ~1e3 steps per period; a viscous rate c needs ~c Δt / 3.3 explicit
  /// steps (stability). Beyond it advance_integrated throws InvalidParameter naming the likely
  /// cause: "viscous" or "stribeck_velocity" for a stiff slip, else "relative_tolerance".
  double max_steps_per_period = 1e6;
};

/// Throws InvalidParameter naming "relative_tolerance", "absolute_tolerance" or
/// "max_steps_per_period" unless each is in its range.
void validate(const IntegratorOptions& options);

/// What the integrator did, for the results' provenance.
struct IntegratorStatistics {
  long long steps = 0;             ///< accepted Runge-Kutta steps
  long long rejected = 0;          ///< rejected (retried) steps
  long long rhs_evaluations = 0;   ///< right-hand-side evaluations
  long long events = 0;            ///< located events: x' = 0, boundaries, stick breaks
  long long slips = 0, sticks = 0; ///< intervals integrated / held
  long long pivots = 0;            ///< pivots (the planar patch integrator only)

  IntegratorStatistics& operator+=(const IntegratorStatistics& o) noexcept;
  IntegratorStatistics& operator-=(const IntegratorStatistics& o) noexcept;
};


/// What the integrator solves: a profile (piecewise polynomial or smooth; borrowed), a
/// piecewise-affine friction level (borrowed), a law (any; velocity-dependent is its purpose)
/// and the tolerances.
struct IntegratorSetup {
  const TableProfile& profile;
  const PiecewiseAffineFriction& friction;
  FrictionLaw law{};
  IntegratorOptions options{};
};

/// True when the integrator can take this profile: it is piecewise polynomial or smooth.
bool integrable_profile(const TableProfile& profile) noexcept;

/// Advances `state` to t_end (>= state.t), calling observer->on_motion (if any) for every stick
/// or slip interval (no closed form: arc = nullptr) and adding to stats (if any). Returns the
/// number of intervals. With an observer, every crossing of a position in `watch` (sorted
/// ascending) by a slip is reported to observer->on_crossing, located on the dense output like
/// the other events (stopping runs time their targets so). Throws InvalidParameter for a profile that is neither piecewise
/// polynomial nor smooth, bad options, a non-finite state or t_end, an unsorted watch; and
/// when the work budget (options.max_steps_per_period) is spent or the state leaves the finite
/// numbers (a stiff slip), naming "viscous", "stribeck_velocity" or "relative_tolerance".
std::size_t advance_integrated(const IntegratorSetup& setup, ObjectState& state, double t_end,
                               MotionObserver* observer = nullptr,
                               IntegratorStatistics* stats = nullptr,
                               std::span<const double> watch = {});

}  // namespace selfalign
