#pragma once
/// \file fourier.hpp
/// A Fourier-series table profile of any order N (Sect. 4.4.2):
///   y(t) = c_0 + sum_{k=1..N} ( A_k cos(k w t) + B_k sin(k w t) ),   w = 2 pi / Δt,
/// with c_0 chosen so that min y = 0. Periodic in y and y' by construction.

#include <array>
#include <string>
#include <vector>

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

class FourierProfile final : public TableProfile, public SmoothMotion {
 public:
  /// \param period  Δt [-], in [1e-50, 1e50]
  /// \param cos_coeffs A_1..A_N [-], \param sin_coeffs B_1..B_N [-] (shorter one padded with 0),
  ///        finite, not all zero, N <= 1000. Throws InvalidParameter otherwise, and when the
  ///        motion is not finite (a period so short that (N w)^2 A_N overflows).
  FourierProfile(double period, std::vector<double> cos_coeffs, std::vector<double> sin_coeffs);

  /// Extrema of y (before the offset c_0) and of |y''| over the period, known to the caller.
  struct KnownExtrema {
    double y_min;              ///< min of sum_k (A_k cos + B_k sin) over the period [-]
    double y_max;              ///< max of the same sum [-], > y_min
    double peak_acceleration;  ///< max |y''| over the period [-], >= 0
  };
  /// The profile of the constructor without its O(N^2) extrema search (128 N samples refined by
  /// bisection), for a caller that already has the extrema (the Fourier optimiser computes them
  /// for its constraints): c_0 = -y_min, stroke() = y_max - y_min, peak_acceleration() as given.
  /// The coefficients are validated as by the constructor (finite, not all zero, N <= 1000);
  /// the extrema must be finite with y_max > y_min and peak_acceleration >= 0 (InvalidParameter
  /// otherwise) but are not checked against the coefficients: their accuracy is the caller's.
  static FourierProfile with_extrema(double period, std::vector<double> cos_coeffs,
                                     std::vector<double> sin_coeffs, const KnownExtrema& extrema);

  double period() const override { return period_; }
  TableState state(double t) const override;
  double peak_acceleration() const override { return peak_; }
  double stroke() const override { return stroke_; }
  std::string kind() const override { return "fourier"; }
  const SmoothMotion* smooth() const override { return this; }
  /// sum_k (k w)^3 sqrt(A_k^2 + B_k^2) and sum_k (k w)^4 sqrt(A_k^2 + B_k^2): bounds of |y^(3)|
  /// and |y^(4)| [-].
  double jerk_bound() const override { return jerk_bound_; }
  double snap_bound() const override { return snap_bound_; }
  /// sum_k (k w)^5 sqrt(A_k^2 + B_k^2) [-].
  double fifth_derivative_bound() const override { return fifth_bound_; }
  const FourierProfile* fourier_series() const override { return this; }

  int order() const noexcept { return static_cast<int>(cos_.size()); }
  const std::vector<double>& cos_coeffs() const noexcept { return cos_; }
  const std::vector<double>& sin_coeffs() const noexcept { return sin_; }
  double offset() const noexcept { return offset_; }  ///< c_0 [-]

  /// y and its first three derivatives at t [-], in one O(N) pass: cos/sin of k w t by the
  /// rotation recurrence (re-seeded every 16 harmonics), on the phase of t in [0, Δt).
  std::array<double, 4> derivatives(double t) const override;

 private:
  struct Unsampled {};
  /// Validates the coefficients and sets the jerk and snap bounds; offset, stroke and peak
  /// are left to the caller.
  FourierProfile(Unsampled, double period, std::vector<double> cos_coeffs,
                 std::vector<double> sin_coeffs);

  double period_;
  std::vector<double> cos_, sin_;
  double offset_ = 0, peak_ = 0, stroke_ = 0, jerk_bound_ = 0, snap_bound_ = 0, fifth_bound_ = 0;
};

}  // namespace selfalign
