#pragma once
/// \file sampled.hpp
/// A user-supplied table profile: samples (t_i, y''_i) of one period, read from a CSV file,
/// interpolated piecewise-constant (then the exact solver applies) or piecewise-linear.
///
/// CSV format: one "t,y''" pair per line, in the same unit system as the rest of the input;
/// blank lines, lines starting with '#', and one leading header line are ignored. The first
/// time must be 0, times strictly increasing; the last time is the period Δt.
///   constant: y'' = y''_i on [t_i, t_{i+1}); the last sample's value is not used.
///   linear:   y'' interpolates linearly between samples.
/// The acceleration must integrate to zero over the period (1e-9 relative); the initial velocity
/// is chosen so that y is periodic, and the initial position so that min y = 0.

#include <memory>
#include <string>
#include <vector>

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

enum class Interpolation { constant, linear };

/// Parses "constant" or "linear"; throws InvalidParameter("interpolation", ...) otherwise.
Interpolation parse_interpolation(const std::string& text);

struct AccelerationSamples {
  std::vector<double> t;    ///< sample times [-] or [s]: t[0] = 0, strictly increasing
  std::vector<double> ydd;  ///< table accelerations at t [-] or [m/s^2]
};

/// Reads a samples CSV (a regular file of at most 256 MB, registered as the input --samples so
/// that no output replaces it: io/atomic_file.hpp). Throws InvalidParameter naming the file and
/// line on malformed input.
AccelerationSamples read_acceleration_samples(const std::string& path);

/// Builds the periodic profile from dimensionless samples. Throws InvalidParameter on fewer
/// than 2 samples, t[0] != 0, non-increasing or non-finite times, non-finite accelerations or a
/// non-zero net velocity change.
std::unique_ptr<TableProfile> make_sampled_profile(const AccelerationSamples& samples,
                                                   Interpolation interpolation);

/// Piecewise-linear acceleration (piecewise-cubic y). Built by make_sampled_profile.
class LinearAccelerationProfile final : public TableProfile {
 public:
  explicit LinearAccelerationProfile(const AccelerationSamples& samples);
  double period() const override { return t_.back(); }
  TableState state(double t) const override;
  double peak_acceleration() const override { return peak_; }
  double stroke() const override { return stroke_; }
  std::string kind() const override { return "samples-linear"; }
  /// The samples it was built from (rebuilds an equal profile).
  AccelerationSamples samples() const { return {t_, a_}; }

 private:
  std::vector<double> t_, a_, y_, yd_;  // knots, with y and y' at each knot
  double peak_ = 0, stroke_ = 0;
};

}  // namespace selfalign
