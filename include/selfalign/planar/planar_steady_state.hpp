#pragma once
/// \file planar_steady_state.hpp
/// The planar steady state as a fixed point of the period map (issue 21), with the 1-D
/// criterion (analysis/steady_state.hpp) instead of a window average.
///
/// A steady planar motion repeats every table period up to a translation (and a rotation where
/// the part spins steadily): on a field that does not change under the part, the period map
/// P : (pose, twist) at phase 0 -> (pose, twist) one period later commutes with translations,
/// so its fixed point lives on the coordinates relative to the drift,
///   z = (u_x, u_y, omega at phase 0;  Δx, Δy, Δangle over the period),
/// and the search iterates P until z stops changing. With the residual e_n = |z_n - z_(n-1)|
/// (max norm, displacements per unit time) and the contraction λ = e_n / e_(n-1) < 1 the error
/// estimate is e_n λ / (1 - λ); the search stops when e_n and that estimate are both within
/// tolerance (1 + |z|), or at e_n = 0 (a stick resets the twist exactly: the fixed point is
/// reached in finitely many periods, as in 1-D cases 1-3 and 5).
///
/// Stepper: the exact event-driven point solver (planar_exact_point.hpp) where it applies (a
/// point part at its centre, a uniform field, a translating table with piecewise-constant
/// accelerations): the result is then exact to the tolerance 1e-13 of the 1-D exact search.
/// Otherwise the rigid part's Moreau stepper (planar_rigid.hpp), tolerance 10 h as the 1-D
/// time-stepping search.
///
/// The friction level under the part (the load-weighted field at the contact points) is
/// tracked over the whole run: where it changes while the fixed point is sought (the part
/// walked into another region of the field, e.g. a pocket), there is no steady drift at the
/// start and the result says so (level_changed; converged only once the level holds again,
/// and then the steady state is the one in the new region, typically at rest).

#include <limits>

#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/simulate/method.hpp"

namespace selfalign {

struct PlanarSteadyStateOptions {
  int max_periods = 2000;      ///< periods simulated at most, in [1, 1e6]
  int transient_periods = 0;   ///< periods run before the search starts, in [0, 1e5]
  /// Accepted |z_n - z_(n-1)| and error estimate, relative to 1 + |z| [-]; 0 (the default):
  /// 1e-13 for the exact point solver, 10 h for Moreau (the 1-D search's velocity_tol and
  /// stepping_tol).
  double tolerance = 0;
};

struct PlanarSteadyState {
  bool converged = false;  ///< false: max_periods reached, or the level under the part changing
  /// The friction level under the part changed during the run (it met another region of the
  /// field): the drift found, if any, is the steady state where it ended, not where it began.
  bool level_changed = false;
  Method method = Method::exact;  ///< exact (point solver) or time_stepping (Moreau)
  int periods = 0;                ///< periods simulated
  double drift_x = std::numeric_limits<double>::quiet_NaN();  ///< Δx / Δt, table frame [-]
  double drift_y = std::numeric_limits<double>::quiet_NaN();  ///< Δy / Δt [-]
  double rotation_rate = std::numeric_limits<double>::quiet_NaN();  ///< Δangle / Δt [-]
  PlanarTwist twist_0s;           ///< the twist at phase 0 of the last period [-]
  double residual = std::numeric_limits<double>::infinity();  ///< e_n [-]
  /// e_n λ/(1 - λ) (0 at an exact fixed point); +inf when no contraction was measured [-].
  double error = std::numeric_limits<double>::infinity();
  PlanarCensus census;            ///< the last period's steps (Moreau only; zeros for exact)
  PlanarPose end_pose;            ///< pose at the end of the run
  double level_min = 0, level_max = 0;  ///< the level under the part over the whole run [-]
};

/// The steady state from (pose, twist) at t = 0. Throws InvalidParameter on a bad problem or
/// options (naming "max_periods", "transient_periods" or "tolerance"), and std::runtime_error
/// when a Moreau run's state or the table's motion leaves the finite numbers (a table motion
/// that returns NaN would otherwise be a converged steady state without drift).
PlanarSteadyState planar_steady_state(const PlanarProblem& problem, const PlanarPose& pose,
                                      const PlanarTwist& twist,
                                      const PlanarSteadyStateOptions& options = {});

}  // namespace selfalign
