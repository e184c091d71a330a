// Tests for analysis/three_phase_steady_state.hpp: the closed-form steady state of the
// three-phase profile (docs/three-phase-steady-state.md) against the fixed-point search of the
// exact solver (a second method: periods simulated event by event, then bracketed), on every
// cell of grids that hold all of cases 0-5, under the paper's law and two other Coulomb laws;
// its slope against the finite-difference monodromy of the period map; a hand-computed case 4.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/analysis/three_phase_steady_state.hpp"
#include "selfalign/error.hpp"

using namespace selfalign;

namespace closed_form_test {

// Agreement of the closed form with the search, relative to 1 + |value|. The search certifies
// x'_0s to velocity_tol = 1e-13 (its bracket); its event times and the period's displacement
// carry the rounding of a few dozen arcs, amplified where a slip ends at a shallow rate (rate
// ratios up to (y'' + k)/k ~ 1e3 on the log plane). The largest difference seen on these grids
// is 3e-13 (v̄) and 5e-13 (x'_0s); 1e-10 leaves a margin of 200 and is still far below any
// modelling effect (a mis-derived formula errs by O(1e-3) or more, tested by the hand value).
constexpr double kClosedFormAgreement = 1e-10;

struct Plane {
  const char* name;
  double period, stroke, lo, hi;
  bool log;
};

constexpr Plane kPlanes[] = {
    {"(1, 0.084) over (0, 3]^2", 1.0, 0.084, 3.0 / 60, 3.0, false},
    {"(2, 0.084) over (0, 3]^2", 2.0, 0.084, 3.0 / 60, 3.0, false},
    {"(0.072, 0.021) over [1, 1275]^2 log", 0.072, 0.021, 1.0, 1275.0, true},
};

// A cell straddles a case boundary when the closed form's case is not the same at the four
// corners of the cell (half a grid step each way, geometric on log grids): there a response
// may stick for a vanishing time, and the two methods may see different sides of the boundary.
bool straddles(const Plane& pl, const FrictionLaw& law, double a2, double a3, double step) {
  auto lo = [&](double v) { return pl.log ? v / std::sqrt(step) : v - step / 2; };
  auto hi = [&](double v) { return pl.log ? v * std::sqrt(step) : v + step / 2; };
  const StickSlipCase c = three_phase_steady_state({pl.period, pl.stroke, a2, a3}, law).motion_case;
  for (double x : {lo(a2), hi(a2)})
    for (double y : {lo(a3), hi(a3)})
      if (x > 0 && y > 0 &&
          three_phase_steady_state({pl.period, pl.stroke, x, y}, law).motion_case != c)
        return true;
  return false;
}

double scaled_difference(double a, double b) { return std::abs(a - b) / (1 + std::abs(b)); }

}  // namespace closed_form_test

using namespace closed_form_test;

