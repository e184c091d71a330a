// Tests for analysis/stick_position.hpp: eqs. (40)-(41) by hand, and the map (59) against the
// exact simulator's successive stick positions (a second method), Fig. 18 setting.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/simulate/exact.hpp"

using namespace selfalign;

namespace {
struct StopPositions final : ArcSink {
  std::vector<double> x;
  void on_arc(const Arc& a) override {
    if (a.end == ArcEnd::velocity_zero) x.push_back(a.x1);
  }
};
}  // namespace

TEST(StickPosition, MinimumIsEquationFortyOne) {
  const TwoRegionFriction f(0.2, 0.05, 2.5);
  EXPECT_NEAR(stick_position_min(f, 2.2), 0.2 + 0.05 * 1.2 / 1.5, 1e-15);
  EXPECT_EQ(stick_position_min(f, 0.7), 0.2);      // sticks anywhere
  EXPECT_TRUE(std::isinf(stick_position_min(f, 2.6)));  // beyond mu_2: never for good
  EXPECT_TRUE(sticks_permanently(f, 2.2, 0.25));
  EXPECT_FALSE(sticks_permanently(f, 2.2, 0.2 + 0.04 - 1e-9));
}

TEST(StickPosition, MapMatchesExactSuccessiveStickPositionsFigureEighteen) {
  const ThreePhaseProfile profile({1.05, 0.084, 2.2, 0.9});
  const TwoRegionFriction friction(0.3, 0.05, 2.5);
  const StickPositionMap map(profile, friction);
  const double x_stick_min = stick_position_min(friction, profile.peak_acceleration());
  // eq. (60) = eq. (41): two closed forms of one position; rounding only.
  EXPECT_NEAR(map.fixed_point(), x_stick_min, 1e-12);

  // Stuck at x_1 at t0; the exact solver's next stops are the map's iterates (eq. 59).
  const double x1 = 0.3 + 0.012;
  ASSERT_TRUE(map.proves_accumulation_from(x1));
  const ExactSetup setup{*profile.piecewise_constant(), *friction.piecewise_affine()};
  ExactState s = make_exact_state(setup, {0, x1, 0});
  StopPositions stops;
  advance_exact(setup, s, 6 * 1.05, &stops);
  ASSERT_EQ(stops.x.size(), 6u);  // one stop per period
  double x = x1;
  for (double exact : stops.x) {
    x = map(x);
    // Both evaluate the same harmonic arcs, one via events, one via eq. (59): 1e-10 (issue).
    EXPECT_NEAR(exact, x, 1e-10);
    EXPECT_LT(x, map.fixed_point());
  }
  // Slope at the fixed point, cos(sqrt(b1)(t2 - t1)), against a central difference of the map.
  const double h = 1e-6, c = map.fixed_point();
  EXPECT_NEAR((map(c + h) - map(c - h)) / (2 * h), map.slope_at_fixed_point(), 1e-6);
}

TEST(StickPosition, AccumulationForEveryEntryIsTheMapAtXMu) {
  // Sect. 7.3: x_{n+1}(x_mu) < x_stick,min <=> every entry accumulates; check the basin bound.
  const TwoRegionFriction friction(0.0, 0.05, 2.5);
  const ThreePhaseProfile accumulating({1.0, 0.084, 2.3, 1.3}), overshooting({1.0, 0.084, 1.8, 1.1});
  const StickPositionMap a(accumulating, friction), o(overshooting, friction);
  EXPECT_TRUE(a.accumulates_for_every_entry());
  EXPECT_LT(a(0.0), a.fixed_point());
  EXPECT_FALSE(o.accumulates_for_every_entry());
  EXPECT_LT(o.slope_at_fixed_point(), 0.0);  // cos(theta) < 0: iterates overshoot
  EXPECT_GT(o(0.5 * o.fixed_point()), o.fixed_point());
}
