// Tests of design/*.hpp: constrained profile optimisation (Sect. 4.4.2, taken further).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/optimize.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace {
using namespace selfalign;

// Limits hold to rounding: the optimisers accept 1e-10 relative slack.
constexpr double kLimitTol = 1e-9;
// Stroke: rescaled exactly by the optimisers, then recomputed by the profile's own extrema.
constexpr double kStrokeTol = 1e-9;
// The Fourier optimiser's extrema grid has 32 N points per period (fourier_design.cpp);
// the independent check samples 10x finer.
constexpr int kCheckSamplesPerHarmonic = 320;

const ActuatorLimits kFig6{};  // Δt = 0.072, Δy = 0.021, y'_max = 3.2, y''_max = 1275

// Independent check of an optimum's limits: rebuilds the profile, samples y, y', y'' densely
// (plus the right limit of every sample for the piecewise-constant y'').
void expect_within_limits(const OptimizationResult& r, int samples) {
  ASSERT_TRUE(r.feasible) << r.message;
  const auto p = rebuild_profile(r);
  const ActuatorLimits& l = r.limits;
  EXPECT_NEAR(p->stroke(), l.stroke, kStrokeTol * l.stroke);
  EXPECT_NEAR(p->period(), l.period, 1e-15);
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin, vmax = 0, amax = 0;
  for (int i = 0; i <= samples; ++i) {
    const TableState s = p->state(l.period * i / samples);
    ymin = std::min(ymin, s.y);
    ymax = std::max(ymax, s.y);
    vmax = std::max(vmax, std::abs(s.yd));
    amax = std::max(amax, std::abs(s.ydd));
  }
  EXPECT_LE(vmax, l.max_velocity * (1 + kLimitTol)) << r.family;
  EXPECT_LE(amax, l.max_acceleration * (1 + kLimitTol)) << r.family;
  EXPECT_LE(ymax - ymin, l.stroke * (1 + kStrokeTol)) << r.family;
  // The stroke is reached: the sampled range is within O(h^2) of Δy.
  EXPECT_GT(ymax - ymin, l.stroke * (1 - 1e-4)) << r.family;
  // The reported extrema are those of the profile (sampling can only under-estimate them).
  EXPECT_LE(vmax, r.max_velocity * (1 + kLimitTol));
  EXPECT_LE(amax, r.max_acceleration * (1 + kLimitTol));
  // f and v̄ are consistent with eq. (11).
  EXPECT_GT(r.v_bar, 0);
  EXPECT_NEAR(r.f, objective_f(r.v_bar), 1e-12 * r.f);
}

OptimizationResult three_phase_fig6() {
  static const OptimizationResult r = optimize_three_phase(kFig6);
  return r;
}

TEST(Optimize, MisuseThrows) {
  ActuatorLimits bad = kFig6;
  bad.max_velocity = -1;
  EXPECT_THROW(optimize_three_phase(bad), InvalidParameter);
  bad = kFig6;
  bad.stroke = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(optimize_piecewise_constant(bad), InvalidParameter);
  bad = kFig6;
  bad.period = 0;
  EXPECT_THROW(optimize_fourier(bad), InvalidParameter);
  OptimizeOptions o;
  o.order = 0;
  EXPECT_THROW(optimize_fourier(kFig6, o), InvalidParameter);
  o = {};
  o.segments = 1;
  EXPECT_THROW(optimize_piecewise_constant(kFig6, o), InvalidParameter);
  o = {};
  o.starts = 0;
  EXPECT_THROW(compare_families(kFig6, o), InvalidParameter);
  o = {};
  o.fd_step = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(optimize_fourier(kFig6, o), InvalidParameter);
  OptimizationResult infeasible;
  infeasible.family = "fourier";
  EXPECT_THROW(rebuild_profile(infeasible), InvalidParameter);
  EXPECT_THROW(fourier_approximation(ThreePhaseProfile({1, 0.05, 2, 2}), 1), InvalidParameter);
}

