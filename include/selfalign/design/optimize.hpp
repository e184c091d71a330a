#pragma once
/// \file optimize.hpp
/// Constrained design of the table motion profile (Sect. 4.4.2, taken further): the actuator
/// limits, the options and result shared by every profile family, the rebuild of an optimum
/// as a TableProfile, and the one table that compares the families.
///
/// Everything is dimensionless (Sect. 3.2). Objective: f = 1/(c v̄^2) of eq. (11) of the
/// steady state on the uniform table (steady_state()), minimised, i.e. v̄ > 0 maximised.
/// Limits (Sect. 4.4.2): period Δt and stroke Δy exactly, |y'| <= y'_max and |y''| <= y''_max
/// over the whole period; zero mean velocity and acceleration hold for every periodic profile.
/// Family optimisers: design/three_phase_design.hpp, design/piecewise_design.hpp,
/// design/fourier_design.hpp; all share the multi-start driver of design/local_search.hpp.

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

/// What the actuator can do (Sect. 4.4.2; Fig. 6: Δt = 0.072, Δy = 0.021, y'_max = 3.2,
/// y''_max = 1275).
struct ActuatorLimits {
  double period = 0.072;             ///< Δt [-], > 0 (exact)
  double stroke = 0.021;             ///< Δy = max y - min y [-], > 0 (exact)
  double max_velocity = 3.2;         ///< y'_max: |y'| <= y'_max over the period [-], > 0
  double max_acceleration = 1275.0;  ///< y''_max: |y''| <= y''_max over the period [-], > 0
  /// Jerk limit |d3y/dt3| <= j_max [-], > 0; +inf (default): none. The three-phase family then
  /// uses the jerk-limited profile (ramps at j_max); the piecewise-constant family, whose
  /// accelerations jump, is infeasible; a Fourier optimum is checked against it.
  double max_jerk = std::numeric_limits<double>::infinity();
};

/// Throws InvalidParameter unless every limit is in [1e-50, 1e50] (error.hpp, kMaxMagnitude).
void validate(const ActuatorLimits& limits);

/// Options of the family optimisers (each uses the fields that apply to it).
struct OptimizeOptions {
  int order = 12;            ///< Fourier order N, in [1, 100]
  int segments = 4;          ///< K of the piecewise-constant family, in [2, 64]
  int starts = 8;            ///< multi-starts of the local optimiser, in [1, 1000]
  int max_evaluations = 3000;  ///< objective evaluations per local run, in [1, 1e6]
  int grid = 48;             ///< three-phase scan: grid points per acceleration axis, [2, 2000]
  int polish = 3;            ///< three-phase: best scan cells polished locally, [1, 1000]
  unsigned seed = 1;         ///< seed of the deterministic random starts
  /// Relative central finite-difference step of the gradient-based (Fourier) optimiser:
  /// h_i = fd_step * max(|x_i|, max_j |x_j|), > 0.
  double fd_step = 1e-6;
  /// Worker threads of the Fourier optimiser's finite-difference stencils, >= 0 (0: all
  /// cores). The result does not depend on it: every stencil point is warm-started from its
  /// centre, whatever thread evaluates it.
  int threads = 0;
  /// The friction law every steady state is computed under (the paper's by default).
  FrictionLaw law;
  /// Called after each local run as progress(done, total); may be empty.
  std::function<void(int done, int total)> progress;
};

/// Throws InvalidParameter on any option outside its documented range.
void validate(const OptimizeOptions& options);

/// An optimum (or the report that none was found). Expected outcomes are values: an
/// optimiser that found nothing feasible returns feasible = false with a message naming the
/// binding limit.
struct OptimizationResult {
  bool feasible = false;
  double f = 0;          ///< objective f of eq. (11) at the optimum [-] (feasible only)
  double v_bar = 0;      ///< steady-state average velocity v̄ [-] (feasible only)
  std::string family;    ///< "three-phase", "piecewise-constant" or "fourier"
  /// The optimum's parameters (see the family's header): three-phase (a2, a3); piecewise
  /// constant (d_1..d_K, a_1..a_K); Fourier (A_1..A_N, B_1..B_N). Stroke already exact.
  std::vector<double> parameters;
  ActuatorLimits limits;  ///< the limits it was optimised for
  double max_velocity = 0;      ///< max |y'| over the period of the optimum [-]
  double max_acceleration = 0;  ///< max |y''| over the period of the optimum [-]
  /// max |d3y/dt3| of the optimum [-]: +inf where the acceleration jumps; the Fourier family's is
  /// the largest of 64 N samples.
  double max_jerk = std::numeric_limits<double>::infinity();
  int evaluations = 0;    ///< objective evaluations in all (scan, starts, gradients)
  int starts = 0;         ///< local runs
  std::string message;    ///< what happened, or the binding limit when infeasible
};

/// Rebuilds the optimal profile from a feasible result. Throws InvalidParameter when the
/// result is infeasible or its family is unknown.
std::unique_ptr<TableProfile> rebuild_profile(const OptimizationResult& result);

/// One row per family: three-phase, piecewise-constant (K = options.segments, started from
/// the three-phase optimum) and Fourier (order options.order).
std::vector<OptimizationResult> compare_families(const ActuatorLimits& limits,
                                                 const OptimizeOptions& options = {});

}  // namespace selfalign
