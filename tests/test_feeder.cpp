// The vibratory feeder (analysis/feeder.hpp, docs/feeder.md). Expected values come from closed
// forms derived in docs/feeder.md; the second method is the contact core's Moreau step with
// gravity and the table's normal motion (core/step.hpp), which knows nothing of them:
//  - the onsets: a part at rest on the track under the sinusoidal drive first slips forward,
//    slips backward or lifts off where the closed forms say, to a 3 % grid in K;
//  - a square-wave drive along the vibration line conveys only through the load modulation;
//    its steady speed in closed form, and Moreau converging to it with order 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/analysis/feeder_exact.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {
namespace feeder_test {  // own names: the tests are built as a unity build

bool print() { return std::getenv("SELFALIGN_PRINT") != nullptr; }

TEST(Feeder, OnsetsOnALevelTrackWithoutNormalMotionAreTheFrictionCoefficient) {
  // psi = 0, theta = 0: the classical horizontal shaker, |a_x| <= mu_s g: both slips at
  // K = mu_s, no lift-off.
  const FeederOnsets o = feeder_onsets(0, 0, 0.4);
  EXPECT_DOUBLE_EQ(o.forward_slip, 0.4);
  EXPECT_DOUBLE_EQ(o.backward_slip, 0.4);
  EXPECT_TRUE(std::isinf(o.lift_off));
  // Gamma = 1 is the lift-off: K sin(psi) = cos(theta).
  const FeederOnsets tilted = feeder_onsets(0.5, 0.1, 0.4);
  EXPECT_DOUBLE_EQ(tilted.lift_off, std::cos(0.1) / std::sin(0.5));
  // Steeper than the friction angle: no part is held at rest (0).
  EXPECT_EQ(feeder_onsets(0.2, 0.5, 0.3).backward_slip, 0.0);
}

// The drive of machine number K on a unit period with g = 1.
FeederDrive drive_at(double K, double psi, double theta) {
  const double w = 2 * std::numbers::pi;
  return {K / (w * w), 1.0, psi, theta, 1.0};
}

TEST(Feeder, MoreauFindsTheOnsetsWhereTheClosedFormsSay) {
  // (psi, theta, mu_s): forward slip first (a level track; a downhill track with the drive
  // pointing down), backward slip first (a steep uphill track). From rest, three periods at
  // 4000 steps per period, at 0.97 and 1.03 times the first slip's onset: nothing, then that
  // slip; and at 0.97 and 1.03 times the lift-off onset: in contact, then lifted off. (A slip
  // always comes before the lift-off: K_f < K_l iff cos(psi + theta) > 0, K_b < K_l iff
  // cos(psi + theta) < 0, docs/feeder.md.)
  struct Case {
    double psi, theta, mu;
    FeederEvent first;
  };
  const Case cases[] = {{0.35, 0.0, 0.5, FeederEvent::forward_slip},
                        {0.2, 0.25, 0.5, FeederEvent::backward_slip},
                        {-0.3, -0.2, 0.6, FeederEvent::forward_slip},
                        {1.1, 0.05, 1.2, FeederEvent::forward_slip}};
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << "psi " << c.psi << " theta " << c.theta << " mu " << c.mu);
    const FeederOnsets o = feeder_onsets(c.psi, c.theta, c.mu);
    const double slip = std::min(o.forward_slip, o.backward_slip);
    ASSERT_EQ(slip == o.forward_slip ? FeederEvent::forward_slip : FeederEvent::backward_slip,
              c.first);
    ASSERT_GT(std::max(o.forward_slip, o.backward_slip), 1.1 * slip);  // off the grid's points
    ASSERT_LT(slip, o.lift_off);
    const FrictionLaw law(c.mu, 0.8 * c.mu);
    const auto run_at = [&](double K) {
      const FeederTable table(drive_at(K, c.psi, c.theta));
      return feeder_run(feeder_model(table, law, 1.0, 4000), 1.0, 3);
    };
    for (const double factor : {0.97, 1.03}) {
      const FeederRun run = run_at(factor * slip);
      if (print()) std::printf("psi %g theta %g mu %g: K %.4f (slip onset %.4f): %s at %.4f\n", c.psi, c.theta, c.mu, factor * slip, slip, feeder_event_name(run.first_event), run.first_event_time);
      EXPECT_EQ(run.first_event, factor < 1 ? FeederEvent::none : c.first) << factor;
      const FeederRun lift = run_at(factor * o.lift_off);
      if (print()) std::printf("  K %.4f (lift-off onset %.4f): lifted off %d at %.4f\n", factor * o.lift_off, o.lift_off, lift.lifted_off, lift.first_event_time);
      EXPECT_EQ(lift.lifted_off, factor > 1) << factor;
    }
  }
}

