#pragma once
/// \file convergence.hpp
/// Convergence of two velocity responses (Sect. 6.2, Fig. 13).
///
/// Two trajectories v1 = x'_1, v2 = x'_2 of the same table motion (uniform friction) from
/// different initial velocities, and the Lyapunov function of eq. (35), V = (v1 - v2)^2 / 2.
/// By eq. (36), V' = -(v1 - v2)(v̂1 - v̂2) with v̂i ∈ Sign(vi) the friction force actually
/// selected: V is constant where v̂1 = v̂2 (both slipping the same way) and decreases where
/// v̂1 ≠ v̂2 (opposite slips, or one sticking while the other slips). Once both stick at the
/// same time the responses coincide for good (cases 1-3, 5); slip-slip (case 4) converges
/// only as t -> infinity.

#include <optional>
#include <vector>

#include "selfalign/profiles/table_profile.hpp"

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/simulate/slip_integrator.hpp"

namespace selfalign {

/// A maximal time interval on which the selected friction forces are equal (v̂1 = v̂2, the
/// paper's '=' intervals) or not ('≠').
struct SignInterval {
  double t_begin = 0, t_end = 0;  ///< [-]
  bool same = false;              ///< true: v̂1 = v̂2 ('='); false: '≠'
};

struct VelocityConvergence {
  /// Samples: a uniform grid plus every event of either trajectory [-].
  std::vector<double> t, v1, v2, lyapunov;  ///< time, x'_1, x'_2, V = (v1 - v2)^2/2
  std::vector<SignInterval> intervals;      ///< '=' and '≠' intervals covering [t0, t0 + duration]
  /// First time from which v1 = v2 for good (both stuck together); empty if not reached.
  std::optional<double> t_coincide;
};

struct ConvergenceOptions {
  double v1 = 0.5;               ///< initial velocity of trajectory 1 [-], |v1| <= 1e50
  double v2 = -0.5;              ///< initial velocity of trajectory 2 [-], |v2| <= 1e50
  double t0 = 0;                 ///< common start time [-]
  double duration = 10;          ///< simulated time [-], in [1e-9 Δt, 1e6 Δt]; |t0| <= 1e8 Δt
  int samples_per_period = 200;  ///< uniform samples per table period, in [1, 1e6]; at most
                                 ///< 1e7 samples over the run
  IntegratorOptions integrator{};  ///< slip integrator's tolerances (Stribeck, viscous laws)
};

/// Runs both trajectories with the exact solver (the profile must be piecewise constant).
/// Throws InvalidParameter otherwise or on bad options. Under a speed-dependent law (Stribeck,
/// viscous) the slip integrator runs them: the '=' / '≠' intervals come from its stick and slip
/// intervals, the velocities from a second run of each response that stops at every sample
/// time (its events agree with the first run's to the integrator's tolerance).
VelocityConvergence velocity_convergence(const TableProfile& profile,
                                         const ConvergenceOptions& options = {});
/// The same under `law` (static >= kinetic, direction-dependent kinetic; any
/// piecewise-polynomial profile, finite jerk included).
VelocityConvergence velocity_convergence(const TableProfile& profile, const FrictionLaw& law,
                                         const ConvergenceOptions& options = {});

}  // namespace selfalign
