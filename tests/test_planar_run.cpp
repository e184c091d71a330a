// Tests for planar/planar_run.hpp, the run driver the CLI and Python share: its samples are the
// stepper's states stepped alone (the second method: advance_planar_rigid step by step), at
// t = 0, every `every` steps and at the last step; its census counts every step.

#include <gtest/gtest.h>

#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/planar_run.hpp"

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

}  // namespace
}  // namespace selfalign
