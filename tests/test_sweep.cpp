// Tests for analysis/sweep.hpp: determinism across thread counts, grids, profile families.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"

using namespace selfalign;

TEST(Sweep, IdenticalBytesWithOneAndTwoThreads) {
  const std::vector<double> g = linear_grid(0.1, 3.0, 40);
  SweepOptions one, two;
  one.threads = 1;
  two.threads = 2;
  std::size_t calls = 0, last = 0;
  two.progress = [&](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_GE(done, last);
    EXPECT_EQ(total, g.size() * g.size());
    last = done;
  };
  const auto a = sweep_accelerations(1.0, 0.084, g, g, one);
  const auto b = sweep_accelerations(1.0, 0.084, g, g, two);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(AccelerationCell)), 0);
  EXPECT_GT(calls, 0u);
  EXPECT_EQ(last, g.size() * g.size());
  EXPECT_EQ(a[0].a2, 0.1);  // row-major, a2 outer
  EXPECT_EQ(a[1].a3, g[1]);
}

TEST(Sweep, GridsHitTheirEnds) {
  const auto lin = linear_grid(1, 2, 5);
  EXPECT_EQ(lin.front(), 1.0);
  EXPECT_EQ(lin.back(), 2.0);
  EXPECT_DOUBLE_EQ(lin[2], 1.5);
  const auto lg = log_grid(1, 1275, 200);
  EXPECT_EQ(lg.front(), 1.0);
  EXPECT_EQ(lg.back(), 1275.0);
  EXPECT_NEAR(lg[1] / lg[0], lg[199] / lg[198], 1e-12);
  EXPECT_THROW(log_grid(0, 1, 3), InvalidParameter);
  EXPECT_THROW(linear_grid(0, 1, 0), InvalidParameter);
}

TEST(Sweep, ScaledShapeFamilyHasTheRequestedPeriodAndStroke) {
  const ScaledShapeFamily family = ScaledShapeFamily::paper_like();
  const auto p = family.make(0.05, 0.02);
  ASSERT_NE(p, nullptr);
  EXPECT_NEAR(p->period(), 0.05, 1e-15);
  EXPECT_NEAR(p->stroke(), 0.02, 1e-15);
  const auto points = sweep_stroke(family, 0.05, {0.01, 0.02, 0.04});
  for (const FamilyPoint& pt : points) EXPECT_TRUE(pt.physical);
  // Fig. 5's trend for this family: a larger stroke moves the object faster (smaller f).
  EXPECT_GT(points[0].f, points[1].f);
  EXPECT_GT(points[1].f, points[2].f);
}

TEST(Sweep, ThreePhaseFamilyReportsCaseZeroAsNonPhysical) {
  const ThreePhaseFamily family(0.5, 0.5);
  const auto pts = sweep_period(family, 0.084, {1.0, 3.0});
  EXPECT_FALSE(pts[0].physical);  // 1/0.5 + 1/0.5 = 4 > 1/(8 0.084)
  EXPECT_TRUE(std::isnan(pts[0].f));
  EXPECT_TRUE(pts[1].physical);   // 4 <= 9/(8 0.084) = 13.4
}

TEST(Sweep, ScaledFourierFamilyScalesTheStrokeAndUsesTimeStepping) {
  const ScaledFourierFamily family({0.0, 0.2}, {1.0, 0.0, 0.1});
  const auto p = family.make(0.072, 0.021);
  EXPECT_NEAR(p->stroke(), 0.021, 1e-14);
  EXPECT_EQ(p->piecewise_constant(), nullptr);
  SweepOptions o;
  o.steady.steps_per_period = 2000;
  const auto pts = sweep_period(family, 0.021, {0.072}, o);
  EXPECT_TRUE(pts[0].physical);
  EXPECT_TRUE(std::isfinite(pts[0].v_bar));
}
