#pragma once
/// \file piecewise_constant.hpp
/// A periodic table profile whose acceleration is piecewise constant: a periodic sequence of
/// second-order polynomials y(t) (the Fig. 3 style of Sect. 4.2), and the common form of every
/// profile the exact event-driven solver integrates.

#include <span>
#include <string>
#include <vector>

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

/// One constant-acceleration interval of a period, with the table state at its start [-].
struct AccelerationSegment {
  double begin;     ///< start time within the period, 0 <= begin < Δt [-]
  double duration;  ///< length of the segment as given (not a difference of begin times) [-]
  double accel;     ///< table acceleration y'' on the segment [-]
  double y;         ///< y at the segment start [-]
  double yd;        ///< y' at the segment start [-]
};

class PiecewiseConstantProfile final : public TableProfile {
 public:
  /// Builds the periodic profile with accelerations accels[i] held for durations[i] [-].
  /// Periodicity of y' needs sum(accels[i] durations[i]) = 0 (checked to 1e-12 relative to
  /// sum |accels[i]| durations[i]). The initial velocity is chosen so the mean velocity is zero
  /// (periodic y) and the initial position so min y = 0. Zero-length segments are dropped.
  /// Throws InvalidParameter on sizes that differ, negative or non-finite durations, a period
  /// outside [1e-50, 1e50], non-finite accelerations, a velocity that does not return, or a
  /// motion that overflows.
  static PiecewiseConstantProfile from_accelerations(std::span<const double> durations,
                                                     std::span<const double> accels,
                                                     std::string kind = "quadratic-sequence");

  double period() const override { return period_; }
  TableState state(double t) const override;
  double velocity(double t) const override;
  double peak_acceleration() const override { return peak_; }
  double stroke() const override { return stroke_; }
  std::string kind() const override { return kind_; }
  const PiecewiseConstantProfile* piecewise_constant() const override { return this; }

  std::span<const AccelerationSegment> segments() const noexcept { return segments_; }
  /// Index of the segment containing phase p in [0, Δt).
  std::size_t segment_at(double phase) const noexcept;
  /// Phase of t in [0, Δt).
  double phase(double t) const noexcept;

 private:
  PiecewiseConstantProfile() = default;
  std::vector<AccelerationSegment> segments_;
  double period_ = 0, peak_ = 0, stroke_ = 0;
  std::string kind_;
};

}  // namespace selfalign
