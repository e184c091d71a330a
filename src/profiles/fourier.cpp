#include "selfalign/profiles/fourier.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "periodic_extrema.hpp"
#include "selfalign/error.hpp"

namespace selfalign {

namespace {
constexpr std::size_t kMaxOrder = 1000;  // N; construction is O(N^2), a step O(N)
// The rotation recurrence below is re-seeded with cos/sin every kResync harmonics: its rounding
// grows like k eps between seeds, so it stays below 16 eps relative.
constexpr std::size_t kResync = 16;
}  // namespace

std::array<double, 4> FourierProfile::derivatives(double t) const {
  // Phase in [0, Δt) first: cos(k w t) of a large t would lose the digits of t's integer part.
  const double ph = t - period_ * std::floor(t / period_);
  const double w = 2 * std::numbers::pi / period_, theta = w * ph;
  const double c1 = std::cos(theta), s1 = std::sin(theta);
  std::array<double, 4> d{offset_, 0.0, 0.0, 0.0};  // y and its first three derivatives
  double c = c1, s = s1;
  for (std::size_t k = 0; k < cos_.size(); ++k) {
    if (k > 0 && k % kResync == 0) {
      c = std::cos(static_cast<double>(k + 1) * theta);
      s = std::sin(static_cast<double>(k + 1) * theta);
    }
    const double kw = static_cast<double>(k + 1) * w;
    const double even = cos_[k] * c + sin_[k] * s;  // the y-like and y'-like combinations
    const double odd = -cos_[k] * s + sin_[k] * c;
    d[0] += even;
    d[1] += kw * odd;
    d[2] -= kw * kw * even;
    d[3] -= kw * kw * kw * odd;
    const double c_next = c * c1 - s * s1;  // (k+2) theta from (k+1) theta
    s = s * c1 + c * s1;
    c = c_next;
  }
  return d;
}

FourierProfile::FourierProfile(Unsampled, double period, std::vector<double> cos_coeffs,
                               std::vector<double> sin_coeffs)
    : period_(require_positive_moderate("period", period)),
      cos_(std::move(cos_coeffs)),
      sin_(std::move(sin_coeffs)) {
  const std::size_t n = std::max(cos_.size(), sin_.size());
  if (n > kMaxOrder)
    throw InvalidParameter("fourier order", static_cast<double>(n),
                           "must be <= 1000 (coefficients in fourier_cos / fourier_sin)");
  cos_.resize(n, 0.0);
  sin_.resize(n, 0.0);
  bool any = false;
  for (std::size_t k = 0; k < n; ++k) {
    require_finite("fourier_cos[" + std::to_string(k + 1) + "]", cos_[k]);
    require_finite("fourier_sin[" + std::to_string(k + 1) + "]", sin_[k]);
    any = any || cos_[k] != 0.0 || sin_[k] != 0.0;
  }
  if (!any)
    throw InvalidParameter("fourier coefficients", "all zero",
                           "need at least one nonzero coefficient (order >= 1)");
  for (std::size_t k = 0; k < n; ++k) {
    const double kw = static_cast<double>(k + 1) * 2 * std::numbers::pi / period_;
    const double amplitude = std::hypot(cos_[k], sin_[k]);
    jerk_bound_ += kw * kw * kw * amplitude;
    snap_bound_ += kw * kw * kw * kw * amplitude;
    fifth_bound_ += kw * kw * kw * kw * kw * amplitude;
  }
}

FourierProfile::FourierProfile(double period, std::vector<double> cos_coeffs,
                               std::vector<double> sin_coeffs)
    : FourierProfile(Unsampled{}, period, std::move(cos_coeffs), std::move(sin_coeffs)) {
  const int samples = 128 * order();
  auto y = [this](double t) { return derivatives(t)[0]; };
  auto yd = [this](double t) { return derivatives(t)[1]; };
  auto ydd = [this](double t) { return derivatives(t)[2]; };
  auto yddd = [this](double t) { return derivatives(t)[3]; };
  const detail::Extrema ey = detail::periodic_extrema(y, yd, period_, samples);
  offset_ = -ey.min;
  stroke_ = ey.max - ey.min;
  const detail::Extrema ea = detail::periodic_extrema(ydd, yddd, period_, samples);
  peak_ = std::max(std::abs(ea.min), std::abs(ea.max));
  if (!std::isfinite(stroke_) || !std::isfinite(peak_) || !(stroke_ > 0))
    throw InvalidParameter("period", period_,
                           "gives no finite table motion with these coefficients (stroke " +
                               format_number(stroke_) + ", peak acceleration " +
                               format_number(peak_) + ")");
}

FourierProfile FourierProfile::with_extrema(double period, std::vector<double> cos_coeffs,
                                            std::vector<double> sin_coeffs,
                                            const KnownExtrema& e) {
  FourierProfile p(Unsampled{}, period, std::move(cos_coeffs), std::move(sin_coeffs));
  require_finite("y_min", e.y_min);
  require_finite("y_max", e.y_max);
  if (!(e.y_max > e.y_min))
    throw InvalidParameter("y_max", e.y_max,
                           "must exceed y_min = " + format_number(e.y_min) + " (stroke > 0)");
  if (!(e.peak_acceleration >= 0) || !std::isfinite(e.peak_acceleration))
    throw InvalidParameter("peak_acceleration", e.peak_acceleration, "must be finite and >= 0");
  p.offset_ = -e.y_min;
  p.stroke_ = e.y_max - e.y_min;
  p.peak_ = e.peak_acceleration;
  if (!std::isfinite(p.stroke_))
    throw InvalidParameter("y_max", e.y_max,
                           "gives no finite stroke with y_min = " + format_number(e.y_min));
  return p;
}

TableState FourierProfile::state(double t) const {
  const std::array<double, 4> d = derivatives(t);
  return {d[0], d[1], d[2]};
}

}  // namespace selfalign
