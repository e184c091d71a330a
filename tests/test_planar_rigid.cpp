// The rigid part on a contact patch (planar/patch_impulse.hpp, planar/planar_rigid.hpp):
//  - the step's impulse solver against a second method (the primal problem reduced to rays:
//    min f = f(0) - 1/2 max_{|d|_M = 1} (d.W* - h(d))_+^2, maximised by a grid and compass
//    search over the sphere), and its three certificates;
//  - a single point at the centre of mass is the point stepper; a symmetric patch on a table
//    moving along x is the 1-D scheme; rotating the whole setup (with a rotating table) rotates
//    the solution; the friction impulse never adds kinetic energy;
//  - a uniform disc launched with (v, omega) on a table at rest stops translating and spinning
//    at the same instant (docs/planar.md), and its pure-slide and pure-spin stopping times are
//    the closed forms v0/k and (3/4) omega0 R / k (the disc's friction torque (2/3) k R);
//  - uniqueness: the drift and spin of a periodic excitation do not depend on the initial twist.
#include <gtest/gtest.h>

#include "planar_launch.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>
#include <numbers>
#include <random>

#include "sanitized.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/planar/planar_point.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

const ThreePhaseProfile kPaperMotion({1.0, 0.084, 3.0, 0.9});  // Sect. 7.2
const ThreePhaseProfile kCrossMotion({0.5, 0.02, 2.2, 1.4});   // half the period: divides it

using Twist = std::array<double, 3>;

// The sanitizer build is unoptimised (Debug): its runs of the two long property tests below
// check fewer cases: two launches of a coarser disc (6 x 12); 3 initial twists settled for 6
// periods instead of 12 for 20.
using testing_support::kSanitized;
using testing_support::rk4_stop_time;

// ---- second method for the step's problem ---------------------------------------------------

double ray_gain(std::span<const PatchContact> cs, double j, const Twist& w, double th, double ph) {
  // d on the M-unit sphere: d = M^-1/2 e, e = (sin th cos ph, sin th sin ph, cos th)
  const Twist d{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th) / std::sqrt(j)};
  double h = 0;
  for (const auto& c : cs) h += c.slip_bound * std::hypot(d[0] - d[2] * c.dy, d[1] + d[2] * c.dx);
  return d[0] * w[0] + d[1] * w[1] + d[2] * w[2] - h;
}

Twist ray_oracle(std::span<const PatchContact> cs, double j, const Twist& free) {
  const Twist w{free[0], free[1], j * free[2]};
  double best = -HUGE_VAL, bt = 0, bp = 0;
  for (int a = 0; a <= 120; ++a)
    for (int b = 0; b < 240; ++b) {
      const double th = std::numbers::pi * a / 120, ph = 2 * std::numbers::pi * b / 240;
      const double g = ray_gain(cs, j, w, th, ph);
      if (g > best) best = g, bt = th, bp = ph;
    }
  for (double step = 0.02; step > 1e-13; step *= 0.5)
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [dt, dp] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1},
                                   {1, -1}, {-1, 1}}) {
        const double g = ray_gain(cs, j, w, bt + dt * step, bp + dp * step);
        if (g > best) best = g, bt += dt * step, bp += dp * step, moved = true;
      }
    }
  if (best <= 0) return {0, 0, 0};
  return {best * std::sin(bt) * std::cos(bp), best * std::sin(bt) * std::sin(bp),
          best * std::cos(bt) / std::sqrt(j)};
}