TEST(Optimize, ThreePhaseOptimumIsFeasible) {
  const OptimizationResult r = three_phase_fig6();
  EXPECT_EQ(r.family, "three-phase");
  ASSERT_EQ(r.parameters.size(), 2u);
  EXPECT_LE(std::max(r.parameters[0], r.parameters[1]), kFig6.max_acceleration);
  expect_within_limits(r, 20'000);
}

// Independent check: a brute-force 300 x 300 uniform scan of (a2, a3) (the optimiser scans a
// 48 x 48 geometric grid and polishes) finds nothing better.
TEST(Optimize, ThreePhaseNotBeatenByFineScan) {
  const OptimizationResult r = three_phase_fig6();
  ASSERT_TRUE(r.feasible);
  const double s_max = kFig6.period * kFig6.period / (8 * kFig6.stroke);
  const int n = 300;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) {
      const double a2 = kFig6.max_acceleration * i / n, a3 = kFig6.max_acceleration * j / n;
      if (1 / a2 + 1 / a3 > s_max) continue;  // case 0
      const ThreePhaseProfile p({kFig6.period, kFig6.stroke, a2, a3});
      const ThreePhaseSolution& s = p.solution();
      const double swing = a2 * (s.t2 - s.t1);  // y'_max - y'_min
      if (std::max(s.yd_ini, swing - s.yd_ini) > kFig6.max_velocity) continue;
      const SteadyState st = steady_state(p);
      if (st.v_bar > 0) best = std::min(best, st.f);
    }
  EXPECT_LE(r.f, best * (1 + 1e-9)) << "brute force found " << best;
}