// A square wave of acceleration +-A along the vibration line at psi (half a period each) on a
// track at theta: phase 1 (+A) presses the part on with g cos theta + A sin psi and holds it,
// phase 2 (-A) unloads it to g cos theta - A sin psi and it slips forward. docs/feeder.md:
// the steady displacement per period is a2 (T/2)^2 / 2 + (a2 T/2)^2 / (2 a1), with
// a2 = A cos psi - g sin theta - mu_k n2 and a1 = A cos psi + g sin theta + mu_k n1.
struct SquareWave {
  double A = 0.8, psi = 0.5, theta = 0.05, mu_s = 0.6, mu_k = 0.5, T = 1.0, g = 1.0;
  double n1() const { return g * std::cos(theta) + A * std::sin(psi); }
  double n2() const { return g * std::cos(theta) - A * std::sin(psi); }
  double a1() const { return A * std::cos(psi) + g * std::sin(theta) + mu_k * n1(); }
  double a2() const { return A * std::cos(psi) - g * std::sin(theta) - mu_k * n2(); }
  double speed() const {
    const double u = a2() * T / 2;
    return (0.5 * a2() * (T / 2) * (T / 2) + u * u / (2 * a1())) / T;
  }
};

TEST(Feeder, ASquareWaveDriveConveysByTheLoadModulationAsTheClosedFormSays) {
  const SquareWave w;
  // The closed form's assumptions: held in phase 1, slipping forward in phase 2, the slip
  // stopping within phase 1, and no lift-off.
  ASSERT_LE(std::abs(w.A * std::cos(w.psi) + w.g * std::sin(w.theta)), w.mu_s * w.n1());
  ASSERT_GT(w.A * std::cos(w.psi) - w.g * std::sin(w.theta), w.mu_s * w.n2());
  ASSERT_LT(w.a2(), w.a1());
  ASSERT_GT(w.n2(), 0);
  const std::vector<double> halves = {w.T / 2, w.T / 2};
  const PiecewisePolynomialProfile along = PiecewisePolynomialProfile::from_accelerations(
      halves, std::vector<double>{w.A * std::cos(w.psi), -w.A * std::cos(w.psi)});
  const PiecewisePolynomialProfile normal = PiecewisePolynomialProfile::from_accelerations(
      halves, std::vector<double>{w.A * std::sin(w.psi), -w.A * std::sin(w.psi)});
  const FrictionLaw law(w.mu_s, w.mu_k);  // level 1, g = 1: the absolute coefficients
  double previous = HUGE_VAL;
  for (const long long n : {200LL, 2000LL, 20000LL}) {
    core::Model model;
    model.motion.first = &along;
    model.motion.normal = &normal;
    model.field = UniformPlanarField{1.0};
    model.bodies = {core::SliderBody{PointFootprint{}, law}};
    model.options = {w.T / static_cast<double>(n), 0.5};
    model.gravity = core::Gravity{w.g, w.theta, -1, 0};
    const FeederRun run = feeder_run(model, w.T, 4);
    const double error = std::abs(run.velocity - w.speed());
    if (print()) std::printf("steps %lld: speed %.10f closed form %.10f error %.3e stick %.3f\n", n, run.velocity, w.speed(), error, run.stick_fraction);
    EXPECT_EQ(run.first_event, FeederEvent::forward_slip);
    EXPECT_LT(error, 2.0 / static_cast<double>(n)) << n;
    if (n > 200) EXPECT_LT(error, previous / 5) << n;  // order ~1: ~10x per decade
    previous = error;
  }
}

