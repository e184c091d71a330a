// Tests for analysis/sweep.hpp: determinism across thread counts, grids, profile families.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

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
  for (std::size_t k = 0; k < a.size(); ++k) {  // bit for bit, field by field
    EXPECT_EQ(std::memcmp(&a[k].v_bar, &b[k].v_bar, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a[k].f, &b[k].f, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a[k].x_dot_0s, &b[k].x_dot_0s, sizeof(double)), 0);
    EXPECT_EQ(a[k].predicted, b[k].predicted);
    EXPECT_EQ(a[k].observed, b[k].observed);
    EXPECT_EQ(a[k].converged, b[k].converged);
    EXPECT_EQ(a[k].failure, b[k].failure);
  }
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
  EXPECT_EQ(p->piecewise_polynomial(), nullptr);
  SweepOptions o;
  o.steady.steps_per_period = 2000;
  const auto pts = sweep_period(family, 0.021, {0.072}, o);
  EXPECT_TRUE(pts[0].physical);
  EXPECT_TRUE(std::isfinite(pts[0].v_bar));
}

// Issue 9, F01: one cell that cannot be computed never aborts a study; it carries its own
// failure and NaN numbers, and every other cell is computed as usual.
namespace {
class FailsAtOnePeriod final : public ProfileFamily {
 public:
  explicit FailsAtOnePeriod(double bad) : bad_(bad) {}
  std::unique_ptr<TableProfile> make(double period, double stroke) const override {
    if (period == bad_) throw InvalidParameter("period", period, "refused by this test family");
    return ThreePhaseFamily(2.3, 1.3).make(period, stroke);
  }
  std::string name() const override { return "fails-at-one-period"; }

 private:
  double bad_;
};
}  // namespace

TEST(Sweep, AFailingCellGetsItsOwnStatusAndTheOthersAreComputed) {
  const std::vector<double> periods{1.0, 1.1, 1.2};  // all physical for (2.3, 1.3), Δy = 0.084
  for (int threads : {1, 2}) {
    SweepOptions o;
    o.threads = threads;
    const auto points = sweep_period(FailsAtOnePeriod(1.1), 0.084, periods, o);
    ASSERT_EQ(points.size(), 3u);
    EXPECT_NE(points[1].failure.find("refused by this test family"), std::string::npos);
    EXPECT_TRUE(std::isnan(points[1].v_bar));
    EXPECT_TRUE(std::isnan(points[1].f));
    // The neighbours are the plain three-phase results (second route: the family directly).
    const auto plain = sweep_period(ThreePhaseFamily(2.3, 1.3), 0.084, periods, o);
    for (std::size_t k : {0u, 2u}) {
      EXPECT_TRUE(points[k].failure.empty());
      EXPECT_TRUE(std::isfinite(points[k].v_bar));
      EXPECT_EQ(points[k].v_bar, plain[k].v_bar);
    }
  }
}

// Issue 9, D02/D15: a worker count beyond the cores is capped (oneTBB crashed on 1e9 and
// warned on stderr for more workers than cores); negative counts are misuse.
TEST(Sweep, WorkerThreadsAreCappedAtTheCores) {
  const int cores = worker_threads(0);
  EXPECT_GE(cores, 1);
  EXPECT_EQ(worker_threads(1), 1);
  EXPECT_EQ(worker_threads(1'000'000'000), cores);
  EXPECT_THROW(worker_threads(-1), InvalidParameter);
  SweepOptions o;
  o.threads = 1'000'000'000;
  const auto cells = sweep_accelerations(1.0, 0.084, {2.3}, {1.3}, o);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_TRUE(cells[0].failure.empty());
  SweepOptions one;
  one.threads = 1;
  EXPECT_EQ(cells[0].v_bar, sweep_accelerations(1.0, 0.084, {2.3}, {1.3}, one)[0].v_bar);
}

// Issue 9, D13: linear_grid(1e308, 1, 3) ended in -inf ((hi - lo) * 2 overflowed).
TEST(Sweep, GridsNearTheLargestDoublesStayFiniteAndExact) {
  const auto g = linear_grid(1e308, 1.0, 3);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g.front(), 1e308);
  EXPECT_EQ(g.back(), 1.0);
  EXPECT_NEAR(g[1], 0.5e308, 1e292);  // the midpoint, to rounding of 1e308
  const auto h = linear_grid(-1.7e308, 1.7e308, 5);
  for (double v : h) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(h[2], 0.0);
  EXPECT_THROW(linear_grid(0, 1, 10'000'001), InvalidParameter);  // beyond 1e7 points
}
