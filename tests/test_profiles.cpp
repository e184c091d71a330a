// Tests for the other profile families: piecewise-constant sequences, Fourier series, samples.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/sampled.hpp"

using namespace selfalign;

TEST(PiecewisePolynomialProfile, SymmetricBangBangByHand) {
  // y'' = +1 on [0, 1), -1 on [1, 3), +1 on [3, 4): y' starts at 0 and is a triangle wave with
  // mean 0; y(t) = t^2/2 on [0, 1] ... a hand-drawn parabola chain with min y = 0 at t = 0 and
  // max at t = 2: y(2) = 0.5 + 0.5 = 1. Stroke 1, peak acceleration 1.
  const double d[3] = {1, 2, 1}, a[3] = {1, -1, 1};
  const auto p = PiecewisePolynomialProfile::from_accelerations(d, a);
  EXPECT_DOUBLE_EQ(p.period(), 4.0);
  EXPECT_NEAR(p.stroke(), 1.0, 1e-15);
  EXPECT_NEAR(p.state(0).y, 0.0, 1e-15);
  EXPECT_NEAR(p.state(0).yd, 0.0, 1e-15);
  EXPECT_NEAR(p.state(2).y, 1.0, 1e-15);
  EXPECT_NEAR(p.state(1).yd, 1.0, 1e-15);
  EXPECT_NEAR(p.state(6).y, 1.0, 1e-14);  // periodic extension
  EXPECT_NEAR(p.state(-2).y, 1.0, 1e-14);
  EXPECT_EQ(p.peak_acceleration(), 1.0);
}

TEST(PiecewisePolynomialProfile, RejectsVelocityThatDoesNotReturn) {
  const double d[2] = {1, 1}, a[2] = {1, -0.9};
  EXPECT_THROW(PiecewisePolynomialProfile::from_accelerations(d, a), InvalidParameter);
  const double neg[2] = {-1, 1}, ok[2] = {1, -1};
  EXPECT_THROW(PiecewisePolynomialProfile::from_accelerations(neg, ok), InvalidParameter);
}

// D32: a gap between breakpoints too short for its acceleration change (jerk beyond 1e50) is the
// later breakpoint's, not the accelerations' ("accels[0]" before).
TEST(PiecewisePolynomialProfile, BreakpointsTooCloseNameTheTime) {
  const double t[2] = {0, 5e-324}, a[2] = {1, -1}, period = 1;
  try {
    PiecewisePolynomialProfile::from_breakpoints(t, a, period);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "times[1]");
    EXPECT_NE(std::string(e.allowed()).find("too close to times[0] = 0"), std::string::npos);
  }
  const double wide[2] = {0, 0.5};
  EXPECT_NO_THROW(PiecewisePolynomialProfile::from_breakpoints(wide, a, period));
  const double nan_a[2] = {1, std::nan("")};
  try {
    PiecewisePolynomialProfile::from_breakpoints(wide, nan_a, period);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "accelerations[1]");
  }
}

TEST(FourierProfile, SingleHarmonicByHand) {
  // y = c0 + A cos(w t): min y = 0 gives c0 = A, stroke 2A, peak |y''| = A w^2.
  const double A = 0.01, P = 0.5, w = 2 * std::numbers::pi / P;
  const FourierProfile f(P, {A}, {});
  EXPECT_NEAR(f.offset(), A, 1e-15);
  EXPECT_NEAR(f.stroke(), 2 * A, 1e-15);
  EXPECT_NEAR(f.peak_acceleration(), A * w * w, 1e-12);
  const TableState s = f.state(0.1);
  EXPECT_NEAR(s.y, A + A * std::cos(w * 0.1), 1e-15);
  EXPECT_NEAR(s.yd, -A * w * std::sin(w * 0.1), 1e-14);
  EXPECT_NEAR(s.ydd, -A * w * w * std::cos(w * 0.1), 1e-12);
}

TEST(FourierProfile, TwoHarmonicsExtremaAreBoundedNotSampled) {
  // y = sin(wt) + 0.5 sin(2wt): y' = w (cos x + cos 2x) = 0 at cos x = 1/2 (x = pi/3):
  // max y = sin(pi/3) + 0.5 sin(2pi/3) = 3 sqrt(3)/4, min = -3 sqrt(3)/4.
  const FourierProfile f(1.0, {}, {1.0, 0.5});
  EXPECT_NEAR(f.stroke(), 1.5 * std::sqrt(3.0), 1e-13);
  EXPECT_THROW(FourierProfile(1.0, {0.0}, {0.0}), InvalidParameter);
}

