// The patch integrator (planar/planar_patch_integrator.hpp), checked against independent
// methods: the exact point solver (a point patch), the 1-D exact solver (a patch symmetric
// about the motion's axis), a fixed-step RK4 of the smooth sliding-and-spinning equations (a
// launched disc's common stop), and Moreau's stepper converging to it with order 1 (a
// 16-point patch that slides, sticks and pivots on a table moving along x and y).
#include <gtest/gtest.h>

#include "planar_launch.hpp"
#include "planar_profiles.hpp"
#include "sanitized.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "selfalign/core/state.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/planar/planar_patch_integrator.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {
namespace {
namespace patch_integrator_test {  // own names: the tests are built as a unity build

using testing_support::kCross;
using testing_support::kPaper;
using testing_support::kSanitized;
using testing_support::rk4_stop_time;

// Short strokes: the part comes to rest within phases (stick events), unlike kPaper's.
const ThreePhaseProfile kSmallPaper({1.0, 0.02, 3.0, 0.9});
const ThreePhaseProfile kSmallCross({0.7, 0.012, 2.2, 1.4});

bool print() { return std::getenv("SELFALIGN_PRINT") != nullptr; }

IntegratorOptions tight() {
  IntegratorOptions o;
  o.relative_tolerance = 1e-12, o.absolute_tolerance = 1e-14;
  return o;
}

TEST(PlanarPatchIntegrator, APointPatchIsTheExactPointSolver) {
  // A point at the centre of mass on a table moving along x and y: slips that turn, stick
  // events |u| -> 0, s > k. The exact point solver is closed-form per arc.
  PlanarTableMotion motion;
  motion.first = &kSmallPaper;
  motion.second = &kSmallCross;
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.5, 1.0)}) {
    const RigidPart part{0.01, point_patch()};
    PlanarExactState exact;
    PlanarPatchState s = make_planar_patch_state(0, {}, {});
    IntegratorStatistics stats;
    double worst = 0;
    for (int n = 1; n <= 28; ++n) {  // 4 periods of the common period 7
      const double t = 0.25 * n;
      advance_planar_exact_point(motion, UniformPlanarField{1.0}, law, exact, t);
      advance_planar_integrated(motion, UniformPlanarField{1.0}, law, part, tight(), s, t, &stats);
      worst = std::max({worst, std::abs(s.pose.x - exact.x), std::abs(s.pose.y - exact.y),
                        std::abs(s.twist.ux - exact.ux), std::abs(s.twist.uy - exact.uy)});
    }
    if (print()) std::printf("point: worst %.3e steps %lld events %lld\n", worst, stats.steps, stats.events);
    EXPECT_LT(worst, 1e-9) << law.describe();
    EXPECT_GT(stats.events, 5);  // it did arrive at rest
    EXPECT_GT(std::abs(exact.x) + std::abs(exact.y), 1e-2);
  }
}

TEST(PlanarPatchIntegrator, ASymmetricPatchOnAnAxisMotionIsTheOneDimensionalExactSolver) {
  // A 4 x 3 rectangle, symmetric about x, on a table moving along x: no torque, no sideways
  // motion; the centre moves as the 1-D part (Sect. 7.2 profile, s = k and s > k).
  PlanarTableMotion motion;
  motion.first = &kSmallCross;
  const RigidPart part{0.1, rectangle_patch(0.4, 0.2, 4, 3)};
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.5, 1.0)}) {
    const UniformFriction one_d;
    const ExactSetup setup{*kSmallCross.piecewise_polynomial(), *one_d.piecewise_affine(), law};
    ExactState ref = make_exact_state(setup, {0, 0, 0});
    PlanarPatchState s = make_planar_patch_state(0, {}, {});
    double worst = 0;
    for (int n = 1; n <= 20; ++n) {
      advance_exact(setup, ref, 0.5 * n);
      advance_planar_integrated(motion, UniformPlanarField{1.0}, law, part, tight(), s, 0.5 * n);
      worst = std::max({worst, std::abs(s.pose.x - ref.object.x), std::abs(s.twist.ux - ref.object.xd)});
      ASSERT_LT(std::abs(s.pose.y) + std::abs(s.pose.angle), 1e-13) << n;
    }
    if (print()) std::printf("1-D: worst %.3e x %.6f\n", worst, s.pose.x);
    EXPECT_LT(worst, 1e-9) << law.describe();
  }
}

