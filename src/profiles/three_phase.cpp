#include "selfalign/profiles/three_phase.hpp"

#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

void validate(const ThreePhaseParameters& p) {
  require_positive_moderate("period", p.period);
  require_positive_moderate("stroke", p.stroke);
  require_positive("a2", p.a2);
  require_positive("a3", p.a3);
}

ThreePhaseSolution solve_three_phase(const ThreePhaseParameters& p) {
  validate(p);
  ThreePhaseSolution r;
  const double dt = p.period;
  const double s = 1.0 / p.a2 + 1.0 / p.a3;
  r.inverse_accel_sum = s;
  r.inverse_accel_limit = dt * dt / (8.0 * p.stroke);
  const double G = std::sqrt(2.0 * s * p.stroke) / dt;
  if (!(G <= 0.5)) return r;  // case 0: eq. (63) has no real solution with t1 >= t0
  const double root = std::sqrt(1.0 - 2.0 * G);
  const double u = 2.0 * G / (1.0 + root);  // = 1 - sqrt(1 - 2G), without cancellation
  const double D = u * dt / s;              // y'_max - y'_min, eq. (65)
  r.physical = true;
  r.t1 = (1.0 - u) * dt;
  r.velocity_swing = D;
  r.t2 = r.t1 + D / p.a2;
  r.t3 = dt;                                   // eq. (62)
  r.yd_ini = 0.5 * u * u * dt / s;             // zero-mean velocity, eq. (64)
  r.y_ini = r.yd_ini * r.yd_ini / (2.0 * p.a3);  // eq. (61)
  r.t_yd0_1 = r.t1 + r.yd_ini / p.a2;          // eq. (66)
  r.t_yd0_2 = r.t3 - r.yd_ini / p.a3;          // eq. (67)
  return r;
}

namespace {
PiecewisePolynomialProfile three_phase_shape(const ThreePhaseParameters& p,
                                           const ThreePhaseSolution& r) {
  if (!r.physical)
    throw InvalidParameter(
        "a2, a3", format_number(p.a2) + ", " + format_number(p.a3),
        "non-physical profile (case 0): need 1/a2 + 1/a3 <= period^2/(8 stroke) = " +
            format_number(r.inverse_accel_limit) + ", got " + format_number(r.inverse_accel_sum));
  // Durations straight from the closed form (docs/three-phase-profile.md), never as
  // differences of the absolute times t1, t2, t3: t3 - t2 = D/y3'' can be 1e-4 of Δt, and its
  // difference would carry Δt's rounding into the net velocity change -y2''(t2-t1) + y3''(t3-t2).
  const double durations[3] = {r.t1, r.velocity_swing / p.a2, r.velocity_swing / p.a3};
  const double accels[3] = {0.0, -p.a2, p.a3};
  return PiecewisePolynomialProfile::from_accelerations(durations, accels, "three-phase");
}
}  // namespace

ThreePhaseProfile::ThreePhaseProfile(const ThreePhaseParameters& p)
    : params_(p), solution_(solve_three_phase(p)), shape_(three_phase_shape(p, solution_)) {}

}  // namespace selfalign
