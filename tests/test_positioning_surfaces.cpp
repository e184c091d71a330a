// Tests for positioning_surfaces (Fig. 17): where accumulation occurs, the periods from entry
// to p = 0.99 and p = 0.999 are counted and compared with the paper's Sect. 7.3 statement
// ("at most 5 period times for p = 0.99, and at most 7 for p = 0.999"), an independent source,
// off the diagonal; on the diagonal y2'' = y3'' with the bound that the contraction of the stick
// positions gives (docs/accumulation.md).
#include <gtest/gtest.h>

#include <cmath>

#include "selfalign/analysis/positioning.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/friction/friction_field.hpp"

using namespace selfalign;

namespace {

constexpr double kPeriod = 1.0, kStroke = 0.084, kWidth = 0.05, kCMu = 2.5;  // Fig. 17

// On the diagonal a2 = a3 = a, an upper bound on the periods from entry to p, by hand
// (docs/accumulation.md, "Accumulation on the diagonal"): from a rest x_1 in [x_mu, c1) the
// distance s = c1 - x_n shrinks at least by ρ = h(s_max)/s_max per period, with
// h(s) = A - sqrt((A - λ s)^2 - (σ s)^2), λ = cos θ cosh(ω T3), σ = cos θ sinh(ω T3),
// A = a/b1, s_max = (a - 1)/b1; so 1 + ceil(ln(1 - p)/ln ρ) looks at rest reach p, the first
// within a period of entry, plus one period for an entry whose first slide back ends below x_mu.
int diagonal_periods_bound(double a, double p) {
  const ThreePhaseSolution r = solve_three_phase({kPeriod, kStroke, a, a});
  const double b1 = (kCMu - 1) / kWidth, omega = std::sqrt(b1);
  const double c = std::cos(omega * (r.t2 - r.t1));
  const double lambda = c * std::cosh(omega * (r.t3 - r.t2));
  const double sigma = c * std::sinh(omega * (r.t3 - r.t2));
  const double A = a / b1, s = (a - 1) / b1;
  const double h = A - std::sqrt((A - lambda * s) * (A - lambda * s) - sigma * sigma * s * s);
  const double rho = h / s;
  return 2 + static_cast<int>(std::ceil(std::log(1 - p) / std::log(rho)));
}

bool every_entry_proven(double a2, double a3) {
  if (!solve_three_phase({kPeriod, kStroke, a2, a3}).physical) return false;
  const TwoRegionTable table(0.0, kWidth, kCMu);  // the map is translation invariant
  const StickPositionMap map(ThreePhaseProfile({kPeriod, kStroke, a2, a3}), table);
  return map.accumulates_for_every_entry() == true;
}

}  // namespace

TEST(PositioningSurfaces, AccumulationReachesPNinetyNineInFiveAndPNineNineNineInSevenPeriods) {
  constexpr int n = 100;  // Fig. 17 setting: Δt = 1, Δy = 0.084, w = 0.05, c_mu = 2.5
  const std::vector<double> g = linear_grid(2.5 / n, 2.5, n);
  PositioningOptions o;
  o.entries = 50;
  o.stopping.max_periods = 300;
  const auto cells = positioning_surfaces(kPeriod, kStroke, kWidth, kCMu, g, g, o);
  int accumulating = 0, max99 = 0, max999 = 0, diagonal = 0;
  for (const PositioningCell& c : cells) {
    if (c.a2 == c.a3 && every_entry_proven(c.a2, c.a3)) {
      // Issue 9 / F03: the diagonal accumulates (it was reported as permanent stick).
      ++diagonal;
      EXPECT_GT(c.accumulating_entries, 0) << c.a2;
    }
    if (c.accumulating_entries == 0) continue;
    ++accumulating;
    EXPECT_GE(c.max_periods_p99, 1) << c.a2 << ", " << c.a3;
    EXPECT_GE(c.max_periods_p999, c.max_periods_p99) << c.a2 << ", " << c.a3;
    // (C) vs (D): where every entry accumulates, the positioning error vanishes.
    if (c.accumulates) EXPECT_EQ(c.dx_d, 0.0) << c.a2 << ", " << c.a3;
    if (c.a2 == c.a3) {
      EXPECT_LE(c.max_periods_p99, diagonal_periods_bound(c.a2, 0.99)) << c.a2;
      EXPECT_LE(c.max_periods_p999, diagonal_periods_bound(c.a2, 0.999)) << c.a2;
      continue;
    }
    max99 = std::max(max99, c.max_periods_p99);
    max999 = std::max(max999, c.max_periods_p999);
  }
  std::printf("[ fig 17 ] %d cells with accumulating entries; off the diagonal max periods "
              "p=0.99: %d, p=0.999: %d\n",
              accumulating, max99, max999);
  EXPECT_GT(accumulating, 100);
  EXPECT_GT(diagonal, 5);
  EXPECT_LE(max99, 5);
  EXPECT_LE(max999, 7);
}

TEST(PositioningSurfaces, DiagonalCellAccumulatesAndIsCounted) {
  // Issue 9 / F03: the cell (2.45, 2.45) accumulates from every entry (its stick positions
  // contract by 0.46 per period to x_stick,min), so it counts in the periods-to-p summary.
  PositioningOptions o;
  o.entries = 10;
  o.stopping.max_periods = 300;
  const auto cells = positioning_surfaces(kPeriod, kStroke, kWidth, kCMu, {2.45}, {2.45}, o);
  ASSERT_EQ(cells.size(), 1u);
  const PositioningCell& c = cells[0];
  EXPECT_TRUE(every_entry_proven(2.45, 2.45));
  EXPECT_TRUE(c.accumulates);
  EXPECT_EQ(c.accumulating_entries, 10);
  EXPECT_EQ(c.dx_d, 0.0);
  EXPECT_GE(c.max_periods_p99, 1);
  EXPECT_LE(c.max_periods_p99, diagonal_periods_bound(2.45, 0.99));
  EXPECT_GE(c.max_periods_p999, c.max_periods_p99);
  EXPECT_LE(c.max_periods_p999, diagonal_periods_bound(2.45, 0.999));
}
