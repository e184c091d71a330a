// Tests for analysis/final_stick.hpp, the one stopping criterion of every stepper: stuck for a
// whole table period, T_p the start of that final stick. The 1-D stopping run and the planar
// stop both decide by it and take T_p from it.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "selfalign/analysis/final_stick.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/profiles/fourier.hpp"

namespace selfalign {
namespace {

// The criterion's bookkeeping by hand: a piece that ends moving ends where a following stick
// begins; a stick piece leaves it; a core step after which the watched body (or any body) is
// not in stick moves it to the step's end.
TEST(FinalStick, TheStickBeginsWhereTheLastMotionEnded) {
  FinalStick one(0.5);
  EXPECT_EQ(one.since(), 0.5);  // at rest from the run's start
  one.on_motion({0.5, 1.0, 0, 0, 0, 0, 0, ArcEnd::acceleration_switch}, nullptr);
  EXPECT_EQ(one.since(), 0.5);
  EXPECT_TRUE(one.stuck_since(0.5));
  one.on_motion({1.0, 1.25, 0, 0, 0.1, 0.2, 1, ArcEnd::acceleration_switch}, nullptr);
  one.on_motion({1.25, 2.0, 0.1, 0.2, 0.3, 0, 1, ArcEnd::velocity_zero}, nullptr);
  one.on_motion({2.0, 3.0, 0.3, 0, 0.3, 0, 0, ArcEnd::stick_break}, nullptr);
  EXPECT_EQ(one.since(), 2.0);
  EXPECT_FALSE(one.stuck_since(1.5));
  EXPECT_TRUE(one.stuck_since(2.0));
  // A time step that ends at rest is a stick step; one that ends moving is not.
  one.on_motion({3.0, 3.1, 0.3, 0, 0.3, -1e-3, -1, ArcEnd::time_step}, nullptr);
  one.on_motion({3.1, 3.2, 0.3, -1e-3, 0.3, 0, 0, ArcEnd::time_step}, nullptr);
  EXPECT_EQ(one.since(), 3.1);

  core::State s;
  s.bodies.resize(2);
  s.bodies[0].mode = PatchMode::stick;
  s.bodies[1].mode = PatchMode::pivot;
  s.t = 4.0;
  FinalStick any(0.0), first(0.0, 0), second(0.0, 1);
  for (FinalStick* f : {&any, &first, &second}) f->on_step(s);
  EXPECT_EQ(any.since(), 4.0);
  EXPECT_EQ(first.since(), 0.0);
  EXPECT_EQ(second.since(), 4.0);
  // a piece of another body is not the watched body's
  first.on_motion({4.0, 4.1, 0, 1, 0.1, 1, 1, ArcEnd::time_step, 1}, nullptr);
  EXPECT_EQ(first.since(), 0.0);
}

// One criterion, two analyses: the 1-D stopping run time-stepped (Moreau, step h = Δt / n) and
// the planar stop of a point part on the same level along x (an AxisField) under the same table
// motion and step decide the same stop at the same step. The case is chosen where the closed
// forms say nothing: a smooth motion y = 0.04 cos(2 pi t) + 0.01 sin(4 pi t) (peak |y''| 2.78)
// onto a level that steps from 1 to 2.7 < 2.78: the continuous motion never stops (eq. 41 has
// no position), while Moreau's step holds a part at rest wherever h s m >= |Δy'| of every step,
// i.e. where 2.7 >= m_h = max_k |y'(k h) - y'((k - 1) h)| / h. Second method for m_h: y' by
// hand, y' = -0.08 pi sin(2 pi t) + 0.04 pi cos(4 pi t).
TEST(FinalStick, TheOneDimensionalAndThePlanarStopAreOneCriterion) {
  // The two schemes take the same steps with different arithmetic (hypot and the patch solver
  // against the 1-D projection): rounding over a few hundred steps.
  constexpr double kSchemesAgree = 1e-12;
  const FourierProfile wave(1.0, {0.04, 0.0}, {0.0, 0.01});
  const FrictionField step_up = FrictionField::ramps({0.05, 0.0500001}, {1.0, 2.7});
  const FieldFriction friction(step_up, PointFootprint{});
  const double pi = std::numbers::pi;
  const auto velocity = [pi](double t) {
    return -0.08 * pi * std::sin(2 * pi * t) + 0.04 * pi * std::cos(4 * pi * t);
  };
  ASSERT_GT(wave.peak_acceleration(), 2.7);
  const StoppingRun exact = stopping_run(wave, friction, {0, 0, 0});
  EXPECT_EQ(exact.method, Method::exact);
  EXPECT_TRUE(exact.never_stops);

  for (const int n : {10, 20, 40}) {
    SCOPED_TRACE(::testing::Message() << n << " steps a period");
    const double h = 1.0 / n;
    double m_h = 0;
    for (int k = 1; k <= n; ++k) m_h = std::max(m_h, std::abs(velocity(k * h) - velocity((k - 1) * h)) / h);
    const bool held = 2.7 >= m_h;
    EXPECT_EQ(held, n != 40);  // the case: coarse steps hold, finer ones do not

    StoppingOptions o;
    o.method = Method::time_stepping;
    o.steps_per_period = n;
    o.max_periods = 2000;
    const StoppingRun one = stopping_run(wave, friction, FrictionLaw{}, {0, 0, 0}, o);
    EXPECT_EQ(one.method, Method::time_stepping);
    PlanarProblem p;
    p.motion.first = &wave;
    p.field = AxisField{step_up, 0, 0, 0};
    p.part = {0.01, point_patch()};
    p.options.step = h;
    const PlanarStopSummary planar = planar_stop(p, {{0, 0, 0}}, 2000, {}, 1);
    ASSERT_EQ(planar.runs.size(), 1u);
    const PlanarStopRun& run = planar.runs[0];
    if (held) {
      ASSERT_EQ(one.kind, StopKind::permanent_stick);
      ASSERT_TRUE(run.stopped);
      EXPECT_GE(one.end_position, 0.0500001);  // on the high level
      EXPECT_NEAR(run.end.x, one.end_position, kSchemesAgree);
      EXPECT_EQ(run.end.y, 0.0);
      EXPECT_EQ(run.process_time, one.process_time);  // the same step
      EXPECT_NEAR(one.process_time / h, std::round(one.process_time / h), 1e-9);  // a step's end
      EXPECT_GT(one.process_time, 0.0);
    } else {
      EXPECT_EQ(one.kind, StopKind::not_stopped);
      EXPECT_TRUE(one.never_stops);
      EXPECT_TRUE(planar.never_stops);
      EXPECT_FALSE(run.stopped);
    }
  }
}

}  // namespace
}  // namespace selfalign