TEST(SampledProfile, ReadsCsvAndInterpolates) {
  const std::string path = testing::TempDir() + "/samples.csv";
  {
    std::ofstream out(path);
    out << "t,ydd\n# comment\n0,1\n1,-1\n3,1\n4,1\n";
  }
  const AccelerationSamples s = read_acceleration_samples(path);
  ASSERT_EQ(s.t.size(), 4u);
  const auto c = make_sampled_profile(s, Interpolation::constant);
  ASSERT_NE(c->piecewise_polynomial(), nullptr);  // the exact solver applies
  EXPECT_NEAR(c->stroke(), 1.0, 1e-15);         // same as SymmetricBangBangByHand
  // Linear: y'' = 1 - t on [0, 2], t - 3 on [2, 4] -> integral 0. Check y' increments by hand:
  const AccelerationSamples lin{{0, 2, 4}, {1, -1, 1}};
  const auto l = make_sampled_profile(lin, Interpolation::linear);
  EXPECT_EQ(l->piecewise_polynomial(), nullptr);
  EXPECT_NEAR(l->state(0.5).ydd, 0.5, 1e-15);
  EXPECT_NEAR(l->state(1.0).yd - l->state(0.0).yd, 0.5, 1e-15);  // integral of 1 - t on [0, 1]
  EXPECT_NEAR(l->state(4.0).yd, l->state(0.0).yd, 1e-14);
  std::remove(path.c_str());
}

TEST(SampledProfile, RejectsMalformedInput) {
  const std::string path = testing::TempDir() + "/bad.csv";
  {
    std::ofstream out(path);
    out << "t,ydd\n0,1\n1,abc\n";
  }
  EXPECT_THROW(read_acceleration_samples(path), InvalidParameter);
  EXPECT_THROW(read_acceleration_samples(path + ".missing"), InvalidParameter);
  EXPECT_THROW(make_sampled_profile({{0.5, 1}, {1, -1}}, Interpolation::constant), InvalidParameter);
  EXPECT_THROW(make_sampled_profile({{0, 1, 1}, {1, -1, 0}}, Interpolation::constant),
               InvalidParameter);
  EXPECT_THROW(parse_interpolation("cubic"), InvalidParameter);
  std::remove(path.c_str());
}

// Issue 9, D20: the series is summed with the rotation recurrence (two trigonometric calls per
// 16 harmonics). Second method: cos/sin of every harmonic, written out here, at order 300 (18
// re-seeds; the construction's extrema search is O(N^2), so a higher order only costs time).
// Tolerance: the recurrence's rounding grows like k eps between re-seeds (16 eps), times the
// sum of |terms|; 1e-12 of that sum is three orders above it.
TEST(FourierProfile, HighOrderMatchesTheDirectSumOfEveryHarmonic) {
  const int order = 300;
  std::vector<double> a(order), b(order);
  for (int k = 0; k < order; ++k) {
    a[static_cast<std::size_t>(k)] = 1e-3 * std::cos(0.7 * k) / (k + 1);
    b[static_cast<std::size_t>(k)] = 1e-3 * std::sin(1.3 * k) / (k + 1);
  }
  const FourierProfile f(2.0, a, b);
  const double w = std::numbers::pi;  // 2 pi / Δt
  for (double t : {0.0, 0.123, 0.5, 1.0, 1.777, 3.3}) {
    double y = f.offset(), yd = 0, ydd = 0, y_scale = 0, yd_scale = 0, ydd_scale = 0;
    for (int k = 0; k < order; ++k) {
      const double kw = (k + 1) * w, c = std::cos(kw * t), s = std::sin(kw * t);
      const double ak = a[static_cast<std::size_t>(k)], bk = b[static_cast<std::size_t>(k)];
      y += ak * c + bk * s;
      yd += kw * (-ak * s + bk * c);
      ydd -= kw * kw * (ak * c + bk * s);
      y_scale += std::abs(ak) + std::abs(bk);
      yd_scale += kw * (std::abs(ak) + std::abs(bk));
      ydd_scale += kw * kw * (std::abs(ak) + std::abs(bk));
    }
    const TableState st = f.state(t);
    constexpr double kRecurrenceTol = 1e-12;
    EXPECT_NEAR(st.y, y, kRecurrenceTol * y_scale) << t;
    EXPECT_NEAR(st.yd, yd, kRecurrenceTol * yd_scale) << t;
    EXPECT_NEAR(st.ydd, ydd, kRecurrenceTol * ydd_scale) << t;
  }
}

// Issue 9, D13, D20: an order beyond 1000, or a period so short that the motion overflows
// (FourierProfile(1e-320, ...) had stroke NaN), is misuse.
TEST(FourierProfile, RefusesOrdersBeyondAThousandAndOverflowingPeriods) {
  EXPECT_THROW(FourierProfile(1.0, std::vector<double>(1001, 1e-6), {}), InvalidParameter);
  try {
    FourierProfile(1e-320, {0.04}, {0.0});
    FAIL() << "an overflowing motion was accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "period");
  }
}

