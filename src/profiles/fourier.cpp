#include "selfalign/profiles/fourier.hpp"

#include <cmath>
#include <numbers>

#include "periodic_extrema.hpp"
#include "selfalign/error.hpp"

namespace selfalign {

FourierProfile::FourierProfile(double period, std::vector<double> cos_coeffs,
                               std::vector<double> sin_coeffs)
    : period_(require_positive("period", period)),
      cos_(std::move(cos_coeffs)),
      sin_(std::move(sin_coeffs)) {
  const std::size_t n = std::max(cos_.size(), sin_.size());
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
  const int samples = 128 * static_cast<int>(n);
  auto y = [this](double t) { return state(t).y; };
  auto yd = [this](double t) { return state(t).yd; };
  auto ydd = [this](double t) { return state(t).ydd; };
  const double w = 2 * std::numbers::pi / period_;
  auto yddd = [this, w](double t) {  // third derivative, for the extrema of y''
    double s = 0;
    for (std::size_t k = 0; k < cos_.size(); ++k) {
      const double kw = (k + 1) * w;
      s += kw * kw * kw * (cos_[k] * std::sin(kw * t) - sin_[k] * std::cos(kw * t));
    }
    return s;
  };
  const detail::Extrema ey = detail::periodic_extrema(y, yd, period_, samples);
  offset_ = -ey.min;
  stroke_ = ey.max - ey.min;
  const detail::Extrema ea = detail::periodic_extrema(ydd, yddd, period_, samples);
  peak_ = std::max(std::abs(ea.min), std::abs(ea.max));
}

TableState FourierProfile::state(double t) const {
  const double w = 2 * std::numbers::pi / period_;
  TableState s{offset_, 0.0, 0.0};
  for (std::size_t k = 0; k < cos_.size(); ++k) {
    const double kw = (k + 1) * w;
    const double c = std::cos(kw * t), sn = std::sin(kw * t);
    s.y += cos_[k] * c + sin_[k] * sn;
    s.yd += kw * (-cos_[k] * sn + sin_[k] * c);
    s.ydd += -kw * kw * (cos_[k] * c + sin_[k] * sn);
  }
  return s;
}

}  // namespace selfalign
