// Tests for core/parameters.hpp, the contact-core model's parameter view. The names and values
// listed are those the test built the model from (written here, not read back from the model);
// a model changed by with_parameters runs bit for bit as the same model built by hand with the
// new numbers (the second method), whatever order the values come in.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/core/parameters.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/planar/contact_patch.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;

// A rigid part and a 1-D part on an axis field (a ramp 1 -> 2 over [0.1, 0.2], then a jump to
// 3 at 0.3), with gravity on a slight incline; `c` changes what the tests change.
struct Numbers {
  double s0 = 1.2, k0 = 1.0, j0 = 0.02;                    // rigid body
  double s1 = 1.3, kf1 = 1.0, kb1 = 0.8, w1 = 0.02;        // 1-D part
  double ramp_top = 2.0, jump_to = 3.0;
  double g = 4.0, incline = 0.05;
};

core::Model build(const Numbers& n) {
  core::Model m;
  m.motion.first = &kPaper;
  m.field = AxisField{FrictionField({{0.1, 1, 1}, {0.2, n.ramp_top, n.ramp_top},
                                     {0.3, n.ramp_top, n.jump_to}}),
                      0, 0, 0};
  m.options = {1.0 / 1000, 0.5};
  m.gravity = core::Gravity{n.g, n.incline, 1, 0};
  m.bodies = {core::RigidBody{{n.j0, rectangle_patch(0.04, 0.02, 3, 2)}, FrictionLaw(n.s0, n.k0)},
              core::SliderBody{UniformFootprint{n.w1}, FrictionLaw(n.s1, n.kf1, n.kb1)}};
  return m;
}

core::State run(const core::Model& m) {
  const std::vector<PlanarPose> poses{{0.05, 0.0, 0.2}, {0.1, 0, 0}};
  const std::vector<PlanarTwist> twists{{0.1, 0, 0}, {0.2, 0, 0}};
  core::State s = core::make_state(m, 0.0, poses, twists);
  EXPECT_EQ(core::step(m, s, 3000), 3000);
  return s;
}

void expect_same(const core::State& a, const core::State& b) {
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].pose.x, b.bodies[i].pose.x) << i;
    EXPECT_EQ(a.bodies[i].pose.y, b.bodies[i].pose.y) << i;
    EXPECT_EQ(a.bodies[i].pose.angle, b.bodies[i].pose.angle) << i;
    EXPECT_EQ(a.bodies[i].twist.ux, b.bodies[i].twist.ux) << i;
  }
}

TEST(CoreParameters, TheViewNamesTheNumbersTheModelIsMadeOf) {
  const Numbers n;
  const std::vector<ModelParameter> view = core::model_parameters(build(n));
  const std::vector<std::pair<std::string, double>> expected{
      {"bodies[0].law.static", 1.2},          {"bodies[0].law.kinetic", 1.0},
      {"bodies[0].inertia", 0.02},            {"bodies[1].law.static", 1.3},
      {"bodies[1].law.kinetic", 1.0},         {"bodies[1].law.kinetic_backward", 0.8},
      {"bodies[1].law.stribeck_velocity", NAN}, {"bodies[1].law.viscous", 0.0},
      {"bodies[1].width", 0.02},              {"field.origin_x", 0.0},
      {"field.origin_y", 0.0},                {"field.angle", 0.0},
      {"field.positions[0]", 0.1},            {"field.levels[0]", 1.0},
      {"field.positions[1]", 0.2},            {"field.levels[1]", 2.0},
      {"field.positions[2]", 0.3},            {"field.left[2]", 2.0},
      {"field.right[2]", 3.0},                {"gravity.g", 4.0},
      {"gravity.incline", 0.05}};
  ASSERT_EQ(view.size(), expected.size());
  for (std::size_t i = 0; i < view.size(); ++i) {
    EXPECT_EQ(view[i].name, expected[i].first) << i;
    if (std::isnan(expected[i].second)) EXPECT_TRUE(std::isnan(view[i].value)) << view[i].name;
    else EXPECT_EQ(view[i].value, expected[i].second) << view[i].name;
  }
  EXPECT_EQ(view.back().unit, "[rad]");
  EXPECT_EQ(view.front().unit, "[-]");
}

TEST(CoreParameters, WithParametersIsTheModelBuiltWithTheNewNumbers) {
  const Numbers n;
  const core::Model model = build(n);
  // A kinetic coefficient above the static one until the static is raised: any order.
  Numbers changed = n;
  changed.s0 = 1.4, changed.k0 = 1.3, changed.kb1 = 0.9, changed.w1 = 0.03;
  changed.ramp_top = 1.6, changed.jump_to = 3.5, changed.incline = 0.1;
  const core::Model with = core::with_parameters(
      model, {{"bodies[0].law.kinetic", 1.3}, {"bodies[0].law.static", 1.4},
              {"bodies[1].law.kinetic_backward", 0.9}, {"bodies[1].width", 0.03},
              {"field.levels[1]", 1.6}, {"field.left[2]", 1.6}, {"field.right[2]", 3.5},
              {"gravity.incline", 0.1}});
  expect_same(run(with), run(build(changed)));
  // the model given is a value: unchanged
  expect_same(run(model), run(build(n)));
  // A Stribeck decay added by name is the law's with_stribeck (exponent 1).
  core::Model decayed = build(n);
  std::get<core::SliderBody>(decayed.bodies[1]).law =
      FrictionLaw(1.3, 1.0, 0.8).with_stribeck(0.05);
  expect_same(run(core::with_parameters(model, {{"bodies[1].law.stribeck_velocity", 0.05}})),
              run(decayed));
}

TEST(CoreParameters, ANameThatIsNotOneOrAnInvalidModelIsNamed) {
  const core::Model model = build(Numbers{});
  const auto failure = [&](const ParameterValues& v) {
    try {
      core::with_parameters(model, v);
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(failure({{"bodies[0].law.statik", 1.0}}).find("did you mean bodies[0].law.static"),
            std::string::npos);
  EXPECT_NE(failure({{"bodies[0].width", 0.1}}).find("not a parameter"), std::string::npos);
  EXPECT_NE(failure({{"gravity.g", NAN}}).find("gravity.g"), std::string::npos);
  // kinetic above static at the end: the law names its part
  EXPECT_NE(failure({{"bodies[0].law.kinetic", 1.5}}).find("bodies[0].law"), std::string::npos);
  EXPECT_NE(failure({{"field.positions[1]", 0.05}}).find("field"), std::string::npos);
  EXPECT_NE(failure({{"gravity.incline", 2.0}}).find("gravity.incline"), std::string::npos);
}

}  // namespace
}  // namespace selfalign
