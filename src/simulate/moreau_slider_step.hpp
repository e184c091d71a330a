#pragma once
// Internal: one Moreau step of the 1-D part (include/selfalign/simulate/time_stepping.hpp for
// the scheme), the one copy of its arithmetic: the 1-D stepper's loop (time_stepping.cpp) and
// the contact core's slider body (src/core/contact_core.cpp) both call it, so a slider body of
// the core moves as the 1-D stepper moves the part, step for step.

#include <cmath>

#include "selfalign/friction/friction_law.hpp"

namespace selfalign::detail {

// The Coulomb law's three coefficients, read once per run.
struct SliderCoefficients {
  double s, kf, kb;
  explicit SliderCoefficients(const FrictionLaw& law)
      : s(law.static_coefficient()), kf(law.kinetic_forward()), kb(law.kinetic_backward()) {}
};

// From x, v at t_k: the level `m` at the step's midpoint (read by the caller), the velocity
// without friction v_free = v - (y'(t_{k+1}) - y'(t_k)) (plus gravity's impulse along an
// incline); returns v at t_{k+1} and sets x1. `load`: the step's normal impulse per unit
// weight, h for the paper's constant normal load (core::Gravity: h cos(incline) + Δz' / g);
// the Coulomb impulses are load s m, load k m. kSpeedDependent: the law's Stribeck decay and
// viscous term taken at the step's start (the viscous drag h c |v| does not scale with load).
template <bool kSpeedDependent>
inline double moreau_slider_step(const FrictionLaw& law, const SliderCoefficients& c, double h,
                                 double theta, double m, double x, double v, double v_free,
                                 double& x1, double load) {
  // Largest friction impulses: static to hold or catch, kinetic while sliding on.
  const bool sliding_on = (v > 0 && v_free > 0) || (v < 0 && v_free < 0);
  double v1 = 0;
  if constexpr (!kSpeedDependent) {
    // The three impulse bounds, products of the level (hoisted out of the loop when the level
    // is constant: the uniform table) and a selection between them.
    const double h_static = load * (c.s * m), h_forward = load * (c.kf * m),
                 h_backward = load * (c.kb * m);
    const double hold = sliding_on ? (v_free > 0 ? h_forward : h_backward) : h_static;
    if (v_free > hold) v1 = v_free - h_forward;
    else if (v_free < -hold) v1 = v_free + h_backward;
  } else {  // mu_sigma(|v|) and c v at the step's start (explicit), the stick set-valued
    const int sigma = v_free > 0 ? 1 : -1;
    const double hold = load * ((sliding_on ? law.kinetic(sigma, std::abs(v)) : c.s) * m);
    const double drag = sliding_on ? h * law.viscous() * std::abs(v) : 0.0;
    if (std::abs(v_free) > hold + drag)
      v1 = v_free - sigma * (hold + drag);
    else if (!sliding_on && std::abs(v_free) > hold)
      v1 = v_free - sigma * load * law.kinetic(sigma, 0.0) * m;
  }
  x1 = x + h * ((1 - theta) * v + theta * v1);
  return v1;
}

}  // namespace selfalign::detail
