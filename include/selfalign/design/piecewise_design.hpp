#pragma once
/// \file piecewise_design.hpp
/// Optimum of the K-segment piecewise-constant acceleration profile under actuator limits.
///
/// Design variables (2K, all in a box): weights w_i in [0, 1] (a zero weight drops its segment) and raw accelerations
/// b_i in [-1, 1]. They map to a profile by
///   d_i = Δt w_i / sum_j w_j                      (sum d_i = Δt exactly),
///   a_i = λ (b_i - sum_j b_j d_j / Δt)            (sum a_i d_i = 0: y' periodic),
///   λ > 0 such that the stroke is Δy exactly      (the stroke is linear in λ at fixed d).
/// Constraints: λ max|a_i| <= y''_max, and |y'| <= y'_max checked at the segment ends (y' is
/// piecewise linear, so its extrema are there): both exact.
/// The K family contains every (K-1)-segment profile (split one segment in two) and, for
/// K >= 3, the three-phase profile. So the K optimum is searched after the (K-1) optimum
/// (recursively down to K = 2, with the same options), and one start is that optimum with its
/// longest segment split; K = 3 also starts from the three-phase optimum. local_search keeps a
/// start nothing beats, so v̄(K) >= v̄(K-1) >= ... >= v̄(three-phase), up to the rounding of the
/// embedding (~1e-16 relative in the profile). The other starts are seeded random. Local
/// optimiser: LN_COBYLA. Cost: the chain's levels, about K/2 times one level's.

#include <span>
#include <vector>

#include "selfalign/design/optimize.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// Maps design variables (w_1..w_K, b_1..b_K) to durations and stroke-exact accelerations.
/// Returns false when the accelerations vanish (no stroke possible).
bool piecewise_design_profile(const ActuatorLimits& limits, std::span<const double> x,
                              std::vector<double>& durations, std::vector<double>& accels);

/// max |y'| over the period of a piecewise-constant profile: at its segment ends (exact).
double max_abs_velocity(const PiecewisePolynomialProfile& profile);

/// Optimises K = options.segments segments, after K - 1, ..., 2 (each started from the one
/// before); when three_phase_start is given and feasible, it is a start of K = 3 (else the
/// three-phase optimum is computed first). options.progress sees the whole chain.
OptimizationResult optimize_piecewise_constant(const ActuatorLimits& limits,
                                               const OptimizeOptions& options = {},
                                               const OptimizationResult* three_phase_start =
                                                   nullptr);

}  // namespace selfalign
