// Tests for core/model.hpp, core/state.hpp, core/step.hpp: the contact core's runtime-sized
// model of N bodies on one table. Without part-part contact the bodies are independent, so each
// must move bit for bit as advance_planar_rigid moves it alone (the second method: the
// one-body stepper the planar analyses have used since issue 13): 1, 2 and 5 bodies with
// different patches, inertias, laws, poses and twists, on a table moving along x and y over a
// field with a rough pocket (the bodies cross its band).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;
const ThreePhaseProfile kHalf({0.5, 0.02, 2.5, 1.5});  // along y; its period divides 1.0

struct Start {
  core::RigidBody body;
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
  model.bodies.push_back(core::RigidBody{{0.0, point_patch()}, {}});  // zero inertia
  const std::vector<PlanarPose> one{{}};
  const std::vector<PlanarTwist> one_twist{{}};
  try {
    core::make_state(model, 0, one, one_twist);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "bodies[0].inertia");
  }
  std::get<core::RigidBody>(model.bodies[0]).part.inertia = 0.01;
  EXPECT_THROW(core::make_state(model, 0, none, one_twist), InvalidParameter);  // poses
  core::State s = core::make_state(model, 0, one, one_twist);
  model.bodies.push_back(model.bodies[0]);
  EXPECT_THROW(core::step(model, s, 1), InvalidParameter);  // a state of another model
}

// The paper's 1-D part as a body of the core (SliderBody): its level is the model's field
// (here an AxisField along x) averaged over its footprint. Beside rigid bodies on the same
// table and field, each slider moves bit for bit as it does alone in the core, and as the 1-D
// Moreau stepper moves it on FieldFriction(field, footprint) (the second method: the 1-D wing's
// own driver and its own footprint average; the same step function, the table's velocity read
// from the profile's state() instead of velocity(), the same numbers for the three-phase
// profile): ramps under uniform footprints of two widths and a point, the paper's law,
// direction-dependent kinetic coefficients, a Stribeck and viscous law.
TEST(ContactCore, TheOneDimensionalPartIsABodyOfTheCore) {
  const FrictionField ramps = FrictionField::ramps({0.05, 0.08, 0.1, 0.16}, {1, 1.4, 1.2, 4});
  struct Slider {
    core::SliderBody body;
    double x0, v0;
  };
  const std::vector<Slider> sliders{
      {{UniformFootprint{0.02}, FrictionLaw{}}, 0.0, 0.0},
      {{PointFootprint{}, FrictionLaw(1.3, 1.0, 0.8)}, 0.02, 0.1},
      {{UniformFootprint{0.05}, FrictionLaw(1.2, 1.0).with_stribeck(0.05, 1.0).with_viscous(0.1)},
       -0.1, -0.2}};
  const TimeSteppingOptions options{1.0 / 1000, 0.5};
  PlanarTableMotion motion;
  motion.first = &kPaper;  // along x: the 1-D table's motion
  const PlanarField field = AxisField{ramps, 0, 0, 0};
  const long long steps = 6000;
  const std::vector<Start> rigid = starts();

  // Alone in the core, and by the 1-D stepper.
  std::vector<core::BodyState> alone;
  for (const Slider& s : sliders) {
    const core::Model one{motion, field, {s.body}, options};
    const std::vector<PlanarPose> pose{{s.x0, 0, 0}};
    const std::vector<PlanarTwist> twist{{s.v0, 0, 0}};
    core::State st = core::make_state(one, 0.0, pose, twist);
    ASSERT_EQ(core::step(one, st, steps), steps);
    alone.push_back(st.bodies[0]);
    TimeSteppingState ts = make_time_stepping_state(kPaper, {0.0, s.x0, s.v0});
    advance_time_stepping(kPaper, FieldFriction(ramps, s.body.footprint), s.body.law, options,
                          ts, steps);
    SCOPED_TRACE(::testing::Message() << "slider at " << s.x0);
    EXPECT_EQ(st.bodies[0].pose.x, ts.object.x);
    EXPECT_EQ(st.bodies[0].twist.ux, ts.object.xd);
    EXPECT_EQ(st.bodies[0].mode == PatchMode::stick, ts.stick);
    EXPECT_EQ(st.bodies[0].pose.y, 0.0);
    EXPECT_NE(ts.object.x, s.x0);  // it moved
  }
  EXPECT_GT(alone[0].pose.x, 0.1);  // onto the ramps

  // Mixed with rigid bodies on the same field: [rigid, slider, rigid, slider, slider].
  core::Model model{motion, field, {}, options};
  std::vector<PlanarPose> poses;
  std::vector<PlanarTwist> twists;
  const auto add_rigid = [&](const Start& r) {
    model.bodies.push_back(r.body);
    poses.push_back(r.pose);
    twists.push_back(r.twist);
  };
  const auto add_slider = [&](const Slider& s) {
    model.bodies.push_back(s.body);
    poses.push_back({s.x0, 0, 0});
    twists.push_back({s.v0, 0, 0});
  };
  add_rigid(rigid[1]);
  add_slider(sliders[0]);
  add_rigid(rigid[2]);
  add_slider(sliders[1]);
  add_slider(sliders[2]);
  core::State state = core::make_state(model, 0.0, poses, twists);
  ASSERT_EQ(core::step(model, state, steps), steps);
  ASSERT_EQ(state.status, core::StepStatus::ok);
  const std::size_t slider_at[] = {1, 3, 4};
  for (std::size_t k = 0; k < 3; ++k) {
    const core::BodyState& b = state.bodies[slider_at[k]];
    EXPECT_EQ(b.pose.x, alone[k].pose.x) << k;
    EXPECT_EQ(b.twist.ux, alone[k].twist.ux) << k;
    EXPECT_EQ(b.mode, alone[k].mode) << k;
  }
  for (const auto& [at, r] : {std::pair{std::size_t{0}, rigid[1]}, std::pair{std::size_t{2}, rigid[2]}}) {
    PlanarRigidState one = make_planar_rigid_state(motion, 0.0, r.pose, r.twist);
    advance_planar_rigid(motion, model.field, r.body.law, r.body.part, options, one, steps);
    EXPECT_EQ(state.bodies[at].pose.x, one.pose.x) << at;
    EXPECT_EQ(state.bodies[at].pose.angle, one.pose.angle) << at;
    EXPECT_EQ(state.bodies[at].twist.omega, one.twist.omega) << at;
  }
}