TEST(PatchImpulse, MatchesTheRayReductionOnRandomPatches) {
  // 300 random problems (2..9 contacts, random levers, bounds, inertia, free twist) covering
  // stick, pivot and slip: the solver's twist equals the second method's to 1e-6 (the compass
  // search's resolution), and its objective is never above it (it is the exact minimiser).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  PatchImpulseSolver solver;
  int modes[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<PatchContact> cs(2 + trial % 8);
    double total = 0;
    for (auto& c : cs) {
      c.dx = u(rng), c.dy = u(rng);
      c.slip_bound = c.stick_bound = 0.1 + 0.3 * (u(rng) + 1);
      total += c.slip_bound;
    }
    const double j = 0.1 + (u(rng) + 1);
    const Twist free{1.5 * total * u(rng), 1.5 * total * u(rng), 3 * total * u(rng)};
    const PatchImpulseResult r = solver.solve(cs, j, free);
    const Twist o = ray_oracle(cs, j, free);
    ++modes[static_cast<int>(r.mode)];
    const double scale = std::hypot(free[0], free[1], free[2]);
    for (int i = 0; i < 3; ++i) ASSERT_NEAR(r.twist[i], o[i], 1e-6 * scale) << trial << " " << i << " mode " << (int)r.mode << " f " << patch_objective(cs, j, free, r.twist) << " fo " << patch_objective(cs, j, free, o) << " sw " << r.sweeps << " nt " << r.newton_steps;
    ASSERT_LE(patch_objective(cs, j, free, r.twist),
              patch_objective(cs, j, free, o) + 1e-13 * scale * scale)
        << trial;
    if (r.mode == PatchMode::stick) {
      ASSERT_EQ(r.twist, (Twist{0, 0, 0}));  // exactly
    }
    if (r.mode == PatchMode::pivot) {  // zero slip at the pivot contact, exactly up to round-off
      const auto& p = cs[static_cast<std::size_t>(r.pivot)];
      ASSERT_LE(std::hypot(r.twist[0] - r.twist[2] * p.dy, r.twist[1] + r.twist[2] * p.dx),
                1e-15 * scale);
    }
  }
  EXPECT_GT(modes[0], 10);  // each case is exercised
  EXPECT_GT(modes[1], 5);
  EXPECT_GT(modes[2], 100);
}

TEST(PatchImpulse, StickIsDecidedByTheLimitSetNotBySmallVelocities) {
  // Two contacts at (+-1, 0) with bounds 1: L contains the wrench (0.9, 0, 0) hence every
  // scaled copy t (0.9, 0, 0), t <= 1.11: the solver returns an exact zero however small or
  // large the free twist inside, and a non-zero slip just outside (t = 1.2).
  const std::vector<PatchContact> cs{{1, 0, 1, 1}, {-1, 0, 1, 1}};
  PatchImpulseSolver solver;
  for (double t : {1e-12, 1e-3, 0.5, 1.1}) {
    const PatchImpulseResult r = solver.solve(cs, 0.5, {2 * 0.9 * t, 0, 0});
    EXPECT_EQ(r.mode, PatchMode::stick) << t;
    EXPECT_EQ(r.twist, (Twist{0, 0, 0})) << t;
  }
  const PatchImpulseResult r = solver.solve(cs, 0.5, {2 * 0.9 * 1.2, 0, 0});
  EXPECT_EQ(r.mode, PatchMode::slip);
  EXPECT_NEAR(r.twist[0], 2 * 0.9 * 1.2 - 2, 1e-12);  // straight slide: v* - sum c
}

// ---- the stepper ------------------------------------------------------------------------------

TEST(PlanarRigid, OnePointAtTheCentreIsThePointStepper) {
  PlanarTableMotion motion;
  motion.first = &kPaperMotion;
  motion.second = &kCrossMotion;
  const PlanarField field = HalfPlaneStepField{0.05, 0.02, 0.4, 0.06, 2.0};
  const FrictionLaw law(1.3, 1.0);
  TimeSteppingOptions o;
  o.step = 1e-3;
  RigidPart part;  // point patch, j = 0.5
  PlanarRigidState r = make_planar_rigid_state(motion, 0, {0, 0, 0.3}, {0.2, -0.1, 0});
  PlanarPointState p = make_planar_point_state(motion, 0, 0, 0, 0.2, -0.1);
  for (int block = 0; block < 50; ++block) {
    advance_planar_rigid(motion, field, law, part, o, r, 100);
    advance_planar_point(motion, field, law, o, p, 100);
    const PlanarPose pose = r.pose;
    const PlanarTwist tw = r.twist;
    ASSERT_NEAR(pose.x, p.x, 1e-12) << block;
    ASSERT_NEAR(pose.y, p.y, 1e-12) << block;
    ASSERT_NEAR(tw.ux, p.ux, 1e-12) << block;
    ASSERT_NEAR(tw.uy, p.uy, 1e-12) << block;
    ASSERT_EQ(r.twist.omega, 0);
  }
  EXPECT_GT(std::hypot(p.x, p.y), 0.02);
  // A spinning point contact keeps its spin (no friction moment at the centre of mass).
  PlanarRigidState spin = make_planar_rigid_state(motion, 0, {0, 0, 0}, {0.2, -0.1, 0.7});
  advance_planar_rigid(motion, field, FrictionLaw{}, part, o, spin, 2000);
  EXPECT_EQ(spin.twist.omega, 0.7);
  EXPECT_NEAR(spin.pose.angle, 0.7 * 2.0, 1e-12);
}