TEST(PlanarPatchIntegrator, ALaunchedDiscStopsWhereRk4OfTheSmoothEquationsStops) {
  // A uniform disc (12 x 24 points) launched with (v0, w0) on a table at rest slides and spins
  // to a common stop; the stop instant (found by bisection on the run's end: the first end at
  // which the twist is exactly 0) against RK4 with dt = 1e-5 run until the slip is below 1e-9.
  // RK4's own error sets the tolerance: for (0.1, 5) its stop moves by 1.4e-7, 1.7e-8, 2.1e-9
  // from dt = 1e-4 to 3e-5, 1e-5, 3e-6 (toward the integrator's 0.7637097028, which is the
  // same to 1e-10 at tolerances 1e-11, 1e-12, 1e-13).
  const double radius = 0.2;
  const int rings = kSanitized ? 6 : 12;  // the sanitizer build: a coarser disc, one launch
  const RigidPart part{radius * radius / 2, disc_patch(radius, rings, 2 * rings)};
  const PlanarTableMotion still;
  const std::vector<std::pair<double, double>> launches =
      kSanitized ? std::vector<std::pair<double, double>>{{0.1, 5.0}}
                 : std::vector<std::pair<double, double>>{{0.3, 2.0}, {0.1, 5.0}, {0.3, 0.5}};
  for (const auto& [v0, w0] : launches) {
    const double t_rk4 = rk4_stop_time(part.patch, part.inertia, v0, w0, 1e-5);
    const auto at_rest = [](const PlanarPatchState& s) {
      return s.twist.ux == 0 && s.twist.uy == 0 && s.twist.omega == 0;
    };
    // Bracket by steps of 0.01, then bisect from the bracket's start state.
    PlanarPatchState lo = make_planar_patch_state(0, {}, {v0, 0, w0});
    for (;;) {
      PlanarPatchState next = lo;
      advance_planar_integrated(still, UniformPlanarField{1.0}, FrictionLaw{}, part, tight(), next, lo.t + 0.01);
      if (at_rest(next)) break;
      lo = next;
      ASSERT_LT(lo.t, 2);
    }
    double a = lo.t, hi = lo.t + 0.01;
    while (hi - a > 1e-12) {
      PlanarPatchState mid = lo;
      advance_planar_integrated(still, UniformPlanarField{1.0}, FrictionLaw{}, part, tight(), mid, 0.5 * (a + hi));
      (at_rest(mid) ? hi : a) = 0.5 * (a + hi);
    }
    if (print()) std::printf("disc v0 %g w0 %g: integrator %.10f RK4 %.10f\n", v0, w0, hi, t_rk4);
    EXPECT_NEAR(hi, t_rk4, 1e-8) << v0 << " " << w0;
  }
}

TEST(PlanarPatchIntegrator, RefusesWhatItDoesNotSolve) {
  const RigidPart part{0.01, point_patch()};
  PlanarPatchState s = make_planar_patch_state(0, {}, {});
  const auto refuses = [&](const PlanarTableMotion& m, const FrictionLaw& law,
                           const IntegratorOptions& o, double t_end, const std::string& name) {
    try {
      advance_planar_integrated(m, UniformPlanarField{1.0}, law, part, o, s, t_end);
      ADD_FAILURE() << "accepted; expected " << name;
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.name(), name);
    }
  };
  PlanarTableMotion turning;
  turning.first = &kPaper, turning.rotation = &kCross;
  refuses(turning, FrictionLaw{}, tight(), 1, "rotation");
  const FourierProfile smooth(1.0, {0.0, 0.0}, {0.0, 0.01});
  PlanarTableMotion fourier;
  fourier.first = &smooth;
  refuses(fourier, FrictionLaw{}, tight(), 1, "first");
  PlanarTableMotion plain;
  plain.first = &kPaper;
  refuses(plain, FrictionLaw{}.with_viscous(0.1), tight(), 1, "law");
  IntegratorOptions bad = tight();
  bad.relative_tolerance = 2;
  refuses(plain, FrictionLaw{}, bad, 1, "relative_tolerance");
  refuses(plain, FrictionLaw{}, tight(), -1, "t_end");
  IntegratorOptions stingy = tight();
  stingy.max_steps_per_period = 3;
  refuses(plain, FrictionLaw{}, stingy, 4, "relative_tolerance");  // the budget
}

