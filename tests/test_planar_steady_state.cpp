// Tests for planar/planar_steady_state.hpp: the planar steady state as a fixed point of the
// period map, against second methods: the 1-D exact steady state (a point part on a table
// moving along x is the 1-D problem, eq. 10), plain iteration of the exact point solver to
// convergence (the same physics without the search), and Moreau's stepper at a fine step.

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "planar_profiles.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/planar/planar_steady_state.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;

// A cross motion along y whose period (0.5) divides the paper profile's (1.0).
const ThreePhaseProfile kCrossHalf({0.5, 0.02, 2.5, 1.5});

PlanarProblem point_problem(const TableProfile* x, const TableProfile* y) {
  PlanarProblem p;
  p.motion.first = x;
  p.motion.second = y;
  p.law = FrictionLaw(1.2, 1.0);
  p.part.patch = point_patch();
  p.options.step = 1.0 / 2000;
  return p;
}

// Both exact: the fixed point and the second method agree to their tolerances (1e-13 relative)
// times the conditioning of the slip phases; 1e-10 is the bound.
constexpr double kExactTol = 1e-10;

TEST(PlanarSteadyState, PointOnAnXMotionIsTheOneDimensionalSteadyState) {
  const PlanarProblem p = point_problem(&kPaper, nullptr);
  const PlanarSteadyState s = planar_steady_state(p, {}, {});
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.method, Method::exact);
  EXPECT_FALSE(s.level_changed);
  const SteadyState one_d = steady_state(kPaper, FrictionLaw(1.2, 1.0));
  ASSERT_TRUE(one_d.converged);
  EXPECT_NEAR(s.drift_x, one_d.v_bar, kExactTol);
  EXPECT_NEAR(s.twist_0s.ux, one_d.x_dot_0s, kExactTol);
  EXPECT_EQ(s.drift_y, 0.0);
  EXPECT_EQ(s.rotation_rate, 0.0);
}

TEST(PlanarSteadyState, PointOnATwoAxisMotionAgreesWithPlainIterationOfTheExactSolver) {
  const PlanarProblem p = point_problem(&kPaper, &kCrossHalf);
  const PlanarSteadyState s = planar_steady_state(p, {}, {0.05, -0.02, 0});
  ASSERT_TRUE(s.converged);
  ASSERT_EQ(s.method, Method::exact);
  // Plain iteration from rest for many periods (the response is unique: Sect. 6.2 in 1-D; here
  // every period contains a stick, which resets the velocity exactly), then one more period.
  PlanarExactState q{0, 0, 0, 0, 0};
  const UniformPlanarField field;
  const int n = 200;
  advance_planar_exact_point(p.motion, field, p.law, q, n * 1.0);
  const double x0 = q.x, y0 = q.y;
  advance_planar_exact_point(p.motion, field, p.law, q, (n + 1) * 1.0);
  EXPECT_NEAR(s.drift_x, q.x - x0, kExactTol);
  EXPECT_NEAR(s.drift_y, q.y - y0, kExactTol);
  EXPECT_NEAR(s.twist_0s.ux, q.ux, kExactTol);
  EXPECT_NEAR(s.twist_0s.uy, q.uy, kExactTol);
  EXPECT_GT(std::hypot(s.drift_x, s.drift_y), 1e-3);  // it walks: not a trivial rest
}

TEST(PlanarSteadyState, MoreauConvergesToTheExactFixedPoint) {
  // The same problem with the point part on a field the exact solver does not take (a friction
  // step far behind the part: uniform along its path), so the rigid part's Moreau stepper runs.
  PlanarProblem p = point_problem(&kPaper, &kCrossHalf);
  const PlanarSteadyState exact = planar_steady_state(p, {}, {});
  ASSERT_TRUE(exact.converged);
  p.field = HalfPlaneStepField{-1e6, 0, M_PI, 1.0, 2.5};  // rises towards -x, far away
  double previous = HUGE_VAL;
  for (const double h : {1.0 / 1000, 1.0 / 8000}) {
    p.options.step = h;
    const PlanarSteadyState moreau = planar_steady_state(p, {}, {});
    ASSERT_TRUE(moreau.converged) << h;
    EXPECT_EQ(moreau.method, Method::time_stepping);
    EXPECT_FALSE(moreau.level_changed);
    const double error =
        std::hypot(moreau.drift_x - exact.drift_x, moreau.drift_y - exact.drift_y);
    EXPECT_LT(error, 2 * h) << h;  // Moreau's first order, as in 1-D (time_stepping.hpp)
    EXPECT_LT(error, previous) << h;
    previous = error;
  }
}

TEST(PlanarSteadyState, APartThatWalksIntoARoughRegionReportsTheChangeNotADrift) {
  // A disc walking along +x towards a rough half-plane from x = 0.4 on (s c_mu = 3.6 > the peak
  // |y''| = 3: it is held there). The fixed point on the smooth region is reached at
  // once (a stick resets the twist: e = 0 after two periods), far from the step: that drift is
  // a true steady state there, the 1-D v̄, and the level never changed.
  PlanarProblem p = point_problem(&kPaper, nullptr);
  p.part.patch = disc_patch(0.05, 2, 6);
  p.part.inertia = 0.05 * 0.05 / 2;
  p.field = HalfPlaneStepField{0.4, 0, 0, 0.05, 3.0};
  const PlanarSteadyState smooth = planar_steady_state(p, {}, {});
  ASSERT_TRUE(smooth.converged);
  EXPECT_FALSE(smooth.level_changed);
  EXPECT_LT(smooth.end_pose.x, 0.4 - 0.05);
  // Moreau (h = 1/2000) against the 1-D exact v̄: measured 2e-5, first order in h.
  EXPECT_NEAR(smooth.drift_x, steady_state(kPaper, FrictionLaw(1.2, 1.0)).v_bar, 0.2 * p.options.step);
  // After a transient of 10 periods (0.84 of travel) the part has entered: the result says
  // the level changed, and the steady state it finds is the one in the rough region, at rest.
  PlanarSteadyStateOptions o;
  o.transient_periods = 10;
  const PlanarSteadyState s = planar_steady_state(p, {}, {}, o);
  EXPECT_TRUE(s.level_changed);
  EXPECT_NEAR(s.level_min, 1.0, 1e-12);
  EXPECT_GT(s.level_max, 3.6 / 1.2 / 1.2);  // far enough in to hold: s m >= 3
  EXPECT_LE(s.level_max, 3.0);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.drift_x, 0.0);  // held: every step sticks, the pose stays exactly (planar_rigid.hpp)
  EXPECT_EQ(s.drift_y, 0.0);
  EXPECT_GT(s.end_pose.x, 0.4);
}

TEST(PlanarSteadyState, BadOptionsNameTheParameter) {
  const PlanarProblem p = point_problem(&kPaper, nullptr);
  PlanarSteadyStateOptions o;
  o.max_periods = 0;
  EXPECT_THROW(planar_steady_state(p, {}, {}, o), InvalidParameter);
  o = {};
  o.tolerance = -1;
  EXPECT_THROW(planar_steady_state(p, {}, {}, o), InvalidParameter);
  o = {};
  o.transient_periods = -1;
  EXPECT_THROW(planar_steady_state(p, {}, {}, o), InvalidParameter);
}

}  // namespace
}  // namespace selfalign