// The square wave's two profiles (along the track and along its normal).
struct SquareWaveTrack {
  std::vector<double> halves;
  PiecewisePolynomialProfile along, normal;
  explicit SquareWaveTrack(const SquareWave& w)
      : halves{w.T / 2, w.T / 2},
        along(PiecewisePolynomialProfile::from_accelerations(
            halves, std::vector<double>{w.A * std::cos(w.psi), -w.A * std::cos(w.psi)})),
        normal(PiecewisePolynomialProfile::from_accelerations(
            halves, std::vector<double>{w.A * std::sin(w.psi), -w.A * std::sin(w.psi)})) {}
  FeederTrack track(const SquareWave& w) const {
    return {&along, &normal, w.g, w.theta, 1.0, FrictionLaw(w.mu_s, w.mu_k)};
  }
};

TEST(FeederExact, WithoutNormalMotionOnALevelTrackItIsTheOneDimensionalExactSolver) {
  // psi = 0, theta = 0: the paper's model. Sect. 7.2's profile, s = k and s > k, g = 2 (any g:
  // the bound is s m (g cos 0) / g = s m): the 1-D exact solver's trajectory over 30 periods,
  // on a uniform level and on a friction step (1 -> 2.5 at a place the part walks through,
  // without a transition width: the slip's boundary event).
  const ThreePhaseProfile paper({1.0, 0.084, 3.0, 0.9});
  const ThreePhaseProfile case3({1.0, 0.084, 2.3, 1.3});
  for (const ThreePhaseProfile* profile : {&paper, &case3}) {
    for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.3, 1.0)}) {
      for (const bool stepped : {false, true}) {
        SCOPED_TRACE(::testing::Message() << law.describe() << (stepped ? ", step" : ""));
        // the step at half the distance walked on the uniform level in 30 periods
        const UniformFriction one_d;
        FeederExactState probe;
        advance_feeder_exact({profile, nullptr, 2.0, 0.0, 1.0, law}, probe, 30.0);
        const AffinePiece pieces[2] = {{-kInf, 0.5 * probe.x, 1.0, 0.0},
                                       {0.5 * probe.x, kInf, 2.5, 0.0}};
        const PiecewiseAffineFriction step(pieces);
        const PiecewiseAffineFriction& level = stepped ? step : *one_d.piecewise_affine();
        const ExactSetup setup{*profile->piecewise_polynomial(), level, law};
        ExactState ref = make_exact_state(setup, {0, 0, 0});
        FeederTrack track{profile, nullptr, 2.0, 0.0, 1.0, law};
        if (stepped) track.field = &step;
        FeederExactState s;
        double worst = 0;
        for (int p = 1; p <= 30; ++p) {
          advance_exact(setup, ref, p);
          advance_feeder_exact(track, s, p);
          worst = std::max({worst, std::abs(s.x - ref.object.x) / (1 + std::abs(ref.object.x)),
                            std::abs(s.u - ref.object.xd)});
        }
        if (print()) std::printf("%s%s: end %.6f (uniform %.6f), worst %.2e\n", law.describe().c_str(), stepped ? " step" : "", s.x, probe.x, worst);
        EXPECT_LT(worst, 1e-12);
        EXPECT_GT(std::abs(s.x), 1e-2);
        if (stepped) EXPECT_GT(std::abs(s.x), std::abs(0.5 * probe.x));  // it crossed the step
      }
    }
  }
}

// Four periods from rest by the exact solver: the state, its statistics, and the distance
// covered in the fourth (a steady period: the first differs, it starts at rest).
struct FourPeriods {
  FeederExactState end;
  FeederExactStatistics stats;
  double distance = 0;
};
FourPeriods four_periods(const SquareWave& w, const SquareWaveTrack& sq) {
  FourPeriods r;
  advance_feeder_exact(sq.track(w), r.end, 3 * w.T, &r.stats);
  const double x3 = r.end.x;
  advance_feeder_exact(sq.track(w), r.end, 4 * w.T, &r.stats);
  r.distance = r.end.x - x3;
  return r;
}

TEST(FeederExact, TheSquareWaveDriveConveysAtTheClosedFormSpeed) {
  const SquareWave w;
  const SquareWaveTrack sq(w);
  const FourPeriods r = four_periods(w, sq);
  if (print()) std::printf("exact square wave: %.15f closed form %.15f\n", r.distance / w.T, w.speed());
  EXPECT_NEAR(r.distance / w.T, w.speed(), 1e-12);
  EXPECT_EQ(r.stats.lift_offs, 0);
}