TEST(ThreePhaseSteadyState, AgreesWithTheSearchOnEveryCellOfThreePlanesAndThreeLaws) {
  constexpr int n = 60;
  const FrictionLaw laws[] = {FrictionLaw{}, FrictionLaw(1.3, 1.0), FrictionLaw(1.2, 1.0, 0.7)};
  for (const FrictionLaw& law : laws) {
    std::array<int, 6> seen{};
    for (const Plane& pl : kPlanes) {
      SCOPED_TRACE(std::string(pl.name) + ", law " + law.describe());
      const std::vector<double> g =
          pl.log ? log_grid(pl.lo, pl.hi, n) : linear_grid(pl.lo, pl.hi, n);
      const double step =
          pl.log ? std::pow(pl.hi / pl.lo, 1.0 / (n - 1)) : (pl.hi - pl.lo) / (n - 1);
      SweepOptions search;
      search.law = law;
      search.closed_form = false;
      SweepOptions closed = search;
      closed.closed_form = true;
      const auto searched = sweep_accelerations(pl.period, pl.stroke, g, g, search);
      const auto formula = sweep_accelerations(pl.period, pl.stroke, g, g, closed);
      double worst_v = 0, worst_x0 = 0;
      int case_differences = 0;
      for (std::size_t k = 0; k < formula.size(); ++k) {
        const AccelerationCell &c = formula[k], &s = searched[k];
        ++seen[static_cast<int>(c.observed)];
        ASSERT_TRUE(c.failure.empty() && s.failure.empty()) << c.failure << s.failure;
        EXPECT_EQ(c.predicted, s.predicted);
        if (s.predicted == StickSlipCase::non_physical) {
          EXPECT_EQ(c.observed, StickSlipCase::non_physical);
          EXPECT_TRUE(std::isnan(c.v_bar) && std::isnan(c.f) && std::isnan(c.x_dot_0s));
          EXPECT_FALSE(c.converged);
          continue;
        }
        ASSERT_TRUE(s.converged && c.converged);
        worst_v = std::max(worst_v, scaled_difference(c.v_bar, s.v_bar));
        worst_x0 = std::max(worst_x0, scaled_difference(c.x_dot_0s, s.x_dot_0s));
        if (c.observed != s.observed) {
          ++case_differences;
          EXPECT_TRUE(straddles(pl, law, c.a2, c.a3, step))
              << "a2 " << c.a2 << " a3 " << c.a3 << ": closed form case "
              << static_cast<int>(c.observed) << ", search " << static_cast<int>(s.observed);
        }
      }
      EXPECT_LE(worst_v, kClosedFormAgreement);
      EXPECT_LE(worst_x0, kClosedFormAgreement);
      RecordProperty(std::string("worst_v_bar ") + pl.name + " " + law.describe(),
                     std::to_string(worst_v));
      std::printf("%s, %s: worst |dv| %.2e, |dx0| %.2e, case differences %d\n", pl.name,
                  law.describe().c_str(), worst_v, worst_x0, case_differences);
    }
    for (int c = 0; c <= 5; ++c) EXPECT_GT(seen[c], 0) << "case " << c << " under " << law.describe();
  }
}

// docs/three-phase-steady-state.md, "A case 4 by hand": Δt = 1, Δy = 0.084, y2'' = 1.1,
// y3'' = 2.3 under the paper's law.
TEST(ThreePhaseSteadyState, SlipSlipMatchesTheHandComputation) {
  const double a = 1.1, b = 2.3;
  const ThreePhaseParameters p{1.0, 0.084, a, b};
  const ThreePhaseSolution r = solve_three_phase(p);
  // The profile by hand (docs/three-phase-profile.md): s = 1/a + 1/b, G = sqrt(2 s Δy) / Δt,
  // u = 1 - sqrt(1 - 2G), D = u Δt / s.
  const double s_inv = 1 / a + 1 / b, G = std::sqrt(2 * s_inv * 0.084),
               u = 1 - std::sqrt(1 - 2 * G);
  const double D = u / s_inv, T1 = 1 - u, T2 = D / a, T3 = D / b;
  ASSERT_NEAR(r.t1, T1, 1e-15);
  // One period from backward speed w at t1, written out for these numbers: v' = a + 1 = 2.1
  // while v < 0 on [t1, t2], a - 1 = 0.1 after it crosses 0; from t2, -(1 + b) = -3.3 down to
  // 0, then -(b - 1) = -1.3; +1 on [t0, t1] (a backward slip decelerating).
  const double w = (1.3 * T3 - T1 - 1.3 * 0.1 * T2 / 3.3) / (1 - 0.13 / (2.1 * 3.3));
  const double s1 = w / 2.1, w2 = 0.1 * (T2 - s1), s2 = w2 / 3.3, w3 = 1.3 * (T3 - s2);
  ASSERT_GT(w, 0);
  ASSERT_NEAR(w3 - T1, w, 1e-14);  // periodic: back to -w at t1
  const double x = -(w3 + w) * T1 / 2 - w * s1 / 2 + w2 * (T2 - s1) / 2 + w2 * s2 / 2 -
                   w3 * (T3 - s2) / 2;
  const ThreePhaseSteadyState cf = three_phase_steady_state(p);
  EXPECT_EQ(cf.motion_case, StickSlipCase::slip_slip);
  EXPECT_NEAR(cf.x_dot_0s, -w3, 1e-14);
  EXPECT_NEAR(cf.displacement, x, 1e-14);
  EXPECT_NEAR(cf.v_bar, x, 1e-14);  // Δt = 1
  EXPECT_NEAR(cf.slope, 0.13 / 6.93, 1e-15);  // eq. (32): (a-1)(b-1)/((a+1)(b+1))
  EXPECT_NEAR(cf.f, 1 / (1e4 * x * x), 1e-12 * cf.f);
}