// Issue 11: with_extrema takes the extrema the caller already has instead of searching them.
// y = sin(wt) + 0.5 sin(2wt) has min/max -+3 sqrt(3)/4 (TwoHarmonicsExtremaAreBoundedNotSampled)
// and |y''| = w^2 |sin x + 2 sin 2x|, largest at cos x = (-1 + sqrt(129))/16 (d/dx = 0).
TEST(FourierProfile, WithExtremaTakesTheGivenExtremaAndValidatesLikeTheConstructor) {
  const double w = 2 * std::numbers::pi, y_max = 0.75 * std::sqrt(3.0);
  const double x = std::acos((-1 + std::sqrt(129.0)) / 16);
  const double peak = w * w * (std::sin(x) + 2 * std::sin(2 * x));
  const FourierProfile searched(1.0, {}, {1.0, 0.5});
  const FourierProfile given = FourierProfile::with_extrema(
      1.0, {}, {1.0, 0.5}, {.y_min = -y_max, .y_max = y_max, .peak_acceleration = peak});
  EXPECT_EQ(given.order(), 2);
  EXPECT_DOUBLE_EQ(given.offset(), y_max);
  EXPECT_DOUBLE_EQ(given.stroke(), 2 * y_max);
  EXPECT_DOUBLE_EQ(given.peak_acceleration(), peak);
  EXPECT_NEAR(searched.peak_acceleration(), peak, 1e-12 * peak);  // the by-hand peak is right
  EXPECT_DOUBLE_EQ(given.jerk_bound(), searched.jerk_bound());
  EXPECT_DOUBLE_EQ(given.snap_bound(), searched.snap_bound());
  for (double t : {0.0, 0.1, 0.37, 0.9}) {
    const std::array<double, 4> a = given.derivatives(t), b = searched.derivatives(t);
    EXPECT_NEAR(a[0], b[0], 1e-13) << t;  // offsets differ by the constructor's search only
    for (std::size_t d = 1; d < 4; ++d) EXPECT_EQ(a[d], b[d]) << t;
  }
  const FourierProfile::KnownExtrema ok{.y_min = -1, .y_max = 1, .peak_acceleration = 1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(FourierProfile::with_extrema(1.0, {0.0}, {0.0}, ok), InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(1.0, {nan}, {}, ok), InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(1.0, std::vector<double>(1001, 1e-6), {}, ok),
               InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(0.0, {1.0}, {}, ok), InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(1.0, {1.0}, {}, {.y_min = 1, .y_max = 1,
                                                             .peak_acceleration = 1}),
               InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(1.0, {1.0}, {}, {.y_min = nan, .y_max = 1,
                                                             .peak_acceleration = 1}),
               InvalidParameter);
  EXPECT_THROW(FourierProfile::with_extrema(1.0, {1.0}, {}, {.y_min = -1, .y_max = 1,
                                                             .peak_acceleration = -1}),
               InvalidParameter);
}

// The capability queries that replace casts (issue 21): each family answers for itself only,
// and the three-phase family's factory (make_three_phase_profile.hpp) picks the family by the
// jerk limit. A jerk-limited profile is never "the paper's three-phase profile", even at a
// jerk so high that its ramps vanish below the rounding of t: the analytic Floquet matrix and
// eq. (59) are written for jumps.
TEST(ProfileCapabilities, EachFamilyAnswersForItselfOnly) {
  const selfalign::ThreePhaseParameters p{1.0, 0.084, 3.0, 0.9};
  const auto jumps = selfalign::make_three_phase_profile(p, std::numeric_limits<double>::infinity());
  const auto ramps = selfalign::make_three_phase_profile(p, 1e9);
  ASSERT_NE(jumps->three_phase(), nullptr);
  EXPECT_EQ(jumps->three_phase()->parameters().a2, 3.0);
  EXPECT_EQ(jumps->kind(), "three-phase");
  EXPECT_EQ(ramps->three_phase(), nullptr);
  EXPECT_EQ(ramps->kind(), "jerk-limited-three-phase");
  EXPECT_NE(ramps->piecewise_polynomial(), nullptr);
  const selfalign::FourierProfile fourier(1.0, {0.01}, {0.02});
  EXPECT_EQ(fourier.three_phase(), nullptr);
  EXPECT_EQ(fourier.piecewise_polynomial(), nullptr);
  ASSERT_NE(fourier.smooth(), nullptr);
  EXPECT_EQ(fourier.smooth()->fourier_series(), &fourier);
  // Case 0 is refused by the factory as by the constructors (1/a2 + 1/a3 > Δt^2/(8 Δy)).
  EXPECT_FALSE(selfalign::three_phase_is_physical({1.0, 0.084, 1.0, 1.0}, 1e9));
  EXPECT_FALSE(selfalign::three_phase_is_physical({1.0, 0.084, 1.0, 1.0},
                                                  std::numeric_limits<double>::infinity()));
  EXPECT_THROW(selfalign::make_three_phase_profile({1.0, 0.084, 1.0, 1.0}, 1e9),
               selfalign::InvalidParameter);
}
