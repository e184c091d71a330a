#pragma once
// Internal: the table velocity of a piecewise-constant-acceleration profile at times that only
// grow (the step ends of a time-stepping run), tracked across calls. The Moreau steppers' hot
// loops (simulate/time_stepping.cpp, planar/planar_point.cpp).

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign::detail {

// PiecewisePolynomialProfile::velocity_of_constant_acceleration(t) (= velocity(t)) bit for bit,
// for any t, fastest for t that grow between calls: the period index and segment are tracked
// instead of found anew each step. The phase is that
// function's own expression t - Δt n; wherever the tracked n is floor(t / Δt) for certain (the
// phase at least kEdge Δt from both ends of the period, far above the rounding of t / Δt for
// the periods tracked) it skips the division, else it takes the profile's own phase() and
// restarts the segment scan. The segment scan is segment_at's, resumed where the last call
// left it (from the first segment when the phase went back).
class TrackedVelocity {
 public:
  explicit TrackedVelocity(const PiecewisePolynomialProfile& p)
      : profile_(&p), segs_(p.segments()), period_(p.period()) {}
  double operator()(double t) const noexcept {
    constexpr double kEdge = 1e-9;      // of the period; rounding of t / Δt: ~1e-16 (n + 1)
    constexpr double kMaxTracked = 1e6;  // periods: (n + 1) eps stays below 1e-9 / 4
    const double guess = t - period_ * n_;
    double ph;
    if (guess >= kEdge * period_ && guess <= (1 - kEdge) * period_ && n_ < kMaxTracked) {
      ph = guess;
    } else {
      n_ = std::floor(t / period_);
      ph = profile_->phase(t);
      i_ = 0;
    }
    if (ph < segs_[i_].begin) i_ = 0;  // t went back: scan afresh
    while (i_ + 1 < segs_.size() && ph >= segs_[i_ + 1].begin) ++i_;
    const AccelerationSegment& s = segs_[i_];
    return s.yd + s.accel * (ph - s.begin);
  }

 private:
  const PiecewisePolynomialProfile* profile_;
  std::span<const AccelerationSegment> segs_;
  double period_;
  mutable double n_ = std::numeric_limits<double>::quiet_NaN();  // NaN: not yet known
  mutable std::size_t i_ = 0;
};


}  // namespace selfalign::detail
