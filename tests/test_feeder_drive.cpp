// The choice of a feeder drive for a target speed (design/feeder_drive.hpp, docs/feeder.md).
// The design's own numbers are checked against what they claim (the speed at the chosen K
// reaches the target, a slightly smaller K does not, the flight bound holds, the no-flight
// design stays below the closed-form lift-off onset), and against a second method: the
// contact core's Moreau run at the designed drive conveys at the target speed to its
// order-1 error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/design/feeder_drive.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {
namespace feeder_drive_test {  // own names: the tests are built as a unity build

bool print() { return std::getenv("SELFALIGN_PRINT") != nullptr; }

FeederRun run_at(const FeederDriveOptions& o, const FeederDriveCandidate& c, double K) {
  const double w = 2 * std::numbers::pi / o.period;
  const FeederTable table({K * o.g / (w * w), o.period, c.vibration_angle, o.incline, o.g});
  return feeder_run_exact(table, FrictionLaw(o.mu_static, o.mu_kinetic), o.g, o.periods);
}

TEST(FeederDrive, TheLeastDriveReachesTheTargetAndMoreauAgrees) {
  // SI: 50 Hz, a track rising by 0.02 rad, mu 0.5 / 0.4: 0.01 m/s without a flight (this
  // drive conveys at most about 0.02 m/s while the part stays on the track) and, with a
  // flight angle of at most 3 rad: 0.03 m/s.
  for (const double max_flight : {0.0, 3.0}) {
    SCOPED_TRACE(max_flight);
    FeederDriveOptions o;
    o.incline = 0.02, o.g = 9.81, o.period = 0.02;
    o.target_speed = max_flight == 0 ? 0.01 : 0.03;
    o.max_flight_angle = max_flight;
    const FeederDriveDesign d = design_feeder_drive(o);
    const FeederDriveCandidate& b = d.best;
    if (print() || !d.feasible) {
      for (const auto& c : d.candidates)
        std::printf("psi %.2f: %s K %.10f a0 %.4e Gamma %.4f v %.8f flight %.4f %s\n", c.vibration_angle, c.feasible ? "feasible" : "infeasible", c.machine_number, c.amplitude, c.throw_number, c.speed, c.flight_angle, c.reason.c_str());
      std::printf("best psi %.2f K %.10f\n", b.vibration_angle, b.machine_number);
    }
    ASSERT_TRUE(d.feasible);
    for (const FeederDriveCandidate& c : d.candidates)
      if (c.feasible) EXPECT_GE(c.machine_number, b.machine_number);
    // what it claims: the target reached at K, not at K (1 - 1e-6); the flight bound kept
    EXPECT_GE(run_at(o, b, b.machine_number).velocity, o.target_speed);
    EXPECT_LT(run_at(o, b, b.machine_number * (1 - 1e-6)).velocity, o.target_speed);
    EXPECT_NEAR(b.speed, o.target_speed, 1e-6 * o.target_speed);
    const FeederOnsets on = feeder_onsets(b.vibration_angle, o.incline, o.mu_static);
    if (max_flight == 0) {
      EXPECT_LE(b.machine_number, on.lift_off);  // Gamma <= 1: it never leaves the track
      EXPECT_LE(b.throw_number, 1.0);
      EXPECT_EQ(b.flight_angle, 0.0);
    } else {
      EXPECT_LE(b.flight_angle, max_flight);
    }
    // the second method: Moreau(-Jean) at the designed drive, 20 000 steps per period
    const double w = 2 * std::numbers::pi / o.period;
    const FeederTable table({b.amplitude, o.period, b.vibration_angle, o.incline, o.g});
    EXPECT_NEAR(b.amplitude, b.machine_number * o.g / (w * w), 1e-15);
    const FeederRun moreau = feeder_run(
        feeder_model(table, FrictionLaw(o.mu_static, o.mu_kinetic), o.g, 20000), o.period,
        o.periods);
    if (print()) std::printf("Moreau at the design: %.8f (target %.8f)\n", moreau.velocity, o.target_speed);
    EXPECT_NEAR(moreau.velocity, o.target_speed, 2e-3 * o.target_speed);
  }
}

TEST(FeederDrive, AnUnreachableTargetIsAResultNotAnError) {
  FeederDriveOptions o;
  o.target_speed = 100.0;  // model units: far beyond any drive up to k_max = 10
  o.vibration_angles = {0.2, 0.6};
  const FeederDriveDesign d = design_feeder_drive(o);
  EXPECT_FALSE(d.feasible);
  EXPECT_TRUE(std::isnan(d.best.machine_number));
  ASSERT_EQ(d.candidates.size(), 2u);
  for (const FeederDriveCandidate& c : d.candidates) {
    EXPECT_FALSE(c.feasible);
    EXPECT_FALSE(c.reason.empty());
    EXPECT_TRUE(std::isnan(c.amplitude));
  }
}

TEST(FeederDrive, BadOptionsAreRefusedByName) {
  const auto names = [](FeederDriveOptions o, const char* name) {
    try {
      (void)design_feeder_drive(o);
      ADD_FAILURE() << "accepted; expected " << name;
    } catch (const InvalidParameter& e) {
      EXPECT_EQ(e.name(), name);
    }
  };
  FeederDriveOptions o;
  o.target_speed = 0.1;
  FeederDriveOptions bad = o;
  bad.target_speed = 0;
  names(bad, "target_speed");
  bad = o, bad.max_flight_angle = -1;
  names(bad, "max_flight_angle");
  bad = o, bad.vibration_angles = {2.0};
  names(bad, "vibration_angles");
  bad = o, bad.k_samples = 1;
  names(bad, "k_samples");
  bad = o, bad.mu_kinetic = 0.9;
  names(bad, "mu_kinetic");
}

}  // namespace feeder_drive_test
}  // namespace
}  // namespace selfalign
