#include "selfalign/simulate/arc.hpp"

#include "selfalign/profiles/fourier.hpp"

#include <cmath>
#include <numbers>

namespace selfalign {

// x = c + d tau + D C(tau) + E S(tau) with (C, S) = (cos, sin/omega) or (cosh, sinh/omega):
// D = x0 - c, E = x0' - d (eqs. 43-46 plus the particular solution of the drifting centre).
PosVel HarmonicArc::state(double x0, double v0, double tau) const noexcept {
  const double c = std::cos(omega * tau), s = std::sin(omega * tau), D = x0 - center;
  const double E = v0 - drift;
  return {center + drift * tau + D * c + E / omega * s, drift - D * omega * s + E * c};
}

Transition HarmonicArc::transition(double tau) const noexcept {
  const double c = std::cos(omega * tau), s = std::sin(omega * tau);
  return {c, s / omega, -omega * s, c};
}

namespace {
// sin(z)/z, with its series where the quotient would lose digits.
double sinc(double z) noexcept {
  return std::abs(z) < 1e-4 ? 1 - z * z / 6 : std::sin(z) / z;
}
}  // namespace

// docs/fourier-transition-region.md, eqs. F3-F8.
PosVel DrivenAffineArc::state(double x0, double v0, double tau) const noexcept {
  const double P = series->period(), w = 2 * std::numbers::pi / P;
  const double phase0 = t0 - P * std::floor(t0 / P);
  const auto& A = series->cos_coeffs();
  const auto& B = series->sin_coeffs();
  const double u0 = x0 - center;
  double u = 0, ud = 0;
  const bool harmonic = kappa > 0;
  const double r = std::sqrt(std::abs(kappa));  // omega or lambda
  double ch = 0, sh = 0;                         // cos/sin or cosh/sinh of r tau
  if (harmonic) {
    ch = std::cos(r * tau), sh = std::sin(r * tau);
    u = u0 * ch + v0 / r * sh;  // F3
    ud = -u0 * r * sh + v0 * ch;
  } else {
    ch = std::cosh(r * tau), sh = std::sinh(r * tau);
    u = u0 * ch + v0 / r * sh;  // F6
    ud = u0 * r * sh + v0 * ch;
  }
  for (std::size_t j = 0; j < A.size(); ++j) {
    if (A[j] == 0 && B[j] == 0) continue;
    const double Om = static_cast<double>(j + 1) * w;
    const double cp = std::cos(Om * phase0), sp = std::sin(Om * phase0);
    const double alpha = A[j] * cp + B[j] * sp, beta = -A[j] * sp + B[j] * cp;  // F2
    const double so = std::sin(Om * tau);
    double kc, ks, kcd;  // zero-state responses to cos, sin (Omega tau) and kc's derivative
    if (harmonic) {      // F4, F5: stable through Omega = omega
      const double sum = Om + r, half = 0.5 * tau;
      const double S = std::sin(sum * half), C = std::cos(sum * half);
      const double sn = sinc((Om - r) * half);
      kc = tau * S * sn / sum;
      ks = -tau * C * sn / sum + sh / (r * sum);
      kcd = (so + r * tau * C * sn) / sum;
    } else {  // F7, F8
      const double den = r * r + Om * Om, co = std::cos(Om * tau);
      kc = (ch - co) / den;
      ks = (Om / r * sh - so) / den;
      kcd = (r * sh + Om * so) / den;
    }
    const double f = Om * Om;
    u += f * (alpha * kc + beta * ks);
    ud += f * (alpha * kcd + beta * Om * kc);
  }
  return {center + u, ud};
}

double DrivenAffineArc::acceleration(double x, double, double tau) const noexcept {
  return -kappa * (x - center) - series->derivatives(t0 + tau)[2];
}

Transition DrivenAffineArc::transition(double tau) const noexcept {
  const double r = std::sqrt(std::abs(kappa));
  if (kappa > 0) return HarmonicArc{r, 0, 0}.transition(tau);
  return HyperbolicArc{r, 0, 0}.transition(tau);
}

PosVel HyperbolicArc::state(double x0, double v0, double tau) const noexcept {
  const double c = std::cosh(omega * tau), s = std::sinh(omega * tau), D = x0 - center;
  const double E = v0 - drift;
  return {center + drift * tau + D * c + E / omega * s, drift + D * omega * s + E * c};
}

Transition HyperbolicArc::transition(double tau) const noexcept {
  const double c = std::cosh(omega * tau), s = std::sinh(omega * tau);
  return {c, s / omega, omega * s, c};
}

ObjectState Arc::at(double t) const noexcept {
  const PosVel s = std::visit([&](const auto& a) { return a.state(x0, xd0, t - t0); }, shape);
  return {t, s.x, s.xd};
}

double Arc::start_acceleration() const noexcept {
  return std::visit([&](const auto& a) { return a.acceleration(x0, xd0, 0.0); }, shape);
}

double Arc::end_acceleration() const noexcept {
  return std::visit([&](const auto& a) { return a.acceleration(x1, xd1, t1 - t0); }, shape);
}

Transition Arc::transition() const noexcept {
  return std::visit([&](const auto& a) { return a.transition(t1 - t0); }, shape);
}

}  // namespace selfalign
