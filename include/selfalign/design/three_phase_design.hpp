#pragma once
/// \file three_phase_design.hpp
/// Global optimum of the three-phase profile (Sect. 4.4.3, Sect. 5.2) under actuator limits.
///
/// Two free accelerations (a2, a3) = (y2'', y3''). Constraints:
///   a2, a3 <= y''_max (the peak |y''| is max(a2, a3); the first phase has y'' = 0);
///   physical: 1/a2 + 1/a3 <= Δt^2 / (8 Δy) (case 0 excluded; three_phase.hpp);
///   |y'| <= y'_max: the velocity is piecewise linear with extrema y'_ini and y'_ini - D
///   exactly (ThreePhaseSolution), so max(y'_ini, D - y'_ini) <= y'_max.
/// Method: a geometric grid over the feasible box (1/s_max, y''_max]^2 (s_max = Δt^2/(8 Δy)),
/// the exact steady state on every cell, then the best `polish` cells are polished by LN_COBYLA
/// (local_search.hpp). The objective is cheap and piecewise smooth, so the scan finds the
/// basin of the global optimum.

#include "selfalign/design/optimize.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

/// Objective and constraint state of one (a2, a3) under the limits.
struct ThreePhaseDesignPoint {
  bool physical = false;  ///< not case 0
  bool feasible = false;  ///< physical and within every limit (to 1e-10 relative)
  double f = 0, v_bar = 0;         ///< eq. (11), eq. (10) (physical only)
  double max_velocity = 0;         ///< max |y'| = max(y'_ini, D - y'_ini) [-]
};

/// Evaluates one point (a2, a3 > 0; limits validated by the caller) under `law`; with a finite
/// limits.max_jerk, of the jerk-limited profile at that jerk.
ThreePhaseDesignPoint evaluate_three_phase(const ActuatorLimits& limits, double a2, double a3,
                                           const FrictionLaw& law = {});

/// Scan + polish. parameters = (a2, a3). Throws InvalidParameter on misuse.
OptimizationResult optimize_three_phase(const ActuatorLimits& limits,
                                        const OptimizeOptions& options = {});

/// The three-phase optimum the richer families start from: `given` when it is feasible (e.g.
/// compare_families' first row), else optimize_three_phase without progress reports, whose
/// evaluations are added to `evaluations`.
OptimizationResult three_phase_seed(const ActuatorLimits& limits, const OptimizeOptions& options,
                                    const OptimizationResult* given, int& evaluations);

}  // namespace selfalign
