#include "selfalign/profiles/sampled.hpp"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <fstream>
#include <sstream>

#include "../io/csv_fields.hpp"
#include "periodic_extrema.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

Interpolation parse_interpolation(const std::string& text) {
  if (text == "constant") return Interpolation::constant;
  if (text == "linear") return Interpolation::linear;
  throw InvalidParameter("interpolation", text, "must be one of: constant, linear");
}

namespace {
}  // namespace

AccelerationSamples read_acceleration_samples(const std::string& path) {
  constexpr std::uintmax_t kMaxSamplesBytes = 256u << 20;  // ~10 million rows
  require_input_file("samples", path, "--samples", kMaxSamplesBytes);
  std::ifstream in(path);
  if (!in) throw InvalidParameter("samples", path, "must be a readable CSV file");
  AccelerationSamples s;
  detail::read_csv_pairs(
      in,
      [&](int, double t, double a) {
        s.t.push_back(t);
        s.ydd.push_back(a);
      },
      [&](int number, const std::string& line, bool range) {
        throw InvalidParameter("samples", path + " line " + std::to_string(number),
                               range ? "'" + line + "' holds a number beyond the range of a double"
                                     : "'" + line + "' must be two numbers 't,ydd'");
      });
  return s;
}

namespace {
void validate_samples(const AccelerationSamples& s) {
  if (s.t.size() != s.ydd.size() || s.t.size() < 2)
    throw InvalidParameter("samples", static_cast<double>(s.t.size()),
                           "need at least 2 rows of (t, ydd)");
  if (s.t[0] != 0.0) throw InvalidParameter("samples t[0]", s.t[0], "must be 0");
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    require_moderate("samples ydd[" + std::to_string(i) + "]", s.ydd[i]);
    if (i > 0 && !(std::abs(s.t[i]) <= kMaxMagnitude && s.t[i] > s.t[i - 1]))
      throw InvalidParameter("samples t[" + std::to_string(i) + "]", s.t[i],
                             "must be <= 1e50 and > t[" + std::to_string(i - 1) + "] = " +
                                 format_number(s.t[i - 1]));
  }
  require_positive_moderate("samples period (last t)", s.t.back());  // a denormal period
}
}  // namespace

std::unique_ptr<TableProfile> make_sampled_profile(const AccelerationSamples& s,
                                                   Interpolation interpolation) {
  validate_samples(s);
  if (interpolation == Interpolation::linear)
    return std::make_unique<LinearAccelerationProfile>(s);
  std::vector<double> durations, accels;
  for (std::size_t i = 0; i + 1 < s.t.size(); ++i) {
    durations.push_back(s.t[i + 1] - s.t[i]);
    accels.push_back(s.ydd[i]);
  }
  return std::make_unique<PiecewisePolynomialProfile>(
      PiecewisePolynomialProfile::from_accelerations(durations, accels, "samples-constant"));
}

LinearAccelerationProfile::LinearAccelerationProfile(const AccelerationSamples& s)
    : t_(s.t), a_(s.ydd) {
  validate_samples(s);
  const std::size_t n = t_.size();
  y_.assign(n, 0.0);
  yd_.assign(n, 0.0);
  double mean = 0, dv_scale = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double d = t_[i + 1] - t_[i];
    const double dy = yd_[i] * d + d * d * (2 * a_[i] + a_[i + 1]) / 6.0;
    mean += dy;
    y_[i + 1] = y_[i] + dy;
    yd_[i + 1] = yd_[i] + 0.5 * d * (a_[i] + a_[i + 1]);
    dv_scale += 0.5 * d * (std::abs(a_[i]) + std::abs(a_[i + 1]));
    peak_ = std::max({peak_, std::abs(a_[i]), std::abs(a_[i + 1])});
  }
  if (!std::isfinite(yd_.back()) || std::abs(yd_.back()) > 1e-9 * std::max(dv_scale, 1e-300))
    throw InvalidParameter("ydd", yd_.back(),
                           "the accelerations must integrate to 0 over the period (net velocity "
                           "change " + format_number(yd_.back()) + ")");
  const double yd0 = -mean / period();
  for (std::size_t i = 0; i < n; ++i) {
    yd_[i] += yd0;
    y_[i] += yd0 * t_[i];
  }
  const detail::Extrema e = detail::periodic_extrema(
      [this](double t) { return state(t).y; }, [this](double t) { return state(t).yd; },
      period(), 64 * static_cast<int>(n));
  for (double& y : y_) y -= e.min;
  stroke_ = e.max - e.min;
}

TableState LinearAccelerationProfile::state(double t) const {
  const double P = period();
  double ph = t - P * std::floor(t / P);
  if (ph >= P) ph -= P;
  const std::size_t i =
      std::min<std::size_t>(std::upper_bound(t_.begin(), t_.end(), ph) - t_.begin(), t_.size() - 1) - 1;
  const double d = t_[i + 1] - t_[i], tau = ph - t_[i];
  const double j = (a_[i + 1] - a_[i]) / d;  // jerk on the segment
  return {y_[i] + yd_[i] * tau + a_[i] * tau * tau / 2 + j * tau * tau * tau / 6,
          yd_[i] + a_[i] * tau + j * tau * tau / 2, a_[i] + j * tau};
}

}  // namespace selfalign