TEST(PlanarRigid, ASymmetricPatchOnATableAlongXIsTheOneDimensionalScheme) {
  // A 4 x 3 rectangle patch (symmetric about the x axis) on a uniform table moving along x:
  // no moment, no sideways force: it is the 1-D scheme term for term (to the Newton tolerance).
  PlanarTableMotion motion;
  motion.first = &kPaperMotion;
  RigidPart part{0.3, rectangle_patch(0.4, 0.2, 4, 3)};
  const FrictionLaw law(1.4, 1.0);
  TimeSteppingOptions o;
  o.step = 1e-3;
  const UniformFriction one_d;
  TimeSteppingState ref = make_time_stepping_state(kPaperMotion, {0, 0, 0.2});
  PlanarRigidState r = make_planar_rigid_state(motion, 0, {0, 0, 0}, {0.2, 0, 0});
  int sticks = 0;
  for (int block = 0; block < 100; ++block) {
    advance_time_stepping(kPaperMotion, one_d, law, o, ref, 50);
    advance_planar_rigid(motion, UniformPlanarField{1.0}, law, part, o, r, 50);
    const PlanarPose pose = r.pose;
    ASSERT_NEAR(pose.x, ref.object.x, 1e-11) << block;
    ASSERT_NEAR(r.twist.ux, ref.object.xd, 1e-11) << block;
    ASSERT_NEAR(pose.y, 0, 1e-13);
    ASSERT_NEAR(pose.angle, 0, 1e-13);
    sticks += r.mode == PatchMode::stick;
  }
  EXPECT_GT(sticks, 5);
  EXPECT_GT(std::abs(ref.object.x), 0.01);
}

struct EnergyCheck : MotionObserver {
  // On a translating table the table's twist is a uniform velocity T': the kinetic energy
  // relative to T'_{k+1} after the step, |V_{k+1} - T'_{k+1}|^2 + j omega^2, never exceeds the
  // free one, |V_k - T'_{k+1}|^2 + j omega_k^2 (the friction impulse only removes energy).
  double inertia;
  PlanarTwist before;
  int checked = 0, stuck = 0;
  EnergyCheck(double j, const PlanarRigidState& s) : inertia(j), before(world_twist(s)) {}
  void on_step(const core::State& s) override {
    const core::BodyState& b = s.bodies[0];
    const PlanarTwist after = world_twist(s.table, b.pose, b.twist);
    const auto energy = [&](const PlanarTwist& q) {
      const double ux = q.ux - s.table.vx, uy = q.uy - s.table.vy;
      return ux * ux + uy * uy + inertia * q.omega * q.omega;
    };
    if (!(energy(after) <= energy(before) * (1 + 1e-12))) ADD_FAILURE() << s.step_index;
    ++checked;
    stuck += b.mode == PatchMode::stick;
    before = after;
  }
};

TEST(PlanarRigid, FrictionNeverAddsKineticEnergy) {
  // On a translating table the table twist is a uniform velocity: the relative kinetic energy
  // after the step never exceeds the free one (M-norm of delta <= M-norm of delta*).
  PlanarTableMotion motion;
  motion.first = &kPaperMotion;
  motion.second = &kCrossMotion;
  RigidPart part{0.02, polygon_patch({0, 0.3, 0.1, -0.2}, {-0.1, 0.05, 0.2, 0.1}, 2)};
  const PlanarField field = CircularPocketField{0.05, 0.0, 0.1, 0.05, 3.0};
  PlanarRigidState r = make_planar_rigid_state(motion, 0, {0, 0, 0.4}, {0.3, 0.1, 2.0});
  EnergyCheck check(part.inertia, r);
  TimeSteppingOptions o;
  o.step = 2e-3;
  advance_planar_rigid(motion, field, FrictionLaw(1.5, 1.0), part, o, r, 5000, &check);
  EXPECT_EQ(check.checked, 5000);
  EXPECT_GT(check.stuck, 100);
}