// The square wave's hopping drive of HoppingFliesAndLandsAsTheFlightEquationSays.
SquareWave hopping_wave() {
  SquareWave w;
  w.A = 2.5, w.psi = 0.6, w.theta = 0.05, w.mu_s = 20, w.mu_k = 20;
  return w;
}

// Hopping: the same square wave unloads the part below zero in its second half (A sin psi >
// g cos theta): it lifts off at T/2 with the track's velocity, flies under h'' = -n2 > 0, then
// h'' = -n1 < 0 from T, and lands at T + tau_L with tau_L = (w2 + sqrt(w2^2 + 2 n1 h2)) / n1,
// h2 = -n2 (T/2)^2 / 2, w2 = -n2 T/2 (the flight equation of this drive). Friction so high that
// it is held whenever it is on the track and sticks at landing: the distance per period is the
// flight's, in closed form: d = c2 (T/2)^2 / 2 + c2 (T/2) tau_L - c1 tau_L^2 / 2
// with c2 = A cos psi - g sin theta, c1 = A cos psi + g sin theta (no friction in flight).
TEST(FeederExact, HoppingFliesAndLandsAsTheFlightEquationSays) {
  const SquareWave w = hopping_wave();
  ASSERT_LT(w.n2(), 0);
  const double h2 = -0.5 * w.n2() * (w.T / 2) * (w.T / 2), w2 = -w.n2() * w.T / 2;
  const double tau_l = (w2 + std::sqrt(w2 * w2 + 2 * w.n1() * h2)) / w.n1();
  ASSERT_LT(tau_l, w.T / 2);
  const double c2 = w.A * std::cos(w.psi) - w.g * std::sin(w.theta);
  const double c1 = w.A * std::cos(w.psi) + w.g * std::sin(w.theta);
  const double d = 0.5 * c2 * (w.T / 2) * (w.T / 2) + c2 * (w.T / 2) * tau_l - 0.5 * c1 * tau_l * tau_l;
  const SquareWaveTrack sq(w);
  const FourPeriods r = four_periods(w, sq);
  const FeederExactState& s = r.end;
  const FeederExactStatistics& stats = r.stats;
  if (print()) std::printf("hopping: distance %.15f closed form %.15f, tau_L %.6f, lift-offs %lld landings %lld (stick %lld)\n", r.distance, d, tau_l, stats.lift_offs, stats.landings, stats.stick_landings);
  EXPECT_NEAR(r.distance, d, 1e-12);
  EXPECT_EQ(stats.lift_offs, 4);
  EXPECT_EQ(stats.landings, 3);  // the fourth lands at 4 T + tau_L
  EXPECT_EQ(stats.stick_landings, 3);
  // In flight just before the landing, held just after it.
  FeederExactState before = s, after = s;
  advance_feeder_exact(sq.track(w), before, 4 * w.T + tau_l - 1e-9);
  advance_feeder_exact(sq.track(w), after, 4 * w.T + tau_l + 1e-9);
  EXPECT_EQ(before.mode, FeederMode::flight);
  EXPECT_GT(before.h, 0);
  EXPECT_EQ(after.mode, FeederMode::stick);
  EXPECT_EQ(after.h, 0);
}

// The core's model of a square wave with n steps per period, flight (Moreau-Jean) on or off.
core::Model square_wave_model(const SquareWave& w, const SquareWaveTrack& sq, long long n,
                              bool flight) {
  core::Model model;
  model.motion.first = &sq.along;
  model.motion.normal = &sq.normal;
  model.field = UniformPlanarField{1.0};
  model.bodies = {core::SliderBody{PointFootprint{}, FrictionLaw(w.mu_s, w.mu_k)}};
  model.options = {w.T / static_cast<double>(n), 0.5};
  model.gravity = core::Gravity{w.g, w.theta, -1, 0, flight};
  return model;
}

