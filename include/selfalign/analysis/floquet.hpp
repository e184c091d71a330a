#pragma once
/// \file floquet.hpp
/// Floquet multipliers of the steady state on the uniform table, three ways (Sect. 6.1):
///  1. analytic — the linearised period map of eqs. (25)-(33): Φ = [[1, m12], [0, 0]] for every
///     response that sticks (cases 1, 2, 3, 5; eq. 30, where m12 = 0 when x'_0s = 0) and
///     Φ = [[1, m12], [0, λ2]] for slip-slip (case 4; eq. 33) with
///     λ2 = c4 = (y2''-1)(y3''-1) / ((y2''+1)(y3''+1)); m12 = d x(t3)/d x'_0s from the event
///     times of the closed-form steady solution;
///  2. saltation — the monodromy matrix built from the fundamental solution of every arc of a
///     steady period, coupled by saltation matrices at the state events (Leine & Nijmeijer):
///        x' = 0 with reversal:   S = diag(1, a+/a-)   (a-: x'' before, a+: x'' after)
///        x' = 0 into stick:      S = diag(1, 0)        (stick arcs carry diag(1, 0) too)
///        friction boundary x=X:  S = [[1, 0], [(a+ - a-)/x', 1]]
///        acceleration switches:  S = I (time events)
///  3. finite difference — central differences of the exact period map.
/// The multiplier 1 belongs to the freedom in position (eigenvector [1, 0]).

#include <array>
#include <complex>

#include <Eigen/Core>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

class PeriodMap;

/// A monodromy matrix Φ(t0 + Δt, t0) acting on (Δx, Δx') and its eigenvalues.
struct Monodromy {
  Eigen::Matrix2d matrix = Eigen::Matrix2d::Identity();
  /// Floquet multipliers, largest modulus first.
  std::array<std::complex<double>, 2> multipliers{};
  bool available = false;  ///< false where the method does not apply (analytic: non-three-phase)
};

/// Eigenvalues of a 2x2 matrix, largest modulus first (Eigen::EigenSolver).
Monodromy make_monodromy(const Eigen::Matrix2d& matrix);

struct FloquetOptions {
  double fd_step = 1e-7;  ///< finite-difference perturbation of x0 and x'_0s [-], in (0, 0.1]
  SteadyStateOptions steady;
};

struct FloquetAnalysis {
  SteadyState steady;            ///< the periodic solution analysed
  Monodromy analytic;            ///< eqs. (25)-(33) (three-phase profiles)
  Monodromy saltation;           ///< arcs + saltation matrices
  Monodromy finite_difference;   ///< central differences
  /// Largest distance between corresponding multipliers of the available methods [-].
  double spread = 0;
};

/// Floquet analysis of a profile whose acceleration is piecewise constant (exact solver).
/// Throws InvalidParameter for other profiles or bad options. The analytic matrix needs the
/// three-phase parameters: use the ThreePhaseProfile overload.
FloquetAnalysis floquet_multipliers(const TableProfile& profile, const FloquetOptions& options = {});
/// Saltation and finite differences on the uniform table under `law` (any piecewise-polynomial
/// profile, finite jerk included; the analytic matrix needs the paper's law and profile).
FloquetAnalysis floquet_multipliers(const TableProfile& profile, const FrictionLaw& law,
                                    const FloquetOptions& options = {});
/// Saltation and finite differences of a period map's steady state (exact maps only).
FloquetAnalysis floquet_multipliers(const PeriodMap& map, const FloquetOptions& options = {});
FloquetAnalysis floquet_multipliers(const ThreePhaseProfile& profile,
                                    const FloquetOptions& options = {});

/// λ2 of the slip-slip case, eq. (33): ((y2''-1)(y3''-1)) / ((y2''+1)(y3''+1)).
double slip_slip_multiplier(double a2, double a3);

}  // namespace selfalign
