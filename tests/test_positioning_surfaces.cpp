// Tests for positioning_surfaces (Fig. 17): where accumulation occurs, the periods from entry
// to p = 0.99 and p = 0.999 are counted and compared with the paper's Sect. 7.3 statement
// ("at most 5 period times for p = 0.99, and at most 7 for p = 0.999"), an independent source.
#include <gtest/gtest.h>

#include <cmath>

#include "selfalign/analysis/positioning.hpp"

using namespace selfalign;

TEST(PositioningSurfaces, AccumulationReachesPNinetyNineInFiveAndPNineNineNineInSevenPeriods) {
  constexpr int n = 100;  // Fig. 17 setting: Δt = 1, Δy = 0.084, w = 0.05, c_mu = 2.5
  const std::vector<double> g = linear_grid(2.5 / n, 2.5, n);
  PositioningOptions o;
  o.entries = 50;
  o.stopping.max_periods = 300;
  const auto cells = positioning_surfaces(1.0, 0.084, 0.05, 2.5, g, g, o);
  int accumulating = 0, max99 = 0, max999 = 0;
  for (const PositioningCell& c : cells) {
    if (c.accumulating_entries == 0) continue;
    ++accumulating;
    EXPECT_GE(c.max_periods_p99, 1) << c.a2 << ", " << c.a3;
    EXPECT_GE(c.max_periods_p999, c.max_periods_p99) << c.a2 << ", " << c.a3;
    max99 = std::max(max99, c.max_periods_p99);
    max999 = std::max(max999, c.max_periods_p999);
    // (C) vs (D): where every entry accumulates, the positioning error vanishes.
    if (c.accumulates) EXPECT_EQ(c.dx_d, 0.0) << c.a2 << ", " << c.a3;
  }
  std::printf("[ fig 17 ] %d cells with accumulating entries; max periods p=0.99: %d, p=0.999: %d\n",
              accumulating, max99, max999);
  EXPECT_GT(accumulating, 100);
  EXPECT_LE(max99, 5);
  EXPECT_LE(max999, 7);
}
