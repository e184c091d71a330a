// Tests for units.hpp: the scales of Sect. 3.2, computed by hand.
#include <gtest/gtest.h>

#include <cmath>

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
