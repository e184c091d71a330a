// Issue 20 / F05: the steady-state search near the case-3/4 boundary of the three-phase
// profile, where the period map P(v) has a kink (stick on one side, slip-slip with slope
// λ2 = c4 on the other) within a hair of the fixed point. The search once stopped there on a
// residual of 2.5e-10 with a secant slope taken across the kink, 3.1e-9 and 5.8e-8 off, and
// reported an error 12x too small.
//
// Second method: plain iteration of the period map, v <- P(v), until v repeats (a fixed
// point in floating point) or its change stops shrinking (the map's rounding): it converges
// geometrically at rate λ from any start (Sect. 6.2) and passes no judgement on slopes. Its own
// error is the map's rounding over 1 - λ. The boundary is located by bisection on a3 of the
// paper's flow-chart rules (predict_case, docs/motion-cases.md); the scan places points at
// relative distances 1e-12 ... 1e-5 on both sides of it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/profiles/three_phase.hpp"

using namespace selfalign;

namespace {

// The acceptance: within 1e-10 of the second method.
constexpr double kAgreement = 1e-10;
// Plain iteration stops after this many periods at the latest (λ <= 0.99 here: 0.99^6000
// is far below the rounding).
constexpr int kPlainPeriods = 6000;

struct PlainFixedPoint {
  double v = 0, v_bar = 0;
};

PlainFixedPoint plain_iteration(const PeriodMap& map) {
  // Iterate until v repeats, or until the change |P(v) - v| has not reached a new low for
  // kPatience periods (the map's rounding); the iterate with the smallest change is the answer.
  constexpr int kPatience = 200;
  double v = 0, best_v = 0, best_change = std::numeric_limits<double>::infinity();
  for (int i = 0, since_best = 0; i < kPlainPeriods && since_best < kPatience; ++i) {
    const double next = map(0, v).xd;
    const double change = std::abs(next - v);
    if (change < best_change) best_change = change, best_v = v, since_best = 0;
    else ++since_best;
    if (change == 0) break;
    v = next;
  }
  return {best_v, map(0, best_v).x / map.period()};
}

// a3 on the case-3/4 boundary for the given period, stroke and a2 (bisection on the rules).
double boundary_a3(double period, double stroke, double a2, double lo, double hi) {
  auto is_slip_slip = [&](double a3) {
    return predict_case({period, stroke, a2, a3}) == StickSlipCase::slip_slip;
  };
  const bool lo_side = is_slip_slip(lo);
  EXPECT_NE(lo_side, is_slip_slip(hi));
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (is_slip_slip(mid) == lo_side ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(SteadyStateKink, ScanAroundTheCaseThreeFourBoundaryAgreesWithPlainIteration) {
  struct Base {
    double period, stroke, a2, a3_lo, a3_hi;
  };
  // Bracketing a3 intervals of the boundary found on a coarse grid of the rules; the first is
  // the F05 reproducer's profile.
  const std::array<Base, 7> bases{{{0.5032256074775499, 0.44172819403061003, 1532.362504331582,
                                    22.0, 26.0},
                                   {0.27, 0.53, 500.0, 125.0, 142.0},
                                   {0.5, 0.44, 100.0, 28.0, 32.0},
                                   {1.0, 0.5, 20.0, 8.9, 10.0},
                                   {0.3, 0.1, 100.0, 15.8, 17.8},
                                   {0.1, 0.01, 500.0, 12.5, 14.2},
                                   {1.0, 0.5, 500.0, 5.6, 6.4}}};
  int points = 0;
  for (const Base& b : bases) {
    const double a3_star = boundary_a3(b.period, b.stroke, b.a2, b.a3_lo, b.a3_hi);
    for (int e = -12; e <= -5; ++e) {
      for (int side : {-1, 1}) {
        const ThreePhaseProfile profile({b.period, b.stroke, b.a2,
                                         a3_star * (1 + side * std::pow(10.0, e))});
        const PeriodMap map(profile);
        const SteadyState s = steady_state(map);
        const PlainFixedPoint ref = plain_iteration(map);
        SCOPED_TRACE(::testing::Message() << "a2 " << b.a2 << " a3 " << profile.parameters().a3
                                        << " (boundary " << a3_star << ", offset " << side
                                        << "e" << e << ")");
        ASSERT_TRUE(s.converged);
        EXPECT_NEAR(s.x_dot_0s, ref.v, kAgreement);
        EXPECT_NEAR(s.v_bar, ref.v_bar, kAgreement);
        // The reported error bounds the true one: the reference is itself within the map's
        // rounding over 1 - λ of v* (λ from the saltation product at the reference).
        const double lambda = map.saltation_monodromy(0, ref.v)(1, 1);
        const double V = (profile.peak_acceleration() + 1) * profile.period();
        const double ref_error =
            std::numeric_limits<double>::epsilon() * (std::abs(ref.v) + V) / (1 - lambda);
        EXPECT_LE(std::abs(s.x_dot_0s - ref.v), s.x_dot_0s_error + ref_error);
        ++points;
      }
    }
  }
  EXPECT_GE(points, 100);
}

// The F05 reproducer's point, 7.7e-10 Δt from the kink, against its 50-digit reference (and
// three independent 1-D solvers, issue 20): v̄ = 1.4792267174654736, x'_0s =
// -0.24107251740577162. The search reported converged 3.1e-9 away with an error of 2.5e-10.
TEST(SteadyStateKink, ReproducerPointMatchesItsHighPrecisionReference) {
  const ThreePhaseProfile profile(
      {0.5032256074775499, 0.44172819403061003, 1532.362504331582, 23.871523695618414});
  const SteadyState s = steady_state(profile);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.motion_case, StickSlipCase::slip_slip);
  constexpr double kXDot = -0.24107251740577162, kVBar = 1.4792267174654736;
  EXPECT_NEAR(s.x_dot_0s, kXDot, kAgreement);
  EXPECT_NEAR(s.v_bar, kVBar, kAgreement);
  // The reference is exact to its last digit (1e-17): the reported error must cover the gap.
  EXPECT_LE(std::abs(s.x_dot_0s - kXDot), s.x_dot_0s_error);
}