// The slope is dP/dv of the period map at the fixed point: c4 (eq. 32) in slip-slip, 0 where
// the steady state sticks. Second method: central finite differences of the exact period map.
TEST(ThreePhaseSteadyState, SlopeIsTheFiniteDifferenceMonodromy) {
  struct Case {
    double a2, a3;
    FrictionLaw law;
  };
  // cases 4, 4 (direction-dependent law), 3, 1, 2 (static > kinetic)
  const Case cases[] = {{1.1, 2.3, {}},  {1.5, 3.0, FrictionLaw(1.2, 1.0, 0.7)},
                        {2.3, 1.3, {}},  {3.0, 0.95, {}},
                        {0.95, 3.0, FrictionLaw(1.3, 1.0)}};
  // h: the map is piecewise affine, so the difference is exact up to rounding / h (1e-16/1e-6)
  // as long as the kinks stay further than h from the fixed point.
  constexpr double h = 1e-6, kSlopeTol = 1e-8;
  for (const Case& c : cases) {
    const ThreePhaseParameters p{1.0, 0.084, c.a2, c.a3};
    const ThreePhaseSteadyState cf = three_phase_steady_state(p, c.law);
    const ThreePhaseProfile profile(p);
    const PeriodMap map(profile, c.law);
    const double fd = map.finite_difference_monodromy(0.0, cf.x_dot_0s, h)(1, 1);
    EXPECT_NEAR(cf.slope, fd, kSlopeTol) << c.a2 << ", " << c.a3 << ", " << c.law.describe();
    // and x'_0s is the map's fixed point
    EXPECT_NEAR(map(0.0, cf.x_dot_0s).xd, cf.x_dot_0s, 1e-13) << c.a2 << ", " << c.a3;
  }
}

TEST(ThreePhaseSteadyState, NonPhysicalProfileIsCaseZeroWithNaNs) {
  const ThreePhaseSteadyState s = three_phase_steady_state({1.0, 0.084, 0.2, 0.2});
  EXPECT_EQ(s.motion_case, StickSlipCase::non_physical);
  EXPECT_TRUE(std::isnan(s.v_bar) && std::isnan(s.f) && std::isnan(s.x_dot_0s) &&
              std::isnan(s.displacement) && std::isnan(s.slope));
}

TEST(ThreePhaseSteadyState, RefusesVelocityDependentLawsAndBadParameters) {
  const FrictionLaw stribeck = FrictionLaw(1.2, 1.0).with_stribeck(0.1);
  EXPECT_FALSE(three_phase_closed_form_applies(stribeck));
  EXPECT_TRUE(three_phase_closed_form_applies(FrictionLaw(1.2, 1.0, 0.8)));
  try {
    three_phase_steady_state({1.0, 0.084, 2.0, 2.0}, stribeck);
    FAIL() << "no throw";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("law"), std::string::npos) << e.what();
  }
  EXPECT_THROW(three_phase_steady_state({1.0, 0.084, -2.0, 2.0}), InvalidParameter);
  // A sweep under a velocity-dependent law searches instead (the closed form does not apply).
  SweepOptions o;
  o.law = FrictionLaw(1.2, 1.0).with_stribeck(0.5);
  const auto cells = sweep_accelerations(1.05, 0.084, {2.2}, {0.9}, o);
  EXPECT_TRUE(cells[0].failure.empty() && cells[0].converged);
}
