#pragma once
/// \file steady_state.hpp
/// Steady state of the object on the uniform low-friction table (Sect. 4.3, 5.1, 6.2): the
/// periodic velocity response, its average velocity v̄ (eq. 10) and the objective f (eq. 11).
///
/// Sect. 6.2 proves the velocity response is unique, so it is found from any start as the
/// root of g(v) = P(v) - v, P the period map x'(t0 + Δt) given x'(t0) = v. P is nondecreasing
/// with slope λ < 1, so g decreases and two iterates with g of opposite signs bracket the
/// fixed point; P is piecewise affine for the paper's profiles (constant after a stick, slope
/// λ2 = c4 in slip-slip, eq. 32) with kinks where the event sequence changes. Steps: plain
/// iterates from rest, then Newton steps on the map's own slope dP/dv (the saltation product of
/// the period's arcs, exact maps) or secant steps (other maps), false position across the
/// bracket where the local slope is near 1 (a piece far from the fixed point), bisection where
/// a step leaves the bracket or stalls. The search stops at a fixed point in floating point (or, for a Newton
/// iterate, at the rounding floor of g), or when a bracket narrower than the tolerance holds
/// it: an estimate within tolerance is certified by evaluating its mirror image across the
/// estimated fixed point. x_dot_0s_error is then the bracket's width, a bound rather than a
/// residual over a slope that may have been taken across a kink (issue 20, F05). Exact solver
/// where the table acceleration is
/// piecewise constant or linear, or the profile is smooth (Fourier: simulate/smooth_exact.hpp);
/// time-stepping otherwise.

#include <limits>
#include <string>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign {

class PeriodMap;

/// The normalising constant c of eq. (11).
inline constexpr double kObjectiveScale = 10'000.0;

/// Objective f = 1/(c v̄^2) of eq. (11); +inf when v̄ = 0.
double objective_f(double v_bar, double c = kObjectiveScale);

struct SteadyStateOptions {
  int max_periods = 2000;        ///< periods simulated at most before giving up
  /// Bound on |x'_0s - v*| (the certifying bracket's width) accepted as steady, relative to
  /// 1 + |v| [-] (exact solver).
  double velocity_tol = 1e-13;
  /// Time-stepping (profiles the exact solver cannot take): h = Δt / steps_per_period.
  int steps_per_period = 4000;
  double theta = 0.5;            ///< time-stepping theta
  double stepping_tol = 0;       ///< time-stepping: velocity_tol's role [-]; 0: 10 h
  /// x'_0 of the search's first period [-] (0: from rest, the default). A nearby profile's
  /// x'_0s (an optimiser's finite-difference neighbours) saves periods: the search converges to
  /// the same fixed point where the steady state is unique.
  double initial_velocity = 0;
  /// g'(v) = λ - 1 of a nearby profile's period map (its SteadyState::slope), < 0; NaN (the
  /// default): unknown. With initial_velocity, the search's first step is then a secant step.
  double initial_slope = std::numeric_limits<double>::quiet_NaN();
  /// Slip integrator (velocity-dependent laws): its tolerances; velocity_tol is then raised to
  /// at least 10 relative_tolerance (the period map is no more accurate than that).
  IntegratorOptions integrator{};
};

struct SteadyState {
  bool converged = false;      ///< false: max_periods reached (fields hold the last iterate)
  Method method = Method::exact;
  double x_dot_0s = 0;         ///< steady-state x' at the profile's t0 (phase 0) [-]
  /// Bound on |x'_0s - v*| [-]: the width of the bracket that holds v* (g = P(v) - v changes
  /// sign across it), or at the rounding floor the residual |P(v) - v| over 1 - λ (λ the map's
  /// own slope at x'_0s); never below the map's rounding over 1 - λ; +inf when not converged.
  double x_dot_0s_error = 0;
  double phase = 0;            ///< phase of the steady-state initial condition in [0, Δt) [-]
  double v_bar = 0;            ///< average velocity over a steady period, eq. (10) [-]
  double f = 0;                ///< objective of eq. (11) [-]; +inf when v̄ = 0
  double displacement = 0;     ///< x(t0 + Δt) - x(t0) over a steady period [-]
  int periods = 0;             ///< periods simulated to find it
  /// A posteriori Table 1 case of the steady period: from the exact arcs, or from the
  /// time-stepping samples (stick where x' = 0 for two or more consecutive steps, slip by sign).
  StickSlipCase motion_case = StickSlipCase::pure_stick;
  /// The steady period's stick/slip sequence, cyclic and compressed (MotionCensus::pattern):
  /// e.g. "stick,forward,backward" (Table 1 case 3) or "forward,backward" (case 4).
  std::string pattern;
  /// The search's last estimate of g'(v) = λ - 1 at the fixed point (secant of its iterates, or
  /// the hint it started from); NaN when no slope was measured.
  double slope = std::numeric_limits<double>::quiet_NaN();
  /// The slip integrator's work for this steady state (method integrator; zeros otherwise).
  IntegratorStatistics integrator;
};

/// Steady state on the uniform table (friction level 1) under the paper's law. Throws
/// InvalidParameter on bad options.
SteadyState steady_state(const TableProfile& profile, const SteadyStateOptions& options = {});
/// Steady state on the uniform table under `law` (static >= kinetic, direction-dependent).
SteadyState steady_state(const TableProfile& profile, const FrictionLaw& law,
                         const SteadyStateOptions& options = {});
/// Steady state of any period map (its friction level should not vary along the path: the
/// steady state is of the velocity; x is started at 0). options.steps_per_period and theta are
/// the map's own.
SteadyState steady_state(const PeriodMap& map, const SteadyStateOptions& options = {});

}  // namespace selfalign
