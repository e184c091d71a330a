// Tests for core/model.hpp, core/state.hpp, core/step.hpp: the contact core's runtime-sized
// model of N bodies on one table. Without part-part contact the bodies are independent, so each
// must move bit for bit as advance_planar_rigid moves it alone (the second method: the
// one-body stepper the planar analyses have used since issue 13): 1, 2 and 5 bodies with
// different patches, inertias, laws, poses and twists, on a table moving along x and y over a
// field with a rough pocket (the bodies cross its band).

#include <gtest/gtest.h>

#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;
const ThreePhaseProfile kHalf({0.5, 0.02, 2.5, 1.5});  // along y; its period divides 1.0

struct Start {
  core::Body body;
  PlanarPose pose;
  PlanarTwist twist;
};

std::vector<Start> starts() {
  std::vector<Start> s;
  s.push_back({{{0.01, point_patch()}, FrictionLaw(1.2, 1.0)}, {0.0, 0.0, 0.0}, {}});
  s.push_back({{{0.05 * 0.05 / 2, disc_patch(0.05, 2, 6)}, FrictionLaw(1.5, 1.0)},
               {0.3, 0.1, 0.2}, {0.1, -0.05, 0.5}});
  s.push_back({{{0.02, rectangle_patch(0.2, 0.1, 3, 2)}, FrictionLaw(1.0, 1.0)},
               {-0.2, 0.0, 1.0}, {0.0, 0.2, -1.0}});
  s.push_back({{{0.01, disc_patch(0.03, 1, 5)}, FrictionLaw(2.0, 1.0)}, {0.45, -0.1, 0.0}, {}});
  s.push_back({{{0.03, rectangle_patch(0.1, 0.1, 2, 2)}, FrictionLaw(1.3, 1.0)},
               {0.1, 0.3, -0.4}, {-0.1, 0.0, 0.0}});
  return s;
}

TEST(ContactCore, EveryBodyOfAnNBodyModelMovesBitForBitAsAlone) {
  const PlanarField field = RectangularPocketField{0.6, 0.0, 0.0, 0.2, 0.3, 0.1, 2.5};
  const TimeSteppingOptions options{1.0 / 1000, 0.5};
  PlanarTableMotion motion;
  motion.first = &kPaper;
  motion.second = &kHalf;
  const long long steps = 3000;  // three periods
  const std::vector<Start> all = starts();
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{5}}) {
    core::Model model{motion, field, {}, options};
    std::vector<PlanarPose> poses;
    std::vector<PlanarTwist> twists;
    for (std::size_t i = 0; i < n; ++i) {
      model.bodies.push_back(all[i].body);
      poses.push_back(all[i].pose);
      twists.push_back(all[i].twist);
    }
    core::State state = core::make_state(model, 0.0, poses, twists);
    ASSERT_EQ(core::step(model, state, steps), steps);
    ASSERT_EQ(state.status, core::StepStatus::ok);
    for (std::size_t i = 0; i < n; ++i) {
      PlanarRigidState alone = make_planar_rigid_state(motion, 0.0, poses[i], twists[i]);
      advance_planar_rigid(motion, field, all[i].body.law, all[i].body.part, options, alone,
                           steps);
      const core::BodyState& b = state.bodies[i];
      SCOPED_TRACE(::testing::Message() << n << " bodies, body " << i);
      EXPECT_EQ(b.pose.x, alone.pose.x);
      EXPECT_EQ(b.pose.y, alone.pose.y);
      EXPECT_EQ(b.pose.angle, alone.pose.angle);
      EXPECT_EQ(b.twist.ux, alone.twist.ux);
      EXPECT_EQ(b.twist.uy, alone.twist.uy);
      EXPECT_EQ(b.twist.omega, alone.twist.omega);
      EXPECT_EQ(b.mode, alone.mode);
      EXPECT_EQ(b.sweeps, alone.sweeps);
    }
    EXPECT_EQ(state.t, 3.0);
  }
}

TEST(ContactCore, BadModelsAndStatesNameTheParameter) {
  PlanarTableMotion motion;
  motion.first = &kPaper;
  core::Model model{motion, UniformPlanarField{}, {}, {1.0 / 1000, 0.5}};
  const std::vector<PlanarPose> none;
  const std::vector<PlanarTwist> no_twist;
  EXPECT_THROW(core::make_state(model, 0, none, no_twist), InvalidParameter);
  model.bodies.push_back({{0.0, point_patch()}, {}});  // zero inertia
  const std::vector<PlanarPose> one{{}};
  const std::vector<PlanarTwist> one_twist{{}};
  try {
    core::make_state(model, 0, one, one_twist);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "bodies[0].inertia");
  }
  model.bodies[0].part.inertia = 0.01;
  EXPECT_THROW(core::make_state(model, 0, none, one_twist), InvalidParameter);  // poses
  core::State s = core::make_state(model, 0, one, one_twist);
  model.bodies.push_back(model.bodies[0]);
  EXPECT_THROW(core::step(model, s, 1), InvalidParameter);  // a state of another model
}

}  // namespace
}  // namespace selfalign