// The one observer interface: the core hands each slider's step to MotionObserver::on_motion as
// the piece the 1-D time-stepping stepper reports for the same step (second method: that
// stepper, observed by the same recorder), `body` its index in the model, and every state to
// on_step; a 1-D observer (MotionCensus) watches a body of the core as it watches the stepper.
struct PieceRecorder final : MotionObserver {
  std::vector<MotionInterval> pieces;
  std::vector<double> step_times;
  std::vector<std::size_t> bodies_seen;
  void on_motion(const MotionInterval& piece, const Arc* arc) override {
    EXPECT_EQ(arc, nullptr);
    pieces.push_back(piece);
  }
  void on_step(const core::State& s) override {
    step_times.push_back(s.t);
    bodies_seen.push_back(s.bodies.size());
  }
};

TEST(ContactCore, OneObserverSeesTheOneDimensionalPiecesAndTheCoresSteps) {
  const FrictionField ramps = FrictionField::ramps({0.05, 0.08, 0.1, 0.16}, {1, 1.4, 1.2, 4});
  const TimeSteppingOptions options{1.0 / 1000, 0.5};
  PlanarTableMotion motion;
  motion.first = &kPaper;
  const PlanarField field = AxisField{ramps, 0, 0, 0};
  const core::SliderBody a{UniformFootprint{0.02}, FrictionLaw{}};
  const core::SliderBody b{PointFootprint{}, FrictionLaw(1.3, 1.0, 0.8)};
  const std::vector<Start> rigid = starts();
  const core::Model model{motion, field, {a, rigid[1].body, b}, options};
  const std::vector<PlanarPose> poses{{0.0, 0, 0}, rigid[1].pose, {0.02, 0, 0}};
  const std::vector<PlanarTwist> twists{{}, rigid[1].twist, {0.1, 0, 0}};
  const long long steps = 2500;
  core::State state = core::make_state(model, 0.0, poses, twists);
  PieceRecorder seen;
  ASSERT_EQ(core::step(model, state, steps, &seen), steps);
  ASSERT_EQ(seen.step_times.size(), static_cast<std::size_t>(steps));
  EXPECT_EQ(seen.step_times.back(), state.t);
  for (std::size_t n : seen.bodies_seen) EXPECT_EQ(n, 3u);
  ASSERT_EQ(seen.pieces.size(), static_cast<std::size_t>(2 * steps));  // two sliders per step

  const std::pair<int, core::SliderBody> sliders[] = {{0, a}, {2, b}};
  for (const auto& [index, body] : sliders) {
    SCOPED_TRACE(::testing::Message() << "body " << index);
    std::vector<MotionInterval> mine;
    for (const MotionInterval& p : seen.pieces)
      if (p.body == index) mine.push_back(p);
    PieceRecorder stepper;
    MotionCensus census_1d;
    TimeSteppingState ts = make_time_stepping_state(
        kPaper, {0.0, poses[static_cast<std::size_t>(index)].x,
                 twists[static_cast<std::size_t>(index)].ux});
    advance_time_stepping(kPaper, FieldFriction(ramps, body.footprint), body.law, options, ts,
                          steps, &stepper);
    ASSERT_EQ(mine.size(), stepper.pieces.size());
    int moving = 0;
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const MotionInterval &p = mine[k], &q = stepper.pieces[k];
      ASSERT_EQ(p.t0, q.t0) << k;
      ASSERT_EQ(p.t1, q.t1) << k;
      ASSERT_EQ(p.x0, q.x0) << k;
      ASSERT_EQ(p.xd0, q.xd0) << k;
      ASSERT_EQ(p.x1, q.x1) << k;
      ASSERT_EQ(p.xd1, q.xd1) << k;
      ASSERT_EQ(p.direction, q.direction) << k;
      ASSERT_EQ(p.end, ArcEnd::time_step);
      EXPECT_EQ(q.body, 0);
      moving += p.direction != 0;
    }
    EXPECT_GT(moving, 100);  // it slid
    // A 1-D observer on the core's run: the census of the body's pieces as of the stepper's.
    struct OneBody final : MotionObserver {
      int body;
      MotionCensus census;
      explicit OneBody(int i) : body(i) {}
      void on_motion(const MotionInterval& p, const Arc* arc) override {
        if (p.body == body) census.on_motion(p, arc);
      }
    } on_core(index);
    core::State again = core::make_state(model, 0.0, poses, twists);
    core::step(model, again, steps, &on_core);
    for (const MotionInterval& q : stepper.pieces) census_1d.on_motion(q, nullptr);
    EXPECT_EQ(on_core.census.pattern(), census_1d.pattern());
    EXPECT_EQ(on_core.census.motion_case(), census_1d.motion_case());
  }
}

