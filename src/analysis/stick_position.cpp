#include "selfalign/analysis/stick_position.hpp"

#include "selfalign/analysis/period_map.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

bool sticks_permanently(const FrictionMap& friction, double peak_acceleration, double x) {
  return friction.bound(x) >= peak_acceleration;  // eq. (40)
}

bool sticks_permanently(const FrictionMap& friction, const FrictionLaw& law,
                        double peak_acceleration, double x) {
  return law.static_coefficient() * friction.bound(x) >= peak_acceleration;
}

double friction_rise(const FrictionMap& friction) {
  if (const TwoRegionTable* two = friction.two_region()) return two->x_mu();
  const PiecewiseAffineFriction* pieces = friction.piecewise_affine();
  if (!pieces)
    throw InvalidParameter("friction", "not piecewise affine",
                           "the rise of the level needs a piecewise-affine friction level");
  return friction_rise(*pieces);
}

double friction_rise(const PiecewiseAffineFriction& f) {
  const auto pieces = f.pieces();
  for (const AffinePiece& p : pieces)
    if (p.slope != 0 || p.bound_at_begin != pieces.front().bound_at_begin) return p.begin;
  return std::numeric_limits<double>::infinity();
}

double stick_position_min(const PiecewiseAffineFriction& f, const FrictionLaw& law,
                          double peak) {
  const auto pieces = f.pieces();
  const double s = law.static_coefficient();
  double x = -std::numeric_limits<double>::infinity();
  for (std::size_t i = pieces.size(); i-- > 0;) {  // from the right: the level must hold on
    const AffinePiece& p = pieces[i];
    const double at_begin = s * p.bound(p.begin), at_end = s * p.bound(p.end);
    if (std::isinf(p.end)) {
      if (s * p.bound_at_begin < peak) return std::numeric_limits<double>::infinity();
      continue;
    }
    if (at_begin >= peak && at_end >= peak) continue;
    // The level crosses peak inside the piece (affine: one crossing) or fails at its end.
    x = at_end >= peak ? p.begin + (peak / s - p.bound_at_begin) / p.slope : p.end;
    break;
  }
  return std::max(x, friction_rise(f));
}

double stick_position_min(const TwoRegionTable& f, double peak) {
  if (peak <= 1) return f.x_mu();
  if (peak > f.c_mu()) return std::numeric_limits<double>::infinity();
  return f.x_mu() + f.width() * (peak - 1) / (f.c_mu() - 1);  // eq. (41)
}

