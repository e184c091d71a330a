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
#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

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