// Two 16-point problems. `turning`: the bench's (bench_simulate.cpp's planar_patch_per_step), a
// 4 x 4 rectangle entering a half-plane step at angle 0.2 on a table moving along x and y: it
// slides, turns and sticks. `door`: an 8 x 2 bar across a half-plane step (its right end on
// the rough side) driven along y: the rough end holds while the bar swings about it (pivots).
struct SixteenPoints {
  PlanarTableMotion motion;
  RigidPart part;
  PlanarField field;
  FrictionLaw law{1.3, 1.0};
  PlanarPose start;
  static SixteenPoints turning() {
    SixteenPoints p;
    p.motion.first = &kPaper, p.motion.second = &kCross;
    p.part = {0.002, rectangle_patch(0.1, 0.06, 4, 4)};
    p.field = HalfPlaneStepField{0.02, 0, 0.3, 0.05, 2.5};
    p.start = {0, 0, 0.2};
    return p;
  }
  static SixteenPoints door() {
    SixteenPoints p;
    p.motion.second = &kPaper;
    p.part = {0.4 * 0.4 / 12, rectangle_patch(0.4, 0.03, 8, 2)};
    p.field = HalfPlaneStepField{0.05, 0, 0, 0.02, 2.5};
    return p;
  }
};

// The pose after T from rest at the start pose starting at t0, by Moreau with step h and by
// the integrator.
PlanarPose moreau_pose(const SixteenPoints& p, double t0, double T, double h,
                       PlanarCensus* census = nullptr) {
  TimeSteppingOptions o;
  o.step = h;
  PlanarRigidState s = make_planar_rigid_state(p.motion, t0, p.start, {});
  struct Count final : MotionObserver {
    PlanarCensus* c;
    void on_step(const core::State& st) override { if (c) c->add(st.bodies[0].mode); }
  } count;
  count.c = census;
  advance_planar_rigid(p.motion, p.field, p.law, p.part, o, s, std::llround(T / h), &count);
  return s.pose;
}
PlanarPose integrated_pose(const SixteenPoints& p, double t0, double T, IntegratorOptions o,
                           IntegratorStatistics* stats = nullptr) {
  PlanarPatchState s = make_planar_patch_state(t0, p.start, {});
  advance_planar_integrated(p.motion, p.field, p.law, p.part, o, s, t0 + T, stats);
  return s.pose;
}
// Position error plus the angle's error times the patch radius.
double distance(const SixteenPoints& p, const PlanarPose& a, const PlanarPose& b) {
  return std::hypot(a.x - b.x, a.y - b.y) + patch_radius(p.part.patch) * std::abs(a.angle - b.angle);
}

TEST(PlanarPatchIntegrator, MoreauConvergesToItWithOrderOneOnSixteenPointPatches) {
  // RMS over grid phases of the pose error after T = 2: Moreau's error falls ~10x per decade
  // of h toward the integrator's pose (order 1), and the integrator agrees with itself at
  // 1e-8 and 1e-12 tolerances. Both problems' runs have sticks; the door's pivots.
  for (const SixteenPoints& p : {SixteenPoints::turning(), SixteenPoints::door()}) {
    const double T = 2.0;
    constexpr int kPhases = kSanitized ? 2 : 4;
    IntegratorStatistics stats;
    PlanarCensus census;
    double rms_prev = HUGE_VAL;
    for (double h : {1e-3, 1e-4}) {
      double sum_sq = 0, self = 0;
      for (int j = 0; j < kPhases; ++j) {
        const double t0 = h * (j + 0.5) / kPhases;
        const PlanarPose ref = integrated_pose(p, t0, T, tight(), &stats);
        IntegratorOptions loose;
        loose.relative_tolerance = 1e-8, loose.absolute_tolerance = 1e-10;
        self = std::max(self, distance(p, integrated_pose(p, t0, T, loose), ref));
        sum_sq += std::pow(distance(p, moreau_pose(p, t0, T, h, &census), ref), 2);
      }
      const double rms = std::sqrt(sum_sq / kPhases);
      if (print()) std::printf("h %g: Moreau rms %.3e (pivot steps %lld), integrator 1e-8 vs 1e-12 %.3e; events %lld steps %lld pivots %lld sticks %lld slips %lld\n", h, rms, census.pivot, self, stats.events, stats.steps, stats.pivots, stats.sticks, stats.slips);
      EXPECT_LT(self, 1e-6);
      EXPECT_LT(rms, 3 * h);
      EXPECT_LT(rms, rms_prev / 4);
      rms_prev = rms;
    }
    EXPECT_GT(stats.sticks, 0);
  }
}

}  // namespace patch_integrator_test
}  // namespace
}  // namespace selfalign