// A slider's level along e1: an axis field turned by 60 degrees from e1 is read at
// d = cos(60) x (and a footprint of width w covers d in [cos(60) (x - w), cos(60) x]); another
// field is read at the point x e1 (by hand: a half-plane step rising at x = 0.3 with band 0.1).
TEST(ContactCore, ASlidersLevelIsTheFieldAlongItsAxis) {
  PlanarTableMotion motion;
  motion.first = &kPaper;
  const double c = std::cos(std::numbers::pi / 3);
  core::Model model{motion, AxisField{FrictionField::ramps({0, 1}, {1, 3}), 0, 0, std::numbers::pi / 3},
                    {}, {1.0 / 1000, 0.5}};
  EXPECT_NEAR(core::slider_level(model, core::SliderBody{}, 1.0), 1 + 2 * c, 1e-15);
  // uniform footprint w = 0.4 at x = 1: the ramp's mean over d in [0.6 c, c], its midpoint 0.8 c
  EXPECT_NEAR(core::slider_level(model, core::SliderBody{UniformFootprint{0.4}, {}}, 1.0),
              1 + 2 * 0.8 * c, 1e-15);
  model.field = HalfPlaneStepField{0.3, 0.0, 0.0, 0.1, 2.0};
  EXPECT_NEAR(core::slider_level(model, core::SliderBody{}, 0.35), 1.5, 1e-15);
}

TEST(ContactCore, AOneDimensionalPartIsRefusedWhereItHasNoMeaning) {
  PlanarTableMotion motion;
  motion.first = &kPaper;
  core::Model model{motion, HalfPlaneStepField{}, {core::SliderBody{UniformFootprint{0.05}, {}}},
                    {1.0 / 1000, 0.5}};
  const std::vector<PlanarPose> at_rest{{0, 0, 0}};
  const std::vector<PlanarTwist> still{{}};
  const auto name_of = [&](const std::vector<PlanarPose>& p, const std::vector<PlanarTwist>& t) {
    try {
      core::make_state(model, 0, p, t);
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("no throw");
  };
  EXPECT_EQ(name_of(at_rest, still), "bodies[0].footprint");  // a band field: point only
  model.bodies[0] = core::SliderBody{UniformFootprint{0.0}, {}};
  model.field = UniformPlanarField{};
  EXPECT_EQ(name_of(at_rest, still), "bodies[0].footprint");  // width 0
  model.bodies[0] = core::SliderBody{PointFootprint{}, {}};
  EXPECT_EQ(name_of(at_rest, still), "no throw");
  EXPECT_EQ(name_of({{0, 0.1, 0}}, still), "poses[0]");
  EXPECT_EQ(name_of(at_rest, {{0, 0, 0.5}}), "twists[0]");
  model.motion.rotation = &kHalf;
  EXPECT_EQ(name_of(at_rest, still), "bodies[0].motion");
}

}  // namespace
}  // namespace selfalign
