#pragma once
/// \file fourier_design.hpp
/// Optimum of the order-N Fourier profile (Sect. 4.4.2, Fig. 6) under actuator limits.
///
/// Design variables: the 2N coefficients (A_1..A_N, B_1..B_N) in [-1, 1]; they are rescaled by
/// a common factor so that the stroke is Δy exactly (the stroke is linear in the scale).
/// Constraints over the whole period, from the extrema of y, y' and y'' (a grid of 32 N points
/// per period, every near-extreme grid point refined by Newton on the next derivative; the
/// optimum is checked again with the profile's bisection-refined extrema):
///   max|y'| <= y'_max,  max|y''| <= y''_max.
///
/// Objective: f of the exact steady state of the scaled series itself. FourierProfile is a
/// SmoothMotion, so steady_state() uses the exact smooth solver (simulate/smooth_exact.hpp:
/// closed-form slip velocity x' = x'(t0) - (y' - y'(t0)) - sigma k m (t - t0), events
/// isolated by safe steps and found to machine precision), which makes f a smooth function of
/// the coefficients. (Time-stepping would not:
/// its O(h) error has an erratic constant, docs/time-stepping.md. The optimiser used to
/// evaluate f on an M = 256-segment piecewise-constant approximation instead, with an
/// O((Δt/M)^2) error in the table velocity; fourier_approximation below is that approximation.)
/// The profile is built by FourierProfile::with_extrema from the extrema the constraints
/// already needed, so each evaluation searches them once. Under a velocity-dependent law the
/// steady state is the slip integrator's (steady_state.hpp).
/// Optimiser: LD_SLSQP with central finite-difference gradients (OptimizeOptions::fd_step),
/// deterministic multi-start: the Lanczos-smoothed Fourier series of the three-phase optimum,
/// then seeded random starts with coefficients decaying as 1/k^2.

#include <memory>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/design/optimize.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The M-segment piecewise-constant approximation of any profile: nodes t_i = i Δt / M,
/// accelerations a_i = (y'(t_{i+1}) - y'(t_i)) / (t_{i+1} - t_i), so its table velocity is the
/// piecewise-linear interpolant of y', exact at the nodes (its mean is the trapezoid rule of
/// y', exact for a trigonometric polynomial of order N < M), with an O((Δt/M)^2) error in
/// between. No longer the optimiser's objective (see above); kept as an independent
/// check of the smooth solver and for profiles without one. segments >= 2; throws
/// InvalidParameter otherwise.
PiecewisePolynomialProfile fourier_approximation(const TableProfile& profile, int segments);

/// Steady state of the M-segment approximation (exact piecewise solver).
SteadyState approximate_steady_state(const TableProfile& profile, int segments);

/// max |y'| over the period of a Fourier profile (bisection-refined extrema).
double max_abs_velocity(const FourierProfile& profile);

/// Fourier coefficients (A, B) of order `order` of a piecewise-constant profile's y, with
/// Lanczos sigma factors to damp the Gibbs overshoot of y''.
void fourier_series_of(const PiecewisePolynomialProfile& profile, int order,
                       std::vector<double>& cos_coeffs, std::vector<double>& sin_coeffs);

/// Optimises order N = options.order. When three_phase_start is given and feasible it seeds
/// one start (else the three-phase optimum is computed first).
OptimizationResult optimize_fourier(const ActuatorLimits& limits,
                                    const OptimizeOptions& options = {},
                                    const OptimizationResult* three_phase_start = nullptr);

}  // namespace selfalign