StickPositionMap::StickPositionMap(const ThreePhaseProfile& profile, const TwoRegionTable& f)
    : p_(profile.parameters()),
      x_mu_(f.x_mu()),
      w_(f.width()),
      c_mu_(f.c_mu()),
      b1_(f.b1()),
      omega_(std::sqrt(f.b1())),
      T1_(profile.solution().t1),
      T2_(profile.solution().t2 - profile.solution().t1),
      T3_(profile.solution().t3 - profile.solution().t2),
      c1_((f.b2() + p_.a2) / f.b1()),  // eq. (60)
      c2_((f.b2() - p_.a3) / f.b1()),
      K_((p_.a2 + p_.a3) / f.b1()),
      x_stick_min_(stick_position_min(f, profile.peak_acceleration())) {
  // x-independent assumptions: the fixed point is x_stick,min and lies in the transition
  // region (y3'' <= y2'' <= c_mu), and the slip on [t1, t2] does not stop (theta < pi).
  shape_ok_ = p_.a3 <= p_.a2 && p_.a2 <= c_mu_ && p_.a2 > 1 && omega_ * T2_ < kPi;
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

double StickPositionMap::slip_duration(double x_n) const {
  const double d = x_n - c1_, th = omega_ * T2_;
  const double d12 = K_ + d * std::cos(th), d22 = -d * std::sin(th);  // eqs. (54), (55)
  return T2_ + std::atan2(d22, d12) / omega_;  // eq. (58), atan2 for all quadrants
}

bool StickPositionMap::held_at(double x) const {
  const double m = 1 + b1_ * std::clamp(x - x_mu_, 0.0, w_);  // eqs. (7)-(9)
  return m >= p_.a3;
}

double StickPositionMap::next_stick_position(double x) const {
  if (!(x >= x_mu_ && x <= x_mu_ + w_)) return kNaN;  // eq. (42) needs the transition region
  if (x >= c1_) return held_at(x) && p_.a2 <= c_mu_ ? x : kNaN;  // m(x) >= y2'', y3'': held
  if (!(omega_ * T2_ < kPi) || slip_duration(x) > T2_ + T3_) return kNaN;
  const double crest = (*this)(x);  // eq. (59): x' = 0 in [t2, t3]
  if (crest > x_mu_ + w_) return kNaN;
  if (held_at(crest)) return crest;
  // m(crest) < y3'': it slides back under y'' = +y3'', x'' = b1 (x - x3) about x3 = (b2 + y3'')/b1
  // (hyperbolic), from rest at t2 + τc until t3 ...
  const double x3 = c1_ - (p_.a2 - p_.a3) / b1_;
  const double p = crest - x3, rest = omega_ * (T3_ - (slip_duration(x) - T2_));
  const double x_t3 = x3 + p * std::cosh(rest), v_t3 = p * std::sinh(rest);  // x, x'/ω at t3
  // ... then under y'' = 0, x'' = m(x) = b1 (x - x0) about x0 = b2/b1 (m = 0), decelerating:
  // E = x - x0 keeps E^2 - (x'/ω)^2, so it stops at x0 + sqrt(E^2 - (x'/ω)^2) after
  // atanh(-(x'/ω)/E)/ω.
  const double x0 = c1_ - p_.a2 / b1_, E = x_t3 - x0;
  if (!(E > std::abs(v_t3))) return kNaN;  // would not stop
  if (std::atanh(-v_t3 / E) / omega_ > T1_) return kNaN;  // still sliding at t1
  const double stop = x0 + std::sqrt(E * E - v_t3 * v_t3);
  return stop >= x_mu_ ? stop : kNaN;  // the slide stayed in the transition region
}

double StickPositionMap::contraction_at_fixed_point() const {
  if (!shape_ok_) return kNaN;
  const double c = std::cos(omega_ * T2_);
  return p_.a3 < p_.a2 ? c : c * std::cosh(omega_ * T3_);
}

// With s = c1 - x_n, λ = cos θ cosh(ω T3), σ = cos θ sinh(ω T3) and A = y2''/b1, a slide back
// after the stop ends within h(s) = A - sqrt((A - λ s)^2 - (σ s)^2) below c1, and h(s) < s iff
// s sin²θ < 2 A (1 - λ); it ends before t1 if atanh(σ s/(A - λ s))/ω <= t1. Each condition
// only gets easier as s shrinks (docs/accumulation.md).
bool StickPositionMap::slide_back_contracts(double s) const {
  const double th = omega_ * T2_, c = std::cos(th), sn = std::sin(th);
  const double lambda = c * std::cosh(omega_ * T3_), sigma = c * std::sinh(omega_ * T3_);
  const double A = p_.a2 / b1_;
  if (!(c > 0 && lambda < 1 && s * sn * sn < 2 * A * (1 - lambda))) return false;
  const double e = A - lambda * s;
  return e > sigma * s && std::atanh(sigma * s / e) / omega_ <= T1_;
}

bool StickPositionMap::proves_accumulation_from(double x) const {
  if (!shape_ok_ || !(x >= x_mu_ && x < c1_)) return false;
  if (!(x > basin_lower_bound())) return false;  // x_{n+1} < c1: no overshoot
  // The stop comes before t3 (the arc time shrinks as x_n -> c1).
  if (slip_duration(x) > T2_ + T3_) return false;
  // Either the object holds at x_{n+1} through the rest of [t2, t3] (friction at x_{n+1} >=
  // y3''; it rises along the increasing sequence), or every slide back is contracted.
  return held_at((*this)(x)) || slide_back_contracts(c1_ - x);
}

EveryEntryAccumulation StickPositionMap::every_entry_accumulation() const {
  EveryEntryAccumulation r;
  const double peak = std::max(p_.a2, p_.a3);
  if (peak > c_mu_) {
    r.reason = "max|y''| = " + format_number(peak) + " > c_mu = " + format_number(c_mu_) +
               ": x_stick,min does not exist (eq. 41), no position holds the object for good";
    return r;
  }
  if (p_.a3 > p_.a2) {
    r.reason = "y3'' > y2'': x_stick,min (eq. 41, set by y3'') lies beyond the fixed point "
               "(b2 + y2'')/b1 of eq. (59), where the object cannot hold (m < y3''); Sect. 7.3 "
               "assumes y2'' >= y3''";
    return r;
  }
  if (p_.a2 <= 1) {
    r.reason = "max|y''| <= 1: the object is held wherever it comes to rest (eq. 40)";
    return r;
  }
  if (!(omega_ * T2_ < kPi)) {
    r.reason = "sqrt(b1) (t2 - t1) >= pi: the slip from rest ends inside [t1, t2], which "
               "eq. (59) excludes";
    return r;
  }
  if (slip_duration(x_mu_) > T2_ + T3_) {
    r.reason = "from x_mu the forward slip lasts past t3: eq. (59) assumes it stops in "
               "[t2, t3]";
    return r;
  }
  r.applies = true;
  if (!((*this)(x_mu_) < c1_)) return r;  // from x_mu it stops beyond x_stick,min, for good
  // Every first stop in [x_mu, c1) is in the basin. Its next stop is held if even the lowest
  // one is (eq. 59 is smallest at d = -K cos θ, where it is c2 + K sin θ), or the slides back
  // contract from the farthest start, x_mu.
  const double d_low = -K_ * std::cos(omega_ * T2_);
  const double lowest = d_low >= x_mu_ - c1_ ? c2_ + K_ * std::sin(omega_ * T2_) : (*this)(x_mu_);
  if (held_at(lowest) || slide_back_contracts(c1_ - x_mu_)) {
    r.accumulates = true;
    return r;
  }
  r.applies = false;
  r.reason = "some first stops in [x_mu, x_stick,min) are followed by a stop where m < y3'' "
             "(lowest at x = " + format_number(lowest) + "), from which the object slides "
             "back, and the contraction bound on those slides fails at x_mu";
  return r;
}

std::optional<bool> StickPositionMap::accumulates_for_every_entry() const {
  const EveryEntryAccumulation e = every_entry_accumulation();
  if (!e.applies) return std::nullopt;
  return e.accumulates;
}

double stopping_look_phase(const TableProfile& profile) {
  const PiecewisePolynomialProfile* pwc = profile.piecewise_polynomial();
  if (profile.three_phase() && pwc)
    for (const AccelerationSegment& seg : pwc->segments())
      if (seg.accel < 0) return seg.begin;  // the -y2'' segment begins at t1
  return 0;
}

PeriodStickPositionMap::PeriodStickPositionMap(const TableProfile& profile,
                                               const FrictionMap& friction,
                                               const FrictionLaw& law) {
  const PiecewisePolynomialProfile& pwc = require_exact_profile(profile, "the stick-position map");
  if (!friction.piecewise_affine())
    throw InvalidParameter("friction", "not piecewise affine",
                           "the stick-position map needs a piecewise-affine level (exact solver)");
  if (law.velocity_dependent())
    throw InvalidParameter("law", law.describe(),
                           "the stick-position map needs a Coulomb law (the exact solver)");
  phase_ = stopping_look_phase(profile);
  period_ = pwc.period();
  PeriodMapOptions o;
  o.method = Method::exact;
  map_ = std::make_unique<PeriodMap>(profile, friction, law, o);
}

PeriodStickPositionMap::~PeriodStickPositionMap() = default;

double PeriodStickPositionMap::operator()(double x_n) const {
  require_moderate("x_n", x_n);
  PeriodMap::Run run = map_->start({phase_, x_n, 0});
  const ObjectState& end = run.advance_to(phase_ + period_);
  return end.xd == 0 ? end.x : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace selfalign