TEST(FeederMoreauJean, ConvergesToTheExactHoppingMotionWithOrderOne) {
  // The second method for flight and landing: the core's Moreau-Jean step (Gravity::flight)
  // against the exact solver on the hopping square wave, the distance of the fourth period.
  const SquareWave w = hopping_wave();
  const SquareWaveTrack sq(w);
  // Measured: errors 1.0e-3, 5.4e-5, 1.0e-5 at 200, 2000, 20000 steps per period (order 1.3
  // then 0.7: order 1 over the two decades); the flight fraction of the period is
  // (T/2 + tau_L) / T = 0.8096 to the step.
  const double exact = four_periods(w, sq).distance;
  const double h2 = -0.5 * w.n2() * (w.T / 2) * (w.T / 2), w2 = -w.n2() * w.T / 2;
  const double tau_l = (w2 + std::sqrt(w2 * w2 + 2 * w.n1() * h2)) / w.n1();
  std::vector<double> errors;
  for (const long long n : {200LL, 2000LL, 20000LL}) {
    const FeederRun run = feeder_run(square_wave_model(w, sq, n, true), w.T, 4);
    const double error = std::abs(run.velocity * w.T - exact);
    if (print()) std::printf("Moreau-Jean %lld steps: distance %.10f exact %.10f error %.3e flight %.5f stick %.3f\n", n, run.velocity * w.T, exact, error, run.flight_fraction, run.stick_fraction);
    EXPECT_TRUE(run.lifted_off);
    EXPECT_LT(error, 6.0 / static_cast<double>(n)) << n;
    EXPECT_NEAR(run.flight_fraction, (w.T / 2 + tau_l) / w.T, 2.0 / static_cast<double>(n)) << n;
    // it leaves the track at T/2 (phase pi, the first step whose normal impulse is negative)
    EXPECT_NEAR(run.lift_off_phase, std::numbers::pi, 2 * std::numbers::pi * 1.5 / static_cast<double>(n)) << n;
    EXPECT_DOUBLE_EQ(run.flight_angle, 2 * std::numbers::pi * run.flight_fraction);
    if (!errors.empty()) EXPECT_LT(error, errors.back() / 3) << n;
    errors.push_back(error);
  }
  EXPECT_LT(errors[2], errors[0] / 50);  // order >= 0.85 over two decades
}

