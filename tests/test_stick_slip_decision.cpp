// Tests for simulate/stick_slip_decision.hpp: the one decision at a velocity zero, against the
// set-valued law (2) written out by hand, and the same decision seen through every solver that
// uses it (a part at rest under a table acceleration just inside / just outside the bound).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/stick_slip_decision.hpp"

namespace selfalign {
namespace {

TEST(StickSlipDecision, FollowsTheSetValuedLaw) {
  // Eq. (2) at x' = 0 with bound b: stick iff -b <= y'' <= b (the bound itself sticks);
  // beyond it the object slips against the table's push, direction -sign(y'').
  EXPECT_EQ(decide_at_rest(1.0, 1.0), 0);
  EXPECT_EQ(decide_at_rest(-1.0, 1.0), 0);
  EXPECT_EQ(decide_at_rest(-0.5, 1.0), 0);
  EXPECT_EQ(decide_at_rest(0.0, 0.0), 0);  // no friction and no push: at rest stays at rest
  EXPECT_EQ(decide_at_rest(std::nextafter(1.0, 2.0), 1.0), -1);
  EXPECT_EQ(decide_at_rest(-std::nextafter(1.0, 2.0), 1.0), 1);
  EXPECT_EQ(decide_at_rest(1e-300, 0.0), -1);
  EXPECT_EQ(decide_at_rest(std::numeric_limits<double>::quiet_NaN(), 1.0), 0);
}

TEST(StickSlipDecision, ABreakDecidesAndAStallHolds) {
  // A stick that just ended at its break slips the break's way whatever the rounding of |y''|.
  EXPECT_EQ(decide_at_rest(0.999999, 1.0, -1), -1);
  EXPECT_EQ(decide_at_rest(-0.999999, 1.0, +1), +1);
  // A stalled slip (t + tau == t) holds the object although |y''| exceeds the bound.
  EXPECT_EQ(decide_at_rest(1.0000005, 1.0, 0, true), 0);
  EXPECT_EQ(decide_at_rest(-1.0000005, 1.0, 0, true), 0);
}

// The solvers take the decision from the same function: a part at rest at t = 0 on a table
// whose acceleration is constant (piecewise-polynomial: exact and integrator) or at its extreme
// (Fourier: smooth exact), just inside or just outside the static bound s = 1.5, must stick for
// the whole first quarter of the period or leave rest at once. Expected by hand from eq. (2).
struct Outcome {
  double x, xd;
};

Outcome run_exact(double accel) {
  // y'' = accel on [0, 0.5), -accel on [0.5, 1): zero mean over the period.
  const double durations[] = {0.5, 0.5}, accels[] = {accel, -accel};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(durations, accels);
  const UniformFriction friction;
  const ExactSetup setup{profile, *friction.piecewise_affine(), FrictionLaw(1.5, 1.0)};
  ExactState s = make_exact_state(setup, {0, 0, 0});
  advance_exact(setup, s, 0.25);
  return {s.object.x, s.object.xd};
}

Outcome run_integrator(double accel) {
  const double durations[] = {0.5, 0.5}, accels[] = {accel, -accel};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(durations, accels);
  const UniformFriction friction;
  const IntegratorSetup setup{profile, *friction.piecewise_affine(),
                              FrictionLaw(1.5, 1.0).with_viscous(1e-3)};
  ObjectState s{0, 0, 0};
  advance_integrated(setup, s, 0.25);
  return {s.x, s.xd};
}

TEST(StickSlipDecision, EverySolverSticksInsideAndSlipsOutsideTheBound) {
  for (const auto& run : {run_exact, run_integrator}) {
    const Outcome inside = run(1.5), outside = run(1.6);
    EXPECT_EQ(inside.x, 0.0);  // held exactly: not creeping
    EXPECT_EQ(inside.xd, 0.0);
    EXPECT_LT(outside.x, 0.0);  // y'' > 0 pushes the part backward relative to the table
    EXPECT_LT(outside.xd, 0.0);
  }
  // Smooth exact: y = a sin(2 pi t), y'' = -a (2 pi)^2 sin(2 pi t) starts at 0 and reaches the
  // bound 1.5 at sin(2 pi t) = 1.5 / (a (2 pi)^2) when a (2 pi)^2 > 1.5, never otherwise.
  const double w2 = 4 * M_PI * M_PI;
  const UniformFriction friction;
  for (const double peak : {1.4, 1.6}) {
    const FourierProfile profile(1.0, {0.0}, {peak / w2});
    const SmoothSetup setup{profile, *friction.piecewise_affine(), FrictionLaw(1.5, 1.0)};
    ObjectState s{0, 0, 0};
    advance_smooth(setup, s, 0.25);
    if (peak < 1.5) {
      EXPECT_EQ(s.x, 0.0);
      EXPECT_EQ(s.xd, 0.0);
    } else {
      // y'' = -peak sin(2 pi t) < 0 pushes forward from sin = 1.5/peak on; at t = 0.25 the slip
      // has x'' = -1 + peak sin(2 pi t) > 0 throughout, so the part still moves forward.
      EXPECT_GT(s.xd, 0.0);
    }
  }
}

}  // namespace
}  // namespace selfalign
