#pragma once
/// \file three_phase_steady_state.hpp
/// The steady state of the three-phase profile (jump accelerations 0, -y2'', +y3'') in closed
/// form, for every motion case of Table 1: the paper's analytic solution (Sect. 5.1, eqs.
/// (12)-(24) for case 1) and its counterparts for cases 2-5, derived in
/// docs/three-phase-steady-state.md for any Coulomb law (static s >= kinetic k_+, k_-, which
/// may differ with the slip direction; the paper's law is s = k_+ = k_- = 1).
///
/// No period is simulated and nothing is iterated: where the steady state sticks, it is the
/// motion from rest at the start of its stick, followed for one period (uniqueness, Sect. 6.2);
/// where it never sticks (slip-slip), the period map is affine with slope c4 (eq. 32) and its
/// fixed point is one division. This is what a sweep cell computes (sweep_accelerations); the
/// fixed-point search (steady_state.hpp) remains the method for every other profile and law,
/// and the tests check the two against each other on every cell of grids covering cases 0-5.

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

/// The closed-form steady state of one three-phase profile.
struct ThreePhaseSteadyState {
  /// Table 1 case of the steady period (its stick and slip pieces of positive length; 0: the
  /// profile does not exist). Under the paper's law it is predict_case's (Fig. 8).
  StickSlipCase motion_case = StickSlipCase::non_physical;
  double x_dot_0s = 0;      ///< steady-state relative velocity x' at t0 [-]; NaN for case 0
  double displacement = 0;  ///< x(t0 + Δt) - x(t0) over a steady period [-]; NaN for case 0
  double v_bar = 0;         ///< eq. (10): displacement / Δt [-]; NaN for case 0
  double f = 0;             ///< eq. (11) [-]; +inf for v̄ = 0, NaN for case 0
  /// dP/dv at the fixed point, P the period map of x'(t0): 0 where the steady state sticks (a
  /// perturbation ends in the stick, eq. 30), c4 = (y2'' - k_+)(y3'' - k_-) / ((y2'' +
  /// k_-)(y3'' + k_+)) in slip-slip (eq. 32 with the paper's law); NaN for case 0.
  double slope = 0;
};

/// True when the closed form holds for `law`: a Coulomb law (no Stribeck decay, no viscous
/// term); velocity-dependent laws have no closed-form slip arcs.
bool three_phase_closed_form_applies(const FrictionLaw& law) noexcept;

/// The steady state of the three-phase profile p on the uniform table under `law`. Throws
/// InvalidParameter on bad parameters (validate) or a velocity-dependent law (named "law").
ThreePhaseSteadyState three_phase_steady_state(const ThreePhaseParameters& p,
                                               const FrictionLaw& law = {});
/// The same from p's solved profile r = solve_three_phase(p) (a sweep solves it once per cell).
ThreePhaseSteadyState three_phase_steady_state(const ThreePhaseParameters& p,
                                               const ThreePhaseSolution& r,
                                               const FrictionLaw& law);

}  // namespace selfalign