TEST(FeederMoreauJean, ARigidPartFliesAsTheOneDimensionalPartDoes) {
  // A rigid point part and a 4 x 2 rectangle (symmetric: it translates) beside the 1-D part
  // on the hopping square wave: the same heights, positions and velocities at every period
  // end (each body has its own normal contact; a rigid part lifts off as a whole).
  const SquareWave w = hopping_wave();
  const SquareWaveTrack sq(w);
  core::Model model = square_wave_model(w, sq, 2000, true);
  const FrictionLaw law(w.mu_s, w.mu_k);
  model.bodies.push_back(core::RigidBody{{0.01, point_patch()}, law});
  model.bodies.push_back(core::RigidBody{{0.02, rectangle_patch(0.2, 0.1, 4, 2)}, law});
  const std::vector<PlanarPose> poses(3);
  const std::vector<PlanarTwist> twists(3);
  core::State s = core::make_state(model, 0.0, poses, twists);
  double worst = 0, flew = 0;
  for (int p = 1; p <= 4; ++p) {
    ASSERT_EQ(core::step(model, s, 2000), 2000);
    for (std::size_t i = 1; i < 3; ++i)
      worst = std::max({worst, std::abs(s.bodies[i].pose.x - s.bodies[0].pose.x),
                        std::abs(s.bodies[i].twist.ux - s.bodies[0].twist.ux),
                        std::abs(s.bodies[i].height - s.bodies[0].height),
                        std::abs(s.bodies[i].pose.y) + std::abs(s.bodies[i].pose.angle)});
    flew = std::max(flew, s.bodies[0].height);
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(flew, 0);  // the period ends in flight (T/2 < t - kT < T/2 + tau_L is flight)
}

TEST(FeederMoreauJean, WithoutALiftOffFlightChangesNothingButRounding) {
  // The sliding square wave never leaves the track: the Moreau-Jean normal stage gives each
  // step the load of the stop-at-lift-off path (h cos theta + Δz'/g) up to rounding.
  const SquareWave w;
  const SquareWaveTrack sq(w);
  const FeederRun with = feeder_run(square_wave_model(w, sq, 2000, true), w.T, 4);
  const FeederRun without = feeder_run(square_wave_model(w, sq, 2000, false), w.T, 4);
  EXPECT_FALSE(with.lifted_off);
  EXPECT_EQ(with.flight_fraction, 0.0);
  EXPECT_NEAR(with.velocity, without.velocity, 1e-13);
  EXPECT_EQ(with.stick_fraction, without.stick_fraction);
}

TEST(FeederChart, TheSimulatedRunsFallInTheClosedFormRegimes) {
  // A 4 x 12 chart (psi, K) on a slightly inclined track: wherever K is at least 5 % away from
  // every onset, the run of the cell (10 periods: the exact solver, and Moreau with flight at
  // 400 steps per period) does what the closed-form regime says: nothing in stick, a lift-off
  // in hopping, conveying forward where only the forward slip is crossed and backward where
  // only the backward one. The cells do not depend on the thread count; the two methods' speeds
  // agree to Moreau's order-1 error at 400 steps: measured at most 9.6e-3 in v / (a0 w cos psi)
  // below Gamma = 3.5, and 3.5e-2 at Gamma = 3.9 (past the bouncing ball's period doubling,
  // where 10 periods from rest are sensitive). The sliding cell psi = 0.2, K = 4.47 converges
  // to the exact speed with order 1 (errors 4.1e-3, 3.9e-4, 5.1e-5, 5.2e-6 at 400 ... 400 000
  // steps: tests/test_feeder_smooth_exact.cpp checks that convergence on two drives).
  FeederChartOptions o;
  o.incline = 0.03, o.mu_static = 0.5, o.mu_kinetic = 0.4, o.steps_per_period = 400;
  const std::vector<double> angles = {0.0, 0.2, 0.5, 0.9};
  std::vector<double> ks;
  for (int i = 0; i < 12; ++i) ks.push_back(0.3 * std::pow(1.35, i));
  std::vector<FeederChartCell> exact;
  for (const Method method : {Method::exact, Method::time_stepping}) {
    SCOPED_TRACE(to_string(method));
    o.method = method;
    o.threads = 1;
    const std::vector<FeederChartCell> one = feeder_regime_chart(angles, ks, o);
    o.threads = 2;
    const std::vector<FeederChartCell> two = feeder_regime_chart(angles, ks, o);
    ASSERT_EQ(one.size(), angles.size() * ks.size());
    if (exact.empty()) exact = one;
    int checked = 0, regimes[5] = {};
    double worst = 0;
    for (std::size_t i = 0; i < one.size(); ++i) {
      const FeederChartCell& c = one[i];
      EXPECT_EQ(c.run.velocity, two[i].run.velocity);
      ASSERT_TRUE(c.failure.empty()) << c.failure;
      const double diff = std::abs(c.dimensionless_speed - exact[i].dimensionless_speed);
      if (print() && diff > 1e-3) std::printf("  psi %.2f K %.3f Gamma %.3f %s: %.5f vs exact %.5f\n", c.vibration_angle, c.machine_number, c.throw_number, feeder_regime_name(c.regime), c.dimensionless_speed, exact[i].dimensionless_speed);
      worst = std::max(worst, diff);
      const FeederOnsets on = feeder_onsets(c.vibration_angle, o.incline, o.mu_static);
      bool clear = true;
      for (double k : {on.forward_slip, on.backward_slip, on.lift_off})
        clear = clear && !(std::abs(c.machine_number - k) < 0.05 * k);
      if (!clear) continue;
      ++checked, ++regimes[static_cast<int>(c.regime)];
      SCOPED_TRACE(::testing::Message() << "psi " << c.vibration_angle << " K "
                                        << c.machine_number << " regime "
                                        << feeder_regime_name(c.regime));
      EXPECT_EQ(c.run.first_event == FeederEvent::none, c.regime == FeederRegime::stick);
      EXPECT_EQ(c.run.lifted_off, c.regime == FeederRegime::hopping);
      if (c.regime == FeederRegime::forward) EXPECT_GT(c.run.velocity, 0);
      if (c.regime == FeederRegime::backward) EXPECT_LT(c.run.velocity, 0);
    }
    if (print()) std::printf("chart (%s): %d cells checked: stick %d forward %d backward %d both %d hopping %d; largest speed difference to exact %.2e\n", to_string(method).c_str(), checked, regimes[0], regimes[1], regimes[2], regimes[3], regimes[4], worst);
    EXPECT_GT(checked, 30);
    for (int r : {0, 1, 3, 4})
      EXPECT_GT(regimes[r], 0) << feeder_regime_name(static_cast<FeederRegime>(r));
    EXPECT_LT(worst, 0.05);
  }
}

// The part's energy per unit mass in the world: kinetic 1/2 |V|^2 with V = the table's velocity
// plus the relative one (along the track and its normal), and gravity's potential
// g (X sin theta + Z cos theta) at the world position (table plus relative).
double world_energy(const SquareWave& w, const SquareWaveTrack& sq, const FeederExactState& s) {
  const TableState a = sq.along.state(s.t), n = sq.normal.state(s.t);
  const double vx = a.yd + s.u, vz = n.yd + s.w;
  return 0.5 * (vx * vx + vz * vz) +
         w.g * ((a.y + s.x) * std::sin(w.theta) + (n.y + s.h) * std::cos(w.theta));
}

TEST(FeederExact, NoArcOrImpactAddsEnergyBeyondTheTablesWork) {
  // An energy audit independent of the solver's arcs: over intervals of delta = 1e-5, the
  // impulse the track gave the part is I = ΔV + g (sin theta, cos theta) delta (exact,
  // landings included), and the track's work is I . V_track at the interval's middle (the
  // track's velocity is linear on a window: error O(delta^2) per interval, O(delta |I| |a|)
  // across a landing). So E(t1) - E(t0) - W = -(friction and impact losses) <= 0 up to those
  // errors. Sliding, hopping with friction that holds at landing, and hopping with sliding
  // landings (mu = 0.3): each must lose energy somewhere (or in pure stick none).
  struct Case {
    SquareWave w;
    const char* name;
  };
  std::vector<Case> cases = {{SquareWave{}, "sliding"}, {hopping_wave(), "hopping, held"}};
  SquareWave slippery = hopping_wave();
  slippery.mu_s = 0.3, slippery.mu_k = 0.25;
  cases.push_back({slippery, "hopping, sliding landings"});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const SquareWave& w = c.w;
    const SquareWaveTrack sq(w);
    const FeederTrack track = sq.track(w);
    constexpr double delta = 1e-5;
    FeederExactState s;
    advance_feeder_exact(track, s, 1.0);  // past the start from rest
    double worst_gain = -HUGE_VAL, loss = 0;
    for (int period = 1; period < 3; ++period) {
      const double E0 = world_energy(w, sq, s);
      double W = 0;
      for (int k = 0; k < static_cast<int>(1 / delta); ++k) {
        const FeederExactState before = s;
        advance_feeder_exact(track, s, period + (k + 1) * delta);
        const TableState a0 = sq.along.state(before.t), n0 = sq.normal.state(before.t);
        const TableState a1 = sq.along.state(s.t), n1 = sq.normal.state(s.t);
        const TableState am = sq.along.state(0.5 * (before.t + s.t));
        const TableState nm = sq.normal.state(0.5 * (before.t + s.t));
        const double ix = (a1.yd + s.u) - (a0.yd + before.u) + w.g * std::sin(w.theta) * (s.t - before.t);
        const double iz = (n1.yd + s.w) - (n0.yd + before.w) + w.g * std::cos(w.theta) * (s.t - before.t);
        W += ix * am.yd + iz * nm.yd;
      }
      const double gain = world_energy(w, sq, s) - E0 - W;
      worst_gain = std::max(worst_gain, gain);
      loss += -gain;
    }
    if (print()) std::printf("%s: largest gain per period %.3e, losses over 2 periods %.4f\n", c.name, worst_gain, loss);
    EXPECT_LT(worst_gain, 1e-6);
    EXPECT_GT(loss, 1e-3);  // friction or impacts dissipate: the audit sees them
  }
}

TEST(Feeder, BadInputNamesTheParameter) {
  const auto names = [](auto f, const std::string& name) {
    try {
      f();
      ADD_FAILURE() << "accepted; expected " << name;
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.name(), name);
    }
  };
  names([] { feeder_onsets(std::numbers::pi / 2, 0, 0.5); }, "vibration_angle");
  names([] { feeder_onsets(0, -2.0, 0.5); }, "incline");
  names([] { feeder_onsets(0, 0, 0); }, "static_friction");
  names([] { FeederTable t({0, 1, 0.1, 0, 1}); }, "amplitude");
  names([] { FeederTable t({0.01, 1, 0.1, 0, -1}); }, "g");
  names([] {
    const FeederTable t({0.01, 1, 0.1, 0, 1});
    feeder_model(t, FrictionLaw{}, 1.0, 1);
  }, "steps_per_period");
}

}  // namespace feeder_test
}  // namespace
}  // namespace selfalign
