// Tests for planar/planar_run.hpp, the run driver the CLI and Python share: its samples are the
// stepper's states stepped alone (the second method: advance_planar_rigid step by step), at
// t = 0, every `every` steps and at the last step; its census counts every step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/planar/planar_run.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;

TEST(PlanarRun, SamplesAreTheStepperStepByStep) {
  PlanarProblem p;
  p.motion.first = &kPaper;
  p.field = HalfPlaneStepField{0.05, 0.0, 0.3, 0.05, 3.0};
  p.part.patch = rectangle_patch(0.04, 0.02, 2, 2);
  p.options.step = 1.0 / 100;
  const long long steps = planar_steps_of_periods(p, 2);
  ASSERT_EQ(steps, 200);
  const long long every = 7;  // 200 is no multiple: the last step is a sample of its own
  std::vector<long long> done;
  const PlanarTrajectory r = simulate_planar(p, {0.0, 0.01, 0.2}, {0.05, 0.0, 0.0}, steps, every,
                                             [&done](long long d, long long) { done.push_back(d); });
  EXPECT_EQ(done, (std::vector<long long>{100, 200}));  // one report a period
  ASSERT_EQ(r.size(), 1u + 200 / 7 + 1);
  EXPECT_EQ(r.census.total(), steps);
  PlanarRigidState s = make_planar_rigid_state(p.motion, 0, {0.0, 0.01, 0.2}, {0.05, 0.0, 0.0});
  std::size_t sample = 0;
  for (long long k = 0; k <= steps; ++k) {
    if (k > 0) advance_planar_rigid(p.motion, p.field, p.law, p.part, p.options, s, 1);
    if (k % every != 0 && k != steps) continue;
    ASSERT_LT(sample, r.size());
    EXPECT_EQ(r.t[sample], s.t) << k;
    EXPECT_EQ(r.x[sample], s.pose.x) << k;
    EXPECT_EQ(r.y[sample], s.pose.y) << k;
    EXPECT_EQ(r.angle[sample], s.pose.angle) << k;
    EXPECT_EQ(r.omega[sample], s.twist.omega) << k;
    EXPECT_EQ(r.table_x[sample], s.table.x) << k;
    EXPECT_EQ(r.mode[sample], s.mode) << k;
    ++sample;
  }
  EXPECT_EQ(sample, r.size());
  EXPECT_EQ(r.end.pose.x, s.pose.x);
  EXPECT_THROW(simulate_planar(p, {}, {}, steps, 0), InvalidParameter);
  EXPECT_THROW(planar_steps_of_duration(p, 0.015), InvalidParameter);  // 1.5 steps
  PlanarProblem at_rest = p;
  at_rest.motion.first = nullptr;
  EXPECT_THROW(planar_steps_of_periods(at_rest, 1), InvalidParameter);
  EXPECT_EQ(planar_steps_of_duration(at_rest, 0.5), 50);
}

// method exact: the exact point solver's run at the samples' times. Second methods: on a table
// moving along x only, a part sliding along x is the 1-D problem, and the 1-D exact solver (a
// separate event-driven code, arcs in x alone) gives its samples to rounding (kSameArcs: a few
// ulps per arc over two periods); on a table moving along x and y, Moreau's run converges to it
// at first order (the error at h/4 is about a quarter of the error at h: the ratio within
// [2, 8], kFirstOrder).
TEST(PlanarRun, TheExactMethodIsTheExactPointSolversRun) {
  constexpr double kSameArcs = 1e-12;
  PlanarProblem p;
  p.motion.first = &kPaper;
  p.part.patch = point_patch();
  p.options.step = 1.0 / 100;
  const long long steps = planar_steps_of_periods(p, 2);
  const PlanarTrajectory exact =
      simulate_planar(p, {0.0, 0.0, 0.3}, {0.05, 0.0, 0.2}, steps, 9, {}, Method::exact);
  ASSERT_EQ(exact.size(), 1u + 200 / 9 + 1);
  EXPECT_EQ(exact.census.total(), 0);
  const UniformFriction uniform;
  const ExactSetup setup{*kPaper.piecewise_polynomial(), *uniform.piecewise_affine()};
  ExactState one = make_exact_state(setup, {0, 0.0, 0.05});
  int slipping = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    advance_exact(setup, one, exact.t[i]);
    EXPECT_NEAR(exact.x[i], one.object.x, kSameArcs) << i;
    EXPECT_NEAR(exact.ux[i], one.object.xd, kSameArcs) << i;
    EXPECT_EQ(exact.y[i], 0.0);
    EXPECT_EQ(exact.angle[i], 0.3 + 0.2 * exact.t[i]);  // no torque about a centred point
    EXPECT_EQ(exact.mode[i] == PatchMode::stick, exact.ux[i] == 0.0);
    slipping += exact.mode[i] == PatchMode::slip;
  }
  EXPECT_GT(slipping, 5);

  constexpr double kFirstOrderLow = 2, kFirstOrderHigh = 8;
  const ThreePhaseProfile across({1.0, 0.084, 3.0, 0.9});
  p.motion.second = &across;
  p.law = FrictionLaw(1.3, 1.0);
  double error[2];
  for (int j = 0; j < 2; ++j) {
    p.options.step = j == 0 ? 1.0 / 400 : 1.0 / 1600;
    const long long n = planar_steps_of_periods(p, 2);
    const PlanarTrajectory e = simulate_planar(p, {}, {0.1, -0.05, 0}, n, n / 8, {}, Method::exact);
    const PlanarTrajectory m = simulate_planar(p, {}, {0.1, -0.05, 0}, n, n / 8);
    ASSERT_EQ(e.size(), m.size());
    error[j] = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
      EXPECT_EQ(e.t[i], m.t[i]);
      error[j] = std::max({error[j], std::abs(e.x[i] - m.x[i]), std::abs(e.y[i] - m.y[i])});
    }
  }
  EXPECT_GT(error[0], 1e-6);  // Moreau is not exact
  EXPECT_GT(error[0] / error[1], kFirstOrderLow);
  EXPECT_LT(error[0] / error[1], kFirstOrderHigh);
  // Where it does not apply, the exact method is refused by name.
  p.part.patch = rectangle_patch(0.04, 0.02, 2, 2);
  try {
    simulate_planar(p, {}, {}, 10, 1, {}, Method::exact);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "method");
  }
}

}  // namespace
}  // namespace selfalign