TEST(PlanarRigid, RotatingTheSetupRotatesTheSolution) {
  // Translation along two directions, an oscillating table rotation, a rectangular pocket and a
  // polygon patch: the same setup turned by alpha gives the turned trajectory to round-off.
  const double alpha = 0.9, c = std::cos(alpha), s = std::sin(alpha);
  const FourierProfile turn(1.0, {0.05}, {0.02});
  PlanarTableMotion a;
  a.first = &kPaperMotion, a.second = &kCrossMotion, a.rotation = &turn;
  PlanarTableMotion b = a;
  b.e1_x = c, b.e1_y = s, b.e2_x = -s, b.e2_y = c;
  RigidPart part{0.01, polygon_patch({0, 0.2, 0.1, -0.1}, {-0.1, 0.0, 0.15, 0.05}, 2)};
  const PlanarField field = RectangularPocketField{0.1, 0.05, 0.3, 0.1, 0.05, 0.04, 2.5};
  const FrictionLaw law(1.2, 1.0);
  TimeSteppingOptions o;
  o.step = 1e-3;
  PlanarRigidState ra = make_planar_rigid_state(a, 0, {0.01, 0.02, 0.3}, {0.1, -0.2, 1.0});
  PlanarRigidState rb = make_planar_rigid_state(
      b, 0, {c * 0.01 - s * 0.02, s * 0.01 + c * 0.02, 0.3 + alpha}, {c * 0.1 + s * 0.2, s * 0.1 - c * 0.2, 1.0});
  const PlanarField fb = rotated_field(field, alpha);
  for (int block = 0; block < 30; ++block) {
    advance_planar_rigid(a, field, law, part, o, ra, 200);
    advance_planar_rigid(b, fb, law, part, o, rb, 200);
    const PlanarPose pa = ra.pose, pb = rb.pose;
    ASSERT_NEAR(pb.x, c * pa.x - s * pa.y, 1e-9) << block;
    ASSERT_NEAR(pb.y, s * pa.x + c * pa.y, 1e-9) << block;
    ASSERT_NEAR(pb.angle, pa.angle + alpha, 1e-9) << block;
    ASSERT_EQ(ra.mode, rb.mode) << block;
  }
  EXPECT_GT(std::hypot(ra.pose.x, ra.pose.y), 0.02);
}

TEST(PlanarRigid, AStickingPartTurnsWithTheTable) {
  // A slowly oscillating table rotation whose largest acceleration at the patch (0.05 rad,
  // period 1 -> psi'' <= 2, lever <= 0.15: <= 0.3 plus centripetal) stays inside the static
  // bound 1: the part starting at rest on the table keeps its table pose exactly.
  const FourierProfile turn(1.0, {0.05}, {0.0});
  PlanarTableMotion motion;
  motion.rotation = &turn;
  RigidPart part{0.01, rectangle_patch(0.2, 0.1, 3, 3)};
  PlanarRigidState r = make_planar_rigid_state(motion, 0, {0.1, 0.05, 0.2}, {0, 0, 0});
  TimeSteppingOptions o;
  o.step = 1e-3;
  advance_planar_rigid(motion, UniformPlanarField{1.0}, FrictionLaw{}, part, o, r, 3000);
  const PlanarPose p = r.pose;
  EXPECT_NEAR(p.x, 0.1, 1e-12);
  EXPECT_NEAR(p.y, 0.05, 1e-12);
  EXPECT_NEAR(p.angle, 0.2, 1e-12);
  EXPECT_EQ(r.mode, PatchMode::stick);
}

struct StopTimes : MotionObserver {
  double t_slide = NAN, t_spin = NAN;
  void on_step(const core::State& s) override {
    const PlanarTwist& u = s.bodies[0].twist;
    if (std::isnan(t_slide) && u.ux == 0 && u.uy == 0) t_slide = s.t;
    if (std::isnan(t_spin) && u.omega == 0) t_spin = s.t;
  }
};

// 12 x 24 points; 6 x 12 in the sanitizer build.
constexpr int kRings = kSanitized ? 6 : 12;

StopTimes launch_disc(double h, double v0, double w0, int rings = kRings, int sectors = 2 * kRings) {
  const double radius = 0.2;
  RigidPart part{radius * radius / 2, disc_patch(radius, rings, sectors)};
  PlanarTableMotion still;  // no profile: the table is at rest
  PlanarRigidState r = make_planar_rigid_state(still, 0, {0, 0, 0}, {v0, 0, w0});
  StopTimes times;
  TimeSteppingOptions o;
  o.step = h;
  const double horizon = v0 + 0.75 * std::abs(w0) * radius + 0.1;
  advance_planar_rigid(still, UniformPlanarField{1.0}, FrictionLaw{}, part, o, r,
                       static_cast<long long>(horizon / h), &times);
  return times;
}

