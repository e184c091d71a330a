// Tests for units.hpp: the scales of Sect. 3.2, computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/units.hpp"

using namespace selfalign;

TEST(Scales, TimeScaleIsSqrtOfLengthOverMuG) {
  // L = 2 mm, mu = 0.25, g = 9.81: T = sqrt(0.002 / 2.4525) = 0.028557... s (hand computation)
  const Scales s(2e-3, 0.25, 9.81);
  EXPECT_NEAR(s.time(), std::sqrt(0.002 / 2.4525), 1e-15);
  EXPECT_DOUBLE_EQ(s.acceleration(), 0.25 * 9.81);  // L/T^2 = mu g
  EXPECT_NEAR(s.velocity(), 2e-3 / std::sqrt(0.002 / 2.4525), 1e-15);
}

TEST(Scales, DimensionlessAccelerationIsAccelerationOverMuG) {
  const Scales s(1e-3, 0.3, 9.81);
  // A table acceleration of 2.943 m/s^2 = mu g is exactly the sticking limit |y''| = 1 (Sect. 3.2).
  EXPECT_NEAR(s.acceleration_from_si(2.943), 1.0, 1e-15);
}

TEST(Scales, RoundTripsEveryQuantity) {
  const Scales s(5e-3, 0.4, 9.80665);
  const double v = 0.123;
  EXPECT_NEAR(s.length_to_si(s.length_from_si(v)), v, 4e-16);  // two roundings of a 0.1-sized number
  EXPECT_NEAR(s.time_to_si(s.time_from_si(v)), v, 4e-16);  // two roundings of a 0.1-sized number
  EXPECT_NEAR(s.velocity_to_si(s.velocity_from_si(v)), v, 4e-16);  // two roundings of a 0.1-sized number
  EXPECT_NEAR(s.acceleration_to_si(s.acceleration_from_si(v)), v, 4e-16);
}

TEST(Scales, JerkScalesWithMuGOverT) {
  // L/T^3 = mu g / T (hand derivation from eq. 4), the Dimension::jerk of config files.
  const Scales s(2e-3, 0.25, 9.81);
  const double T = std::sqrt(0.002 / 2.4525);
  EXPECT_NEAR(s.jerk(), 2.4525 / T, 1e-12);  // ~86, a few roundings
  EXPECT_NEAR(s.jerk_to_si(2.0), 2 * 2.4525 / T, 1e-12);
  EXPECT_NEAR(s.jerk_from_si(s.jerk_to_si(0.123)), 0.123, 4e-16);  // two roundings
}

TEST(Scales, AbsentAndUnboundedValuesPassThrough) {
  // NaN (absent) stays NaN, +-inf (no jerk limit, accumulation) stays +-inf.
  const Scales s(1e-3, 0.3);
  const double inf = std::numeric_limits<double>::infinity();
  for (double (Scales::*f)(double) const noexcept :
       {&Scales::length_to_si, &Scales::time_to_si, &Scales::velocity_to_si,
        &Scales::acceleration_to_si, &Scales::jerk_to_si, &Scales::length_from_si,
        &Scales::time_from_si, &Scales::velocity_from_si, &Scales::acceleration_from_si,
        &Scales::jerk_from_si}) {
    EXPECT_TRUE(std::isnan((s.*f)(std::nan(""))));
    EXPECT_EQ((s.*f)(inf), inf);
    EXPECT_EQ((s.*f)(-inf), -inf);
  }
}

TEST(Scales, RejectsNonPositiveOrNaNInputsByName) {
  EXPECT_THROW(Scales(0, 0.3), InvalidParameter);
  EXPECT_THROW(Scales(1e-3, -0.3), InvalidParameter);
  try {
    Scales(1e-3, 0.3, std::nan(""));
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "g");
    EXPECT_EQ(e.allowed(), "must be > 0");
  }
}
