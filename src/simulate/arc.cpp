#include "selfalign/simulate/arc.hpp"

#include <cmath>

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
