#include "selfalign/profiles/piecewise_polynomial.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

namespace {
// Position and velocity increments over tau on a segment starting at (0, yd) with y'' = a + j tau.
// Jerk 0 keeps the paper's quadratic forms term for term (eqs. 15-20).
double y_increment(double yd, double a, double j, double tau) {
  if (j == 0.0) return yd * tau + 0.5 * a * tau * tau;
  return tau * (yd + tau * (0.5 * a + tau * j / 6.0));
}
double yd_increment(double a, double j, double tau) {
  return j == 0.0 ? a * tau : tau * (a + 0.5 * j * tau);
}
}  // namespace

PiecewisePolynomialProfile PiecewisePolynomialProfile::build(std::span<const double> durations,
                                                             std::span<const double> accel_begin,
                                                             std::span<const double> accel_end,
                                                             std::string kind,
                                                             const char* begin_name,
                                                             const char* end_name) {
  if (durations.size() != accel_begin.size() || durations.size() != accel_end.size() ||
      durations.empty())
    throw InvalidParameter("segments", static_cast<double>(durations.size()),
                           "durations and accelerations must be non-empty and of equal length (" +
                               std::to_string(accel_begin.size()) + " accelerations)");
  PiecewisePolynomialProfile p;
  p.kind_ = std::move(kind);
  double t = 0, yd = 0, y = 0, dv = 0, dv_scale = 0;
  for (std::size_t i = 0; i < durations.size(); ++i) {
    const std::string idx = "[" + std::to_string(i) + "]";
    const double d = require_non_negative("durations" + idx, durations[i]);
    const double a = require_finite(begin_name + idx, accel_begin[i]);
    const double b = require_finite(end_name + idx, accel_end[i]);
    if (d == 0.0) continue;
    const double j = a == b ? 0.0 : (b - a) / d;
    if (!std::isfinite(j))
      throw InvalidParameter(end_name + idx, b,
                             "the jerk (accel_end - accel_begin)/duration overflows");
    p.segments_.push_back({t, d, a, y, yd, j});
    y += y_increment(yd, a, j, d);  // with y'(0) = 0: also the integral of y' so far
    const double dvi = yd_increment(a, j, d);
    yd += dvi;
    dv += dvi;
    dv_scale += 0.5 * (std::abs(a) + std::abs(b)) * d;
    t += d;
    p.peak_ = std::max({p.peak_, std::abs(a), std::abs(b)});
    p.peak_jerk_ = std::max(p.peak_jerk_, std::abs(j));
  }
  p.constant_ = p.peak_jerk_ == 0.0;
  p.period_ = require_positive_moderate("period", t);  // a denormal period left P/N = 0
  if (!std::isfinite(dv_scale))
    throw InvalidParameter("accelerations", dv_scale,
                           "the table motion overflows: sum of |acceleration| x duration must be "
                           "finite");
  if (std::abs(dv) > 1e-12 * std::max(dv_scale, 1e-300))
    throw InvalidParameter("accelerations", dv,
                           "the accelerations must integrate to 0 over the period (net velocity "
                           "change sum of acceleration x duration = " + format_number(dv) + ")");
  // Zero mean velocity: shift y' by -mean/Δt; y then gains -mean/Δt * t. With y'(0) = 0 the
  // integral of y' over the period is the final y.
  const double yd0 = -y / p.period_;
  double y_min = 0, y_max = 0;
  for (AccelerationSegment& s : p.segments_) {
    s.yd += yd0;
    s.y += yd0 * s.begin;
    const double d = s.duration;
    const double y_end = s.y + y_increment(s.yd, s.accel, s.jerk, d);
    y_min = std::min({y_min, s.y, y_end});
    y_max = std::max({y_max, s.y, y_end});
    // Interior extrema where y' = yd + a tau + j tau^2 / 2 = 0.
    auto extremum = [&](double tau) {
      if (tau > 0 && tau < d) {
        const double y_ext = s.y + y_increment(s.yd, s.accel, s.jerk, tau);
        y_min = std::min(y_min, y_ext);
        y_max = std::max(y_max, y_ext);
      }
    };
    if (s.jerk == 0.0) {
      const double tau = s.accel != 0.0 ? -s.yd / s.accel : 0.0;
      if (tau > 0 && tau < d) {  // y = y0 + yd tau / 2 at y' = 0
        const double y_ext = s.y + 0.5 * s.yd * tau;
        y_min = std::min(y_min, y_ext);
        y_max = std::max(y_max, y_ext);
      }
    } else {
      const double disc = s.accel * s.accel - 2.0 * s.jerk * s.yd;
      if (disc >= 0) {
        const double r = std::sqrt(disc);
        extremum((-s.accel + r) / s.jerk);
        extremum((-s.accel - r) / s.jerk);
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

PiecewisePolynomialProfile PiecewisePolynomialProfile::from_accelerations(
    std::span<const double> durations, std::span<const double> accels, std::string kind) {
  return build(durations, accels, accels, std::move(kind), "accelerations", "accelerations");
}

PiecewisePolynomialProfile PiecewisePolynomialProfile::from_linear_accelerations(
    std::span<const double> durations, std::span<const double> accel_begin,
    std::span<const double> accel_end, std::string kind) {
  return build(durations, accel_begin, accel_end, std::move(kind), "accel_begin", "accel_end");
}

PiecewisePolynomialProfile PiecewisePolynomialProfile::from_breakpoints(
    std::span<const double> times, std::span<const double> accels, double period,
    std::string kind) {
  if (times.size() != accels.size() || times.size() < 2)
    throw InvalidParameter("times", static_cast<double>(times.size()),
                           "times and accelerations must be of equal length >= 2 (" +
                               std::to_string(accels.size()) + " accelerations)");
  if (times[0] != 0.0) throw InvalidParameter("times[0]", times[0], "must be 0");
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1]) || !std::isfinite(times[i]))
      throw InvalidParameter("times[" + std::to_string(i) + "]", times[i],
                             "must be finite and > times[" + std::to_string(i - 1) + "] = " +
                                 format_number(times[i - 1]));
  if (!(period > times.back()) || !std::isfinite(period))
    throw InvalidParameter("period", period,
                           "must be finite and > the last breakpoint " + format_number(times.back()));
  const std::size_t n = times.size();
  for (std::size_t i = 0; i < n; ++i)
    require_moderate("accelerations[" + std::to_string(i) + "]", accels[i]);
  std::vector<double> d(n), a(n), b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double end = i + 1 < n ? times[i + 1] : period;
    d[i] = end - times[i];
    a[i] = accels[i];
    b[i] = accels[(i + 1) % n];
    // The jerk between two breakpoints is their acceleration change over their gap: a gap too
    // short for the change is the user's breakpoint (or period), not the accelerations.
    if (a[i] != b[i] && !(std::abs(b[i] - a[i]) / d[i] <= kMaxMagnitude)) {
      const std::string end_name = i + 1 < n ? "times[" + std::to_string(i + 1) + "]" : "period";
      throw InvalidParameter(end_name, end,
                             "is too close to times[" + std::to_string(i) + "] = " +
                                 format_number(times[i]) + " for the acceleration change " +
                                 format_number(b[i] - a[i]) + " (the jerk, change / gap, must be " +
                                 "<= 1e50: a gap >= " +
                                 format_number(std::abs(b[i] - a[i]) / kMaxMagnitude) + ")");
    }
  }
  return build(d, a, b, std::move(kind), "accelerations", "accelerations");
}

TableState PiecewisePolynomialProfile::state(double t) const {
  const double ph = phase(t);
  const AccelerationSegment& s = segments_[segment_at(ph)];
  const double tau = ph - s.begin;
  if (s.jerk == 0.0)
    return {s.y + s.yd * tau + 0.5 * s.accel * tau * tau, s.yd + s.accel * tau, s.accel};
  return {s.y + y_increment(s.yd, s.accel, s.jerk, tau),
          s.yd + yd_increment(s.accel, s.jerk, tau), s.accel + s.jerk * tau};
}

}  // namespace selfalign
