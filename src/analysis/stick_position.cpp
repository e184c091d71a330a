#include "selfalign/analysis/stick_position.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace selfalign {

bool sticks_permanently(const FrictionMap& friction, double peak_acceleration, double x) {
  return friction.bound(x) >= peak_acceleration;  // eq. (40)
}

double stick_position_min(const TwoRegionFriction& f, double peak) {
  if (peak <= 1) return f.x_mu();
  if (peak > f.c_mu()) return std::numeric_limits<double>::infinity();
  return f.x_mu() + f.width() * (peak - 1) / (f.c_mu() - 1);  // eq. (41)
}

StickPositionMap::StickPositionMap(const ThreePhaseProfile& profile, const TwoRegionFriction& f)
    : p_(profile.parameters()),
      x_mu_(f.x_mu()),
      w_(f.width()),
      c_mu_(f.c_mu()),
      b1_(f.b1()),
      omega_(std::sqrt(f.b1())),
      T2_(profile.solution().t2 - profile.solution().t1),
      T3_(profile.solution().t3 - profile.solution().t2),
      c1_((f.b2() + p_.a2) / f.b1()),  // eq. (60)
      c2_((f.b2() - p_.a3) / f.b1()),
      K_((p_.a2 + p_.a3) / f.b1()),
      x_stick_min_(stick_position_min(f, profile.peak_acceleration())) {
  // x-independent assumptions: the fixed point is x_stick,min and lies in the transition
  // region (y3'' <= y2'' <= c_mu), and the slip on [t1, t2] does not stop (theta < pi).
  shape_ok_ = p_.a3 <= p_.a2 && p_.a2 <= c_mu_ && p_.a2 > 1 && omega_ * T2_ < std::numbers::pi;
}

double StickPositionMap::operator()(double x_n) const {
  const double d = x_n - c1_, th = omega_ * T2_;
  const double a = K_ + d * std::cos(th), b = d * std::sin(th);
  return c2_ + std::sqrt(a * a + b * b);  // eq. (59)
}

double StickPositionMap::slope_at_fixed_point() const { return std::cos(omega_ * T2_); }

double StickPositionMap::basin_lower_bound() const {
  return c1_ - 2 * K_ * std::cos(omega_ * T2_);
}

bool StickPositionMap::accumulates_for_every_entry() const {
  return (*this)(x_mu_) < x_stick_min_;
}

double StickPositionMap::slip_duration(double x_n) const {
  const double d = x_n - c1_, th = omega_ * T2_;
  const double d12 = K_ + d * std::cos(th), d22 = -d * std::sin(th);  // eqs. (54), (55)
  return T2_ + std::atan2(d22, d12) / omega_;  // eq. (58), atan2 for all quadrants
}

bool StickPositionMap::proves_accumulation_from(double x) const {
  if (!shape_ok_ || !(x >= x_mu_ && x < c1_)) return false;
  if (!(x > basin_lower_bound())) return false;  // x_{n+1} < c1: the sequence stays below
  const double next = (*this)(x);
  // The stop comes before t3 (the arc time shrinks as x_n -> c1), and the object holds there
  // through the rest of [t2, t3] (friction at x_{n+1} >= y3''; it rises along the sequence).
  if (slip_duration(x) > T2_ + T3_) return false;
  const double m_next = 1 + (c_mu_ - 1) / w_ * (next - x_mu_);
  return m_next >= p_.a3;
}

}  // namespace selfalign
