// Tests for the contact core's loads stage (core::Gravity in core/model.hpp): gravity on an
// inclined table and the table's normal motion, for the 1-D part (SliderBody) and rigid parts
// alike. Expected values are closed forms by hand (model units: accelerations in units of
// mu_1 g, so gravity is g = 1 / mu_1; the friction level 1 is mu_1 times the weight):
//  * on a still incline a part at rest slides iff g sin(a) > s m cos(a), then with the constant
//    acceleration g sin(a) - k m cos(a): Moreau's theta = 1/2 scheme is exact for it
//    (v = a t, x = a t^2 / 2);
//  * under a normal motion z(t) a sliding part loses k m (h + Δz'/g) of velocity per step, so
//    v(t) = v0 - k m (t + (z'(t) - z'(0)) / g) while it slides, the normal vibration averaging
//    out over a whole period;
//  * the bodies lift off in the first step whose normal impulse h + Δz'/g is negative.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/profiles/fourier.hpp"

namespace selfalign {
namespace {

// A table that does not move in its plane.
class Still final : public TableProfile {
 public:
  double period() const override { return 1.0; }
  TableState state(double) const override { return {0, 0, 0}; }
  double peak_acceleration() const override { return 0; }
  double stroke() const override { return 0; }
  std::string kind() const override { return "still"; }
};
const Still kStill;

// Rounding over a thousand steps of O(1) numbers.
constexpr double kSteps = 1e-12;

// A slider, a rigid point part and a rigid rectangle (symmetric: it translates) on a uniform
// level m: they move alike on a translating table.
core::Model three_parts(double m, const FrictionLaw& law) {
  core::Model model;
  model.motion.first = &kStill;
  model.field = UniformPlanarField{m};
  model.options = {1.0 / 1000, 0.5};
  model.bodies = {core::SliderBody{PointFootprint{}, law}, core::RigidBody{{0.01, point_patch()}, law},
                  core::RigidBody{{0.02, rectangle_patch(0.2, 0.1, 3, 2)}, law}};
  return model;
}

core::State at_rest(const core::Model& model, double v0 = 0) {
  const std::vector<PlanarPose> poses(3);
  const std::vector<PlanarTwist> twists(3, PlanarTwist{v0, 0, 0});
  return core::make_state(model, 0.0, poses, twists);
}

TEST(CoreLoads, OnAStillInclineAPartSlidesAtGSinMinusKMCos) {
  const double g = 2.0, incline = 0.6, m = 0.5;
  const FrictionLaw law(1.2, 1.0);
  core::Model model = three_parts(m, law);
  model.gravity = core::Gravity{g, incline, 1, 0};
  ASSERT_GT(g * std::sin(incline), 1.2 * m * std::cos(incline));  // it slides
  const double a = g * std::sin(incline) - 1.0 * m * std::cos(incline);
  core::State s = at_rest(model);
  ASSERT_EQ(core::step(model, s, 1000), 1000);
  ASSERT_EQ(s.status, core::StepStatus::ok);
  for (std::size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(::testing::Message() << "body " << i);
    EXPECT_NEAR(s.bodies[i].twist.ux, a * s.t, kSteps);
    EXPECT_NEAR(s.bodies[i].pose.x, 0.5 * a * s.t * s.t, kSteps);
    EXPECT_NEAR(s.bodies[i].pose.y, 0.0, kSteps);
    EXPECT_NEAR(s.bodies[i].pose.angle, 0.0, kSteps);
  }
  // Downhill along another direction: the rigid parts slide along it (the slider is guided
  // along e1 and takes gravity's component along it).
  const double c = std::cos(0.3), d = std::sin(0.3);
  model.gravity = core::Gravity{g, incline, c, d};
  core::State turned = at_rest(model);
  core::step(model, turned, 1000);
  EXPECT_NEAR(turned.bodies[1].twist.ux, a * c * turned.t, kSteps);
  EXPECT_NEAR(turned.bodies[1].twist.uy, a * d * turned.t, kSteps);
  const double along_e1 = g * std::sin(incline) * c;  // the slider: pulled by this, held by s m cos
  ASSERT_GT(along_e1, 1.2 * m * std::cos(incline));
  EXPECT_NEAR(turned.bodies[0].twist.ux, (along_e1 - m * std::cos(incline)) * turned.t, kSteps);
}

TEST(CoreLoads, AGentleInclineHoldsAPartAtRest) {
  const double g = 2.0, incline = 0.1, m = 0.5;
  core::Model model = three_parts(m, FrictionLaw(1.2, 1.0));
  model.gravity = core::Gravity{g, incline, 1, 0};
  ASSERT_LE(g * std::sin(incline), 1.2 * m * std::cos(incline));  // held by static friction
  core::State s = at_rest(model);
  core::step(model, s, 1000);
  for (const core::BodyState& b : s.bodies) {
    EXPECT_EQ(b.pose.x, 0.0);
    EXPECT_EQ(b.twist.ux, 0.0);
    EXPECT_EQ(b.mode, PatchMode::stick);
  }
}

TEST(CoreLoads, TheTablesNormalMotionLoadsTheFrictionByItsVelocityChange) {
  const double g = 2.0, A = 0.02, v0 = 1.5, m = 1.0, k = 1.0;
  const FourierProfile lift(1.0, {A}, {});  // z = A cos(2 pi t) (+ an offset)
  const double w = 2 * std::numbers::pi;
  const auto zd = [&](double t) { return -A * w * std::sin(w * t); };
  ASSERT_LT(A * w * w, g);  // never lifts off
  core::Model model = three_parts(m, FrictionLaw(1.2, k));
  model.motion.normal = &lift;
  model.gravity = core::Gravity{g, 0, 1, 0};
  core::State s = at_rest(model, v0);
  struct Check final : MotionObserver {
    std::function<double(double)> expected;
    int checked = 0;
    void on_step(const core::State& st) override {
      for (const core::BodyState& b : st.bodies) EXPECT_NEAR(b.twist.ux, expected(st.t), kSteps);
      ++checked;
    }
  } check;
  check.expected = [&](double t) { return v0 - k * m * (t + (zd(t) - zd(0)) / g); };
  ASSERT_EQ(core::step(model, s, 1000, &check), 1000);
  EXPECT_EQ(check.checked, 1000);
  // Over the whole period the vibration averages out: the constant-load loss k m t.
  for (const core::BodyState& b : s.bodies) EXPECT_NEAR(b.twist.ux, v0 - k * m * 1.0, kSteps);
}

TEST(CoreLoads, TheBodiesLiftOffInTheFirstStepWhoseNormalImpulseIsNegative) {
  const double g = 2.0, A = 0.1, h = 1.0 / 1000;
  const FourierProfile lift(1.0, {}, {A});  // z = A sin(2 pi t): z'' < -g first near t = 1/4
  const double w = 2 * std::numbers::pi;
  const auto zd = [&](double t) { return A * w * std::cos(w * t); };
  ASSERT_GT(A * w * w, g);
  long long first = -1;  // by hand: the first k with h + (z'(t_{k+1}) - z'(t_k)) / g < 0
  for (long long j = 0; j < 1000 && first < 0; ++j)
    if (h + (zd((j + 1) * h) - zd(j * h)) / g < 0) first = j;
  ASSERT_GT(first, 0);
  core::Model model = three_parts(1.0, FrictionLaw(1.2, 1.0));
  model.motion.normal = &lift;
  model.gravity = core::Gravity{g, 0, 1, 0};
  core::State s = at_rest(model, 0.3);
  EXPECT_EQ(core::step(model, s, 1000), first);
  EXPECT_EQ(s.status, core::StepStatus::lift_off);
  EXPECT_EQ(s.step_index, first);
}

// Gravity on a level table without normal motion is the paper's model: the same steps, bit for
// bit, on a table that moves in its plane (second method: the model without gravity).
TEST(CoreLoads, GravityOnALevelTableIsThePapersModel) {
  using testing_support::kPaper;
  core::Model paper = three_parts(1.0, FrictionLaw(1.2, 1.0));
  paper.motion.first = &kPaper;
  core::Model weighed = paper;
  weighed.gravity = core::Gravity{3.0, 0, 1, 0};
  core::State a = at_rest(paper, 0.1), b = at_rest(weighed, 0.1);
  core::step(paper, a, 3000);
  core::step(weighed, b, 3000);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.bodies[i].pose.x, b.bodies[i].pose.x) << i;
    EXPECT_EQ(a.bodies[i].twist.ux, b.bodies[i].twist.ux) << i;
    EXPECT_EQ(a.bodies[i].pose.angle, b.bodies[i].pose.angle) << i;
  }
  EXPECT_NE(a.bodies[0].pose.x, 0.0);
}