// The K-segment family contains the three-phase profile and starts from its optimum.
TEST(Optimize, PiecewiseConstantAtLeastAsGoodAsThreePhase) {
  const OptimizationResult three = three_phase_fig6();
  for (int k : {3, 4}) {
    OptimizeOptions o;
    o.segments = k;
    o.starts = 2;
    const OptimizationResult r = optimize_piecewise_constant(kFig6, o, &three);
    EXPECT_EQ(r.family, "piecewise-constant");
    ASSERT_EQ(r.parameters.size(), static_cast<std::size_t>(2 * k));
    EXPECT_LE(r.f, three.f * (1 + 1e-9)) << "K = " << k;
    expect_within_limits(r, 20'000);
  }
}

// Issue 9 / P02: the K-segment family contains every (K-1)-segment profile (split one segment
// in two), so its optimum cannot be worse; stroke 0.2, y''_max 6 once gave v̄ 0.340 for K = 3
// and 0.330 for K = 5. Each K starts, among its other starts, from the (K-1) optimum embedded;
// that start is the same profile up to rounding of its durations and accelerations (~1e-16
// relative), which moves v̄ by far less than kEmbedding = 1e-9 relative.
TEST(Optimize, PiecewiseConstantOptimumNeverFallsAsSegmentsAreAdded) {
  constexpr double kEmbedding = 1e-9;
  const ActuatorLimits limits{1.0, 0.2, 100.0, 6.0};
  double previous = 0;
  for (int k = 2; k <= 5; ++k) {
    OptimizeOptions o;
    o.segments = k;
    const OptimizationResult r = optimize_piecewise_constant(limits, o);
    ASSERT_TRUE(r.feasible) << "K = " << k << ": " << r.message;
    EXPECT_GE(r.v_bar, previous * (1 - kEmbedding)) << "K = " << k;
    expect_within_limits(r, 20'000);
    previous = r.v_bar;
  }
}

// The M-segment approximation against time-stepping's v̄ (h = Δt/4000, O(h) with an erratic
// constant, docs/time-stepping.md): agreement at the 1e-3 level; and the approximation itself
// converges in M (O(1/M^2) in the table velocity).
TEST(Optimize, FourierApproximationMatchesTimeStepping) {
  std::vector<double> a, b;
  const ThreePhaseProfile three({kFig6.period, kFig6.stroke, 1000, 80});
  fourier_series_of(*three.piecewise_polynomial(), 6, a, b);
  const FourierProfile p(kFig6.period, a, b);
  const SteadyState approx = approximate_steady_state(p, 256);
  const SteadyState fine = approximate_steady_state(p, 1024);
  const SteadyState stepped = steady_state(p);  // the Fourier profile itself: exact since issue 11
  ASSERT_EQ(stepped.method, Method::exact);
  ASSERT_TRUE(approx.converged && stepped.converged);
  ASSERT_GT(approx.v_bar, 0);
  EXPECT_NEAR(approx.v_bar, stepped.v_bar, 2e-3 * std::abs(stepped.v_bar));
  EXPECT_NEAR(approx.v_bar, fine.v_bar, 1e-3 * std::abs(fine.v_bar));
  // Node velocities of the approximation are those of the profile.
  const PiecewisePolynomialProfile pc = fourier_approximation(p, 256);
  for (int i = 0; i < 256; i += 17)
    EXPECT_NEAR(pc.velocity(kFig6.period * i / 256), p.velocity(kFig6.period * i / 256), 1e-9);
}

// Issue target: the 12th-order optimum reaches f <= 5.6e-4 at the Fig. 6 setting (the
// paper's "f = 56" read as 5.6e-4).
TEST(Optimize, FourierOrder12ReachesPaperTarget) {
  OptimizeOptions o;
  o.starts = 1;  // the three-phase start alone reaches the target (sanitizer build: keep small)
  int calls = 0, last = 0;
  o.progress = [&](int done, int total) {  // (0, 1) while the run is under way, then (1, 1)
    ++calls;
    EXPECT_LE(done, total);
    EXPECT_GE(done, last);
    last = done;
  };
  const OptimizationResult r = optimize_fourier(kFig6, o, nullptr);
  EXPECT_GE(calls, 1);
  EXPECT_EQ(last, 1);
  EXPECT_EQ(r.family, "fourier");
  ASSERT_EQ(r.parameters.size(), 24u);
  EXPECT_LE(r.f, 5.6e-4);
  EXPECT_LE(r.f, three_phase_fig6().f * (1 + 1e-9));  // one start is the three-phase optimum
  expect_within_limits(r, kCheckSamplesPerHarmonic * o.order);
}

TEST(Optimize, InfeasibleLimitsAreReported) {
  ActuatorLimits slow = kFig6;
  slow.max_velocity = 0.1;  // the stroke needs a mean |y'| of 2 Δy / Δt = 0.58
  OptimizeOptions o;
  o.starts = 1;
  o.order = 3;
  o.max_evaluations = 300;
  for (const OptimizationResult& r : compare_families(slow, o)) {
    EXPECT_FALSE(r.feasible) << r.family;
    EXPECT_NE(r.message.find("max_velocity"), std::string::npos) << r.message;
  }
  ActuatorLimits weak = kFig6;
  weak.max_acceleration = 10;  // below 2 / s_max = 16 Δy / Δt^2 = 64.8
  const OptimizationResult r = optimize_three_phase(weak, o);
  EXPECT_FALSE(r.feasible);
  EXPECT_NE(r.message.find("max_acceleration"), std::string::npos) << r.message;
}

TEST(Optimize, CompareFamiliesOneRowEach) {
  OptimizeOptions o;
  o.starts = 1;
  o.order = 4;
  o.max_evaluations = 1000;
  const auto rows = compare_families(kFig6, o);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].family, "three-phase");
  EXPECT_EQ(rows[1].family, "piecewise-constant");
  EXPECT_EQ(rows[2].family, "fourier");
  for (const auto& r : rows) {
    EXPECT_TRUE(r.feasible) << r.family << ": " << r.message;
    EXPECT_GT(r.evaluations, 0);
  }
  EXPECT_LE(rows[1].f, rows[0].f * (1 + 1e-9));
}

}  // namespace

// The Fourier optimiser's gradient stencils run on worker threads, each point warm-started
// from the stencil's centre: the result must not depend on the thread count (bit for bit).
TEST(Optimize, FourierResultDoesNotDependOnTheThreadCount) {
  OptimizeOptions o;
  o.order = 4;
  o.starts = 2;
  o.max_evaluations = 200;  // a short run: enough stencils to race if anything were shared
  o.threads = 1;
  const OptimizationResult serial = optimize_fourier(kFig6, o, nullptr);
  o.threads = 2;
  const OptimizationResult parallel = optimize_fourier(kFig6, o, nullptr);
  ASSERT_EQ(serial.feasible, parallel.feasible);
  EXPECT_EQ(serial.parameters, parallel.parameters);
  EXPECT_EQ(serial.f, parallel.f);
  EXPECT_EQ(serial.evaluations, parallel.evaluations);
  o.threads = -1;
  EXPECT_THROW(optimize_fourier(kFig6, o, nullptr), InvalidParameter);
}
