#include "selfalign/analysis/three_phase_steady_state.hpp"

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/error.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {

bool three_phase_closed_form_applies(const FrictionLaw& law) noexcept {
  return !law.velocity_dependent();
}

ThreePhaseSteadyState three_phase_steady_state(const ThreePhaseParameters& p,
                                               const FrictionLaw& law) {
  return three_phase_steady_state(p, solve_three_phase(p), law);  // validates p
}

// docs/three-phase-steady-state.md, with v = x' the relative velocity, y'' = 0, -a, +b on the
// intervals of lengths T1, T2, T3, and the slip rates of v' = -sigma k_sigma - y'' (eq. 6).
ThreePhaseSteadyState three_phase_steady_state(const ThreePhaseParameters& p,
                                               const ThreePhaseSolution& r,
                                               const FrictionLaw& law) {
  if (!three_phase_closed_form_applies(law))
    throw InvalidParameter("law", law.describe(),
                           "must be a Coulomb law (no Stribeck decay or viscous term) for the "
                           "closed-form steady state");
  ThreePhaseSteadyState s;
  if (!r.physical) {
    s.x_dot_0s = s.displacement = s.v_bar = s.f = s.slope = kNaN;
    return s;
  }
  const double a = p.a2, b = p.a3, mu_s = law.static_coefficient();
  const double kf = law.kinetic_forward(), kb = law.kinetic_backward();
  const double T1 = r.t1, T2 = r.t2 - r.t1, T3 = r.t3 - r.t2;
  const bool forward_push = a > mu_s, backward_push = b > mu_s;  // slip starts from rest
  double x = 0;  // displacement over the steady period
  if (!forward_push && !backward_push) {
    s.motion_case = StickSlipCase::pure_stick;  // (S5): rest is the steady state
  } else if (!backward_push) {
    // (S1), eqs. (12)-(24): rest until t1, forward slip, stop at t2 + tau_s <= t3, rest.
    const double v2 = (a - kf) * T2;        // eq. (16) at t2
    const double tau_s = v2 / (kf + b);     // eq. (21)
    x = v2 * (T2 + tau_s) / 2;              // eqs. (17), (20)
    s.motion_case = StickSlipCase::stick_slip_forward;
  } else if (!forward_push) {
    // (S2): rest until t2, backward slip; it stops in [t0, t1] or else in [t1, t2].
    const double v3 = (b - kb) * T3;  // backward speed at t3 = t0
    x = -v3 * T3 / 2;
    const double w1 = v3 - kb * T1;   // backward speed left at t1
    x -= w1 <= 0 ? v3 * v3 / (2 * kb) : (v3 + w1) * T1 / 2 + w1 * w1 / (2 * (a + kb));
    s.x_dot_0s = -v3;
    s.motion_case = StickSlipCase::stick_slip_backward;
  } else {
    // Sticking is possible on [t0, t1] only. From rest at t1: forward slip, stop at t2 + tau_s,
    // backward slip reaching the speed v3 at t3.
    const double v2 = (a - kf) * T2;
    const double tau_s = v2 / (kf + b);
    const double v3 = (b - kb) * (T3 - tau_s);
    if (v3 < kb * T1) {
      // (S3): it stops again in [t0, t1]: self-consistent, so the steady state.
      x = v2 * (T2 + tau_s) / 2 - v3 * (T3 - tau_s) / 2 - v3 * v3 / (2 * kb);
      s.x_dot_0s = -v3;
      s.motion_case = StickSlipCase::general_stick_slip;
    } else {
      // (S4): slip-slip. With w the backward speed at t1, one period is affine in w with slope
      // c4 (eq. 32); its fixed point is the steady state.
      const double c4 = (b - kb) * (a - kf) / ((kf + b) * (a + kb));
      const double w = ((b - kb) * T3 - kb * T1 - (b - kb) * (a - kf) * T2 / (kf + b)) / (1 - c4);
      const double s1 = w / (a + kb);            // backward slip ends in [t1, t2]
      const double w2 = (a - kf) * (T2 - s1);    // forward speed at t2
      const double s2 = w2 / (kf + b);           // forward slip ends in [t2, t3]
      const double w3 = (b - kb) * (T3 - s2);    // backward speed at t3 = t0
      x = -(w3 + w) * T1 / 2 - w * s1 / 2 + w2 * (T2 - s1 + s2) / 2 - w3 * (T3 - s2) / 2;
      s.x_dot_0s = -w3;
      s.slope = c4;
      s.motion_case = StickSlipCase::slip_slip;
    }
  }
  s.displacement = x;
  s.v_bar = x / p.period;         // eq. (10)
  s.f = objective_f(s.v_bar);     // eq. (11)
  return s;
}

}  // namespace selfalign