TEST(CoreLoads, BadGravityAndANormalMotionWithoutItNameTheParameter) {
  const FourierProfile lift(1.0, {0.01}, {});
  core::Model model = three_parts(1.0, FrictionLaw{});
  const auto name_of = [](const core::Model& m) {
    try {
      core::validate(m);
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("accepted");
  };
  model.motion.normal = &lift;
  EXPECT_EQ(name_of(model), "motion.normal");
  model.gravity = core::Gravity{0.0};
  EXPECT_EQ(name_of(model), "gravity.g");
  model.gravity = core::Gravity{1.0, std::numbers::pi / 2};
  EXPECT_EQ(name_of(model), "gravity.incline");
  model.gravity = core::Gravity{1.0, 0.1, 1, 1};
  EXPECT_EQ(name_of(model), "gravity.downhill");
  model.gravity = core::Gravity{1.0, 0.1, 0, -1};
  EXPECT_EQ(name_of(model), "accepted");
  // The other solvers have no normal load and refuse a normal motion.
  PlanarProblem p;
  p.motion.first = &kStill;
  p.motion.normal = &lift;
  p.part = {0.01, point_patch()};
  p.options.step = 0.01;
  try {
    validate(p);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "normal");
  }
}

}  // namespace
}  // namespace selfalign
