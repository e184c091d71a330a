#include "selfalign/profiles/piecewise_constant.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

PiecewiseConstantProfile PiecewiseConstantProfile::from_accelerations(
    std::span<const double> durations, std::span<const double> accels, std::string kind) {
  if (durations.size() != accels.size() || durations.empty())
    throw InvalidParameter("segments", static_cast<double>(durations.size()),
                           "durations and accelerations must be non-empty and of equal length (" +
                               std::to_string(accels.size()) + " accelerations)");
  PiecewiseConstantProfile p;
  p.kind_ = std::move(kind);
  double t = 0, yd = 0, y = 0, dv = 0, dv_scale = 0, mean = 0;
  for (std::size_t i = 0; i < durations.size(); ++i) {
    const double d = require_non_negative("durations[" + std::to_string(i) + "]", durations[i]);
    const double a = require_finite("accelerations[" + std::to_string(i) + "]", accels[i]);
    if (d == 0.0) continue;
    p.segments_.push_back({t, d, a, y, yd});
    mean += yd * d + 0.5 * a * d * d;  // integral of y' over the segment, with yd(0) = 0
    y += yd * d + 0.5 * a * d * d;
    yd += a * d;
    dv += a * d;
    dv_scale += std::abs(a) * d;
    t += d;
    p.peak_ = std::max(p.peak_, std::abs(a));
  }
  p.period_ = require_positive_moderate("period", t);  // a denormal period left P/N = 0
  if (!std::isfinite(dv_scale))
    throw InvalidParameter("accelerations", dv_scale,
                           "the table motion overflows: sum of |acceleration| x duration must be "
                           "finite");
  if (std::abs(dv) > 1e-12 * std::max(dv_scale, 1e-300))
    throw InvalidParameter("accelerations", dv,
                           "the accelerations must integrate to 0 over the period (net velocity "
                           "change sum of acceleration x duration = " + format_number(dv) + ")");
  // Zero mean velocity: shift y' by -mean/Δt; y then gains -mean/Δt * t.
  const double yd0 = -mean / p.period_;
  double y_min = 0, y_max = 0;
  for (std::size_t i = 0; i < p.segments_.size(); ++i) {
    AccelerationSegment& s = p.segments_[i];
    s.yd += yd0;
    s.y += yd0 * s.begin;
    const double d = s.duration;
    const double y_end = s.y + s.yd * d + 0.5 * s.accel * d * d;
    y_min = std::min({y_min, s.y, y_end});
    y_max = std::max({y_max, s.y, y_end});
    if (s.accel != 0.0) {  // interior extremum where y' = 0
      const double tau = -s.yd / s.accel;
      if (tau > 0 && tau < d) {
        const double y_ext = s.y + 0.5 * s.yd * tau;
        y_min = std::min(y_min, y_ext);
        y_max = std::max(y_max, y_ext);
      }
    }
  }
  for (AccelerationSegment& s : p.segments_) s.y -= y_min;
  p.stroke_ = y_max - y_min;
  if (!std::isfinite(p.stroke_) || !std::isfinite(yd0))
    throw InvalidParameter("durations", p.period_,
                           "the table motion overflows: position or velocity not finite over a "
                           "period this long with these accelerations");
  return p;
}

double PiecewiseConstantProfile::phase(double t) const noexcept {
  double p = t - period_ * std::floor(t / period_);
  if (p >= period_) p -= period_;  // rounding at the top end
  return p < 0 ? 0 : p;
}

std::size_t PiecewiseConstantProfile::segment_at(double phase) const noexcept {
  std::size_t i = 0;
  while (i + 1 < segments_.size() && phase >= segments_[i + 1].begin) ++i;
  return i;
}

TableState PiecewiseConstantProfile::state(double t) const {
  const double ph = phase(t);
  const AccelerationSegment& s = segments_[segment_at(ph)];
  const double tau = ph - s.begin;
  return {s.y + s.yd * tau + 0.5 * s.accel * tau * tau, s.yd + s.accel * tau, s.accel};
}

double PiecewiseConstantProfile::velocity(double t) const {
  const double ph = phase(t);
  const AccelerationSegment& s = segments_[segment_at(ph)];
  return s.yd + s.accel * (ph - s.begin);
}

}  // namespace selfalign
