#pragma once
/// \file piecewise_polynomial.hpp
/// A periodic table profile whose acceleration is piecewise polynomial of degree <= 1: on each
/// segment y'' = a + j tau (constant jerk j, tau the time into the segment), so y is a
/// periodic sequence of cubics. Jerk 0 everywhere gives the paper's sequences of second-order
/// polynomials (Fig. 3, Sect. 4.2); a finite jerk gives the trapezoidal-acceleration motions of
/// real actuators (Sect. 8, item 2). It is the common form of every profile the exact
/// event-driven solver integrates (simulate/exact.hpp).

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

/// One interval of a period on which the table acceleration is affine in time, with the table
/// state at its start [-]: y''(begin + tau) = accel + jerk tau for 0 <= tau < duration.
struct AccelerationSegment {
  double begin;     ///< start time within the period, 0 <= begin < Δt [-]
  double duration;  ///< length of the segment as given (not a difference of begin times) [-]
  double accel;     ///< table acceleration y'' at the segment start [-]
  double y;         ///< y at the segment start [-]
  double yd;        ///< y' at the segment start [-]
  double jerk = 0;  ///< y''' on the segment [-]; 0 on constant-acceleration segments

  /// y'' at the segment's end (left limit) [-].
  double end_accel() const noexcept { return accel + jerk * duration; }
};

class PiecewisePolynomialProfile final : public TableProfile {
 public:
  /// Builds the periodic profile with accelerations accels[i] held for durations[i] [-].
  /// Periodicity of y' needs sum(accels[i] durations[i]) = 0 (checked to 1e-12 relative to
  /// sum |accels[i]| durations[i]). The initial velocity is chosen so the mean velocity is zero
  /// (periodic y) and the initial position so min y = 0. Zero-length segments are dropped.
  /// Throws InvalidParameter on sizes that differ, negative or non-finite durations, a period
  /// outside [1e-50, 1e50], non-finite accelerations, a velocity that does not return, or a
  /// motion that overflows.
  static PiecewisePolynomialProfile from_accelerations(std::span<const double> durations,
                                                       std::span<const double> accels,
                                                       std::string kind = "quadratic-sequence");

  /// Builds the periodic profile whose acceleration goes linearly from accel_begin[i] to
  /// accel_end[i] over durations[i] [-] (jerk (end - begin)/duration; a jump between segments
  /// is allowed). Periodicity of y' needs sum((begin + end)/2 duration) = 0, checked as in
  /// from_accelerations; the same normalisation (zero mean velocity, min y = 0) and the same
  /// errors, naming "accel_begin" / "accel_end".
  static PiecewisePolynomialProfile from_linear_accelerations(
      std::span<const double> durations, std::span<const double> accel_begin,
      std::span<const double> accel_end, std::string kind = "piecewise-linear-acceleration");

  /// The piecewise-linear acceleration through the periodic breakpoints (times[i], accels[i])
  /// [-]: times strictly increasing from times[0] = 0, the period is `period` > times.back(),
  /// and the acceleration returns to accels[0] at t = period (continuous, finite jerk, at most
  /// 1e50). Throws InvalidParameter naming "times[i]" (not increasing, or too close to the
  /// previous breakpoint for its acceleration change), "period" or "accelerations[i]".
  static PiecewisePolynomialProfile from_breakpoints(std::span<const double> times,
                                                     std::span<const double> accels,
                                                     double period,
                                                     std::string kind = "piecewise-linear-acceleration");

  double period() const override { return period_; }
  TableState state(double t) const override;
  /// Inline (the time-stepping schemes' hot path); the same formulas as state().
  double velocity(double t) const override {
    const double ph = phase(t);
    const AccelerationSegment& s = segments_[segment_at(ph)];
    const double tau = ph - s.begin;
    return s.yd + (s.jerk == 0.0 ? s.accel * tau : tau * (s.accel + 0.5 * s.jerk * tau));
  }
  /// velocity(t) of a piecewise-constant acceleration (piecewise_constant() true) without the
  /// jerk test: the same arithmetic, for the time-stepping loop over the paper's profiles.
  double velocity_of_constant_acceleration(double t) const noexcept {
    const double ph = phase(t);
    const AccelerationSegment& s = segments_[segment_at(ph)];
    return s.yd + s.accel * (ph - s.begin);
  }
  double peak_acceleration() const override { return peak_; }
  double stroke() const override { return stroke_; }
  std::string kind() const override { return kind_; }
  const PiecewisePolynomialProfile* piecewise_polynomial() const override { return this; }

  std::span<const AccelerationSegment> segments() const noexcept { return segments_; }
  /// Index of the segment containing phase p in [0, Δt).
  std::size_t segment_at(double phase) const noexcept {
    std::size_t i = 0;
    while (i + 1 < segments_.size() && phase >= segments_[i + 1].begin) ++i;
    return i;
  }
  /// Phase of t in [0, Δt).
  double phase(double t) const noexcept {
    double p = t - period_ * std::floor(t / period_);
    if (p >= period_) p -= period_;  // rounding at the top end
    return p < 0 ? 0 : p;
  }
  /// True when every segment has jerk 0 (the paper's piecewise-constant acceleration).
  bool piecewise_constant() const noexcept { return constant_; }
  /// The largest |jerk| over the segments [-] (0 for piecewise-constant acceleration).
  double peak_jerk() const noexcept { return peak_jerk_; }

 private:
  PiecewisePolynomialProfile() = default;
  static PiecewisePolynomialProfile build(std::span<const double> durations,
                                          std::span<const double> accel_begin,
                                          std::span<const double> accel_end, std::string kind,
                                          const char* begin_name, const char* end_name);
  std::vector<AccelerationSegment> segments_;
  double period_ = 0, peak_ = 0, stroke_ = 0, peak_jerk_ = 0;
  bool constant_ = true;
  std::string kind_;
};

}  // namespace selfalign