TEST(PlanarRigid, AUniformDiscStopsSlidingAndSpinningAtTheSameInstant) {
  // Closed forms first (pure slide: t = v0 / k; pure spin: t = j omega0 / torque with
  // torque = sum w_i |p_i| = (2/3) R up to the quadrature's O(1/sectors^2 + 1/rings^2)).
  const double radius = 0.2;
  const double hc = kSanitized ? 1e-3 : 1e-4;
  EXPECT_NEAR(launch_disc(hc, 0.3, 0).t_slide, 0.3, 2 * hc);
  ContactPatch disc = disc_patch(radius, kRings, 2 * kRings);
  double torque = 0;
  for (const auto& p : disc) torque += p.load * std::hypot(p.x, p.y);
  // cell centroids sit at sinc(pi/sectors) of the sector's mean radius: 1 - sinc(pi/24) = 2.9e-3,
  // 1 - sinc(pi/12) = 1.1e-2
  EXPECT_NEAR(torque, 2 * radius / 3, (kSanitized ? 1.5e-2 : 4e-3) * 2 * radius / 3);
  EXPECT_NEAR(launch_disc(hc, 0, 5).t_spin, radius * radius / 2 * 5 / torque, 2 * hc);
  // Combined: both stop together, at the instant a second method gives: RK4 on the smooth
  // sliding-and-spinning equations (the same contact points, friction k w_i against each
  // point's slip direction), run until the slip is below 1e-9; Moreau's common stop instant
  // converges to it with the step order.
  const std::vector<std::pair<double, double>> launches =
      kSanitized ? std::vector<std::pair<double, double>>{{0.1, 5.0}, {0.3, 0.5}}
                 : std::vector<std::pair<double, double>>{{0.3, 2.0}, {0.1, 5.0}, {0.3, 0.5}};
  for (const auto& [v0, w0] : launches) {
    const double t_rk4 = rk4_stop_time(disc, radius * radius / 2, v0, w0, 1e-4);
    double err_prev = HUGE_VAL;
    for (double h : {1e-3, 1e-4}) {
      const StopTimes t = launch_disc(h, v0, w0);
      ASSERT_FALSE(std::isnan(t.t_slide));
      EXPECT_EQ(t.t_slide, t.t_spin) << v0 << " " << w0 << " h " << h;  // the same step
      const double err = std::abs(t.t_slide - t_rk4);
      RecordProperty("stop_error_h" + std::to_string(h), std::to_string(err));
      if (std::getenv("SELFALIGN_PRINT")) std::printf("v0 %g w0 %g h %g Moreau %.6f RK4 %.6f err %.2e\n", v0, w0, h, t.t_slide, t_rk4, err);
      EXPECT_LE(err, 2 * h) << v0 << " " << w0 << " h " << h;
      EXPECT_LT(err, err_prev / 3);  // first order: ~10x per decade of h
      err_prev = err;
    }
  }
}

TEST(PlanarRigid, TheAsymptoticDriftDoesNotDependOnTheInitialTwist) {
  // Uniqueness: a table moving along x and y (Sect. 7.2 and a cross motion at twice the
  // frequency) walks a disc patch part; 12 random initial twists end in the same periodic
  // drift and spin (to 1e-9 per period after the transient).
  PlanarTableMotion motion;
  motion.first = &kPaperMotion, motion.second = &kCrossMotion;
  RigidPart part{0.005, disc_patch(0.1, 3, 6)};
  const FrictionLaw law(1.2, 1.0);
  TimeSteppingOptions o;
  o.step = 1e-3;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  double ref[3] = {NAN, NAN, NAN};
  for (int trial = 0; trial < (kSanitized ? 3 : 12); ++trial) {
    PlanarRigidState r = make_planar_rigid_state(motion, 0, {0, 0, 0},
                                                 {u(rng), u(rng), 10 * u(rng)});
    advance_planar_rigid(motion, UniformPlanarField{1.0}, law, part, o, r, kSanitized ? 6000 : 20'000);
    const PlanarPose a = r.pose;
    advance_planar_rigid(motion, UniformPlanarField{1.0}, law, part, o, r, 1000);
    const PlanarPose b = r.pose;
    const double drift[3] = {b.x - a.x, b.y - a.y, b.angle - a.angle};
    if (trial == 0) {
      for (int i = 0; i < 3; ++i) ref[i] = drift[i];
      EXPECT_GT(std::hypot(drift[0], drift[1]), 1e-3);  // it walks
      continue;
    }
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(drift[i], ref[i], 1e-9) << trial << " " << i;
  }
}

}  // namespace
}  // namespace selfalign
