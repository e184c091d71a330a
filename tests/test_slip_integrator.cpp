// Tests for simulate/slip_integrator.hpp: exact sticks, integrated slips (Odeint dopri5 with
// event location) under velocity-dependent friction, against independent numbers:
//  - static = kinetic and no viscous term: the Coulomb solution of the closed-form solvers
//    (hand-derived two-harmonic steady states, tests/oracles/single_harmonic.hpp; the exact
//    piecewise solver for a three-phase profile) to the integrator's tolerance;
//  - the global error scales with the tolerance (three decades), as documented;
//  - a viscous slip under constant table acceleration: its closed form (docs/slip-integrator.md);
//  - Stribeck with v_s -> 0 tends to the static != kinetic Coulomb solution of the exact solver;
//  - Moreau time-stepping converges to the integrator's steady state (observed order about 1);
//  - no creep: every stick holds x and x' = 0 exactly;
//  - Floquet by finite differences: the multipliers {1, 0} that position invariance and a stick
//    force on the uniform table.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <complex>
#include <limits>
#include <vector>

#include "oracles/single_harmonic.hpp"
#include "oracles/stribeck_rk4.hpp"
#include "selfalign/analysis/floquet.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"

using namespace selfalign;

namespace {

// A law that is Coulomb in value (static = kinetic: the Stribeck term is identically zero) but
// velocity-dependent in form, so every solver path takes the integrator.
FrictionLaw coulomb_through_integrator(double k) { return FrictionLaw(k, k).with_stribeck(1.0, 1.0); }

struct IntervalList final : MotionObserver {
  std::vector<MotionInterval> intervals;
  void on_motion(const MotionInterval& i, const Arc*) override { intervals.push_back(i); }
};

const ThreePhaseProfile& three_phase() {
  static const ThreePhaseProfile p(ThreePhaseParameters{1.05, 0.084, 2.2, 0.9});
  return p;
}
}  // namespace

// Static = kinetic, c = 0: the steady states of the closed forms. Fourier (two harmonics,
// hand-derived v̄): the integrator's global error at rtol 1e-10 measured 4e-11 in v̄ (about
// 0.2); 1e-9 leaves a factor 25. Three-phase (parabolic arcs, integrated exactly by a 5th-order
// method): rounding only, 1e-12.
TEST(SlipIntegrator, ReproducesTheCoulombSolutionWhenStaticEqualsKinetic) {
  constexpr double kSmoothTol = 1e-9, kPolynomialTol = 1e-12;
  const oracle::SingleHarmonicCase cases[] = {{(2 * std::numbers::pi), 1.5, 0.1, 1.0, 1.0},
                                              {(2 * std::numbers::pi), 1.5, 0.3, 1.0, 1.0},
                                              {2.5, 0.3, -0.02, 1.6, 1.6}};
  for (const auto& c : cases) {
    const oracle::SingleHarmonicResult expected = oracle::single_harmonic_vbar(c);
    ASSERT_TRUE(expected.valid());
    const FourierProfile profile(c.period, {c.A1, c.A2}, {0.0, 0.0});
    const SteadyState r = steady_state(profile, coulomb_through_integrator(c.k));
    ASSERT_EQ(r.method, Method::integrator);
    ASSERT_TRUE(r.converged);
    EXPECT_GT(r.integrator.steps, 0);
    EXPECT_NEAR(r.v_bar, expected.vbar, kSmoothTol) << c.A1 << " " << c.A2;
  }
  const SteadyState exact = steady_state(three_phase(), FrictionLaw(1.0, 1.0));
  const SteadyState integrated = steady_state(three_phase(), coulomb_through_integrator(1.0));
  ASSERT_EQ(exact.method, Method::exact);
  ASSERT_EQ(integrated.method, Method::integrator);
  EXPECT_NEAR(integrated.v_bar, exact.v_bar, kPolynomialTol);
}

// Global error against the exact smooth solver over five periods from rest, at rtol 1e-6,
// 1e-8, 1e-10 (atol = rtol / 100). Dormand-Prince with the standard controller: the error is
// about proportional to the tolerance (docs/slip-integrator.md); measured 4e-8, 1e-8, 7e-11 in
// x. Each error within 100 rtol, and four decades of tolerance buy at least two of error.
TEST(SlipIntegrator, GlobalErrorScalesWithTheTolerance) {
  constexpr double kErrorPerTolerance = 100;
  const FourierProfile profile((2 * std::numbers::pi), {1.5, 0.1}, {0.0, 0.2});
  const UniformFriction uniform;
  ObjectState exact{0, 0, 0};
  advance_smooth({profile, *uniform.piecewise_affine(), FrictionLaw(1.0, 1.0)}, exact,
                 5 * profile.period());
  std::vector<double> errors;
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    ObjectState s{0, 0, 0};
    IntegratorStatistics stats;
    advance_integrated({profile, *uniform.piecewise_affine(), coulomb_through_integrator(1.0),
                        {tol, tol / 100}},
                       s, 5 * profile.period(), nullptr, &stats);
    const double error = std::max(std::abs(s.x - exact.x), std::abs(s.xd - exact.xd));
    EXPECT_LE(error, kErrorPerTolerance * tol) << tol;
    EXPECT_GT(stats.events, 0);
    errors.push_back(error);
  }
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  EXPECT_GE(errors[0] / errors[2], 1e2);
}

// x'' = -k - c x' - A on a forward slip under constant A: with b = k + A,
//   x'(t) = (v0 + b/c) e^{-ct} - b/c,  x(t) = (v0 + b/c)(1 - e^{-ct})/c - b t / c,
// and x' = 0 at t* = ln(1 + c v0 / b) / c (docs/slip-integrator.md, eq. V1-V3). Then |A| <= s:
// a stick to the end of the run, x held exactly.
TEST(SlipIntegrator, ViscousSlipMatchesItsClosedForm) {
  constexpr double kTol = 1e-10;  // rtol 1e-12 on an O(1) solution: 100 x
  const double A = 0.5, k = 1.0, c = 0.7, v0 = 2.0, b = k + A;
  const std::vector<double> durations{1.0, 1.0}, accels{A, -A};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(durations, accels);
  const UniformFriction uniform;
  const FrictionLaw law = FrictionLaw(1.0, k).with_viscous(c);
  auto x_of = [&](double t) { return (v0 + b / c) * (1 - std::exp(-c * t)) / c - b * t / c; };
  const double t_star = std::log(1 + c * v0 / b) / c;
  ASSERT_LT(t_star, 1.0);
  ObjectState s{0, 0, v0};
  advance_integrated({profile, *uniform.piecewise_affine(), law, {1e-12, 1e-14}}, s, 0.5);
  EXPECT_NEAR(s.x, x_of(0.5), kTol);
  EXPECT_NEAR(s.xd, (v0 + b / c) * std::exp(-c * 0.5) - b / c, kTol);
  IntervalList list;
  ObjectState r{0, 0, v0};
  advance_integrated({profile, *uniform.piecewise_affine(), law, {1e-12, 1e-14}}, r, 1.8, &list);
  ASSERT_EQ(list.intervals.size(), 2u);  // the slip, then one stick across the switch at t = 1
  EXPECT_EQ(list.intervals[0].end, ArcEnd::velocity_zero);
  EXPECT_EQ(list.intervals[1].direction, 0);
  EXPECT_EQ(list.intervals[1].end, ArcEnd::horizon);
  EXPECT_NEAR(list.intervals[0].t1, t_star, kTol);
  EXPECT_NEAR(list.intervals[0].x1, x_of(t_star), kTol);
  EXPECT_EQ(r.xd, 0.0);
  EXPECT_EQ(r.x, list.intervals[0].x1);
}

// Stribeck mu(v) = k + (s - k) exp(-(v/v_s)^2) over three decades of v_s: v̄ tends to the
// exact solver's static != kinetic steady state (s = 1.3, k = 1), the gap shrinking about
// tenfold per decade (measured 1.08e-3, 1.09e-4, 1.09e-5: first order in v_s).
TEST(SlipIntegrator, StribeckTendsToTheStaticKineticCoulombLawAsTheStribeckVelocityVanishes) {
  const FrictionLaw coulomb(1.3, 1.0);
  const SteadyState limit = steady_state(three_phase(), coulomb);
  ASSERT_EQ(limit.method, Method::exact);
  std::vector<double> gaps;
  for (double vs : {1e-2, 1e-3, 1e-4}) {
    const SteadyState r = steady_state(three_phase(), coulomb.with_stribeck(vs, 2.0));
    ASSERT_EQ(r.method, Method::integrator);
    ASSERT_TRUE(r.converged);
    gaps.push_back(std::abs(r.v_bar - limit.v_bar));
  }
  for (std::size_t i = 1; i < gaps.size(); ++i) {
    EXPECT_LT(gaps[i], gaps[i - 1] / 5) << i;  // about tenfold; 5 leaves room
    EXPECT_GT(gaps[i], gaps[i - 1] / 20) << i; // and first order, not faster
  }
  EXPECT_LT(gaps.back(), 2e-5);
}

// Moreau (speed-dependent part explicit, stick set-valued) against the integrator's steady
// state under Stribeck and viscous friction: errors shrink about tenfold per tenfold h.
TEST(SlipIntegrator, MoreauConvergesToTheIntegratorWithOrderOne) {
  const FrictionLaw law = FrictionLaw(1.3, 1.0).with_stribeck(0.05, 2.0).with_viscous(0.2);
  const SteadyState reference = steady_state(three_phase(), law);
  ASSERT_EQ(reference.method, Method::integrator);
  const UniformFriction uniform;
  std::vector<double> errors;
  const double P = three_phase().period(), T = 4 * P;
  for (int n : {1000, 10000, 100000}) {
    // RMS over 8 start phases of x after four periods from rest (tests/moreau_order.hpp: it
    // removes the lottery of where each event falls inside its step)
    const double h = P / n;
    double sum_sq = 0;
    for (int j = 0; j < 8; ++j) {
      const double t0 = h * (j + 0.5) / 8;
      ObjectState exact{t0, 0, 0};
      advance_integrated({three_phase(), *uniform.piecewise_affine(), law}, exact, t0 + T);
      TimeSteppingState ts = make_time_stepping_state(three_phase(), {t0, 0, 0});
      advance_time_stepping(three_phase(), uniform, law, {h, 0.5}, ts, 4LL * n);
      sum_sq += std::pow(ts.object.x - exact.x, 2);
    }
    errors.push_back(std::sqrt(sum_sq / 8));
  }
  const double order = std::log10(errors[0] / errors[2]) / 2;
  RecordProperty("moreau_errors", std::to_string(errors[0]) + " " + std::to_string(errors[1]) +
                                      " " + std::to_string(errors[2]));
  EXPECT_GT(order, 0.7);
  EXPECT_LT(order, 1.5);
}

// During every stick interval of a Stribeck run x' is exactly 0 and x does not move; the
// trajectory's stick samples likewise.
TEST(SlipIntegrator, NoCreepDuringSticks) {
  const FrictionLaw law = FrictionLaw(1.3, 1.0).with_stribeck(0.01, 1.0).with_viscous(0.1);
  const UniformFriction uniform;
  IntervalList list;
  ObjectState s{0, 0, 0};
  advance_integrated({three_phase(), *uniform.piecewise_affine(), law}, s,
                     20 * three_phase().period(), &list);
  int sticks = 0;
  for (const MotionInterval& i : list.intervals) {
    if (i.direction != 0) continue;
    ++sticks;
    EXPECT_EQ(i.xd0, 0.0);
    EXPECT_EQ(i.xd1, 0.0);
    EXPECT_EQ(i.x0, i.x1);
  }
  EXPECT_GE(sticks, 20);
  SimulationOptions o;
  o.duration = 10 * three_phase().period();
  const SimulationResult r = simulate(three_phase(), uniform, law, {0, 0, 0}, o);
  EXPECT_EQ(r.method, Method::integrator);
  EXPECT_GT(r.integrator.steps, 0);
  int stuck = 0;
  for (std::size_t i = 0; i < r.trajectory.size(); ++i)
    if (r.trajectory.stick[i]) {
      ++stuck;
      EXPECT_EQ(r.trajectory.xd[i], 0.0);
      if (i > 0 && r.trajectory.stick[i - 1]) EXPECT_EQ(r.trajectory.x[i], r.trajectory.x[i - 1]);
    }
  EXPECT_GT(stuck, 100);
}

// On the uniform table a shift of x maps to the same shift (multiplier 1), and a stick in the
// steady period forgets the velocity (multiplier 0): finite differences of the integrated map
// find {1, 0} to the FD error (h 1e-5: truncation 0, integrator noise 1e-10 / 1e-5 = 1e-5).
TEST(SlipIntegrator, FloquetByFiniteDifferencesFindsTheStickMultipliers) {
  const FrictionLaw law = FrictionLaw(1.3, 1.0).with_stribeck(0.01, 2.0);
  FloquetOptions o;
  o.fd_step = 1e-5;
  const FloquetAnalysis a = floquet_multipliers(three_phase(), law, o);
  ASSERT_EQ(a.steady.method, Method::integrator);
  EXPECT_FALSE(a.saltation.available);
  EXPECT_TRUE(std::isnan(a.spread));
  EXPECT_NEAR(std::abs(a.finite_difference.multipliers[0]), 1.0, 1e-4);
  EXPECT_NEAR(std::abs(a.finite_difference.multipliers[1]), 0.0, 1e-4);
}

TEST(SlipIntegrator, RefusesBadInputNamingTheParameter) {
  auto message = [](auto f) {
    try {
      f();
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const FrictionLaw law(1.2, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double vs : {0.0, -1.0, nan, std::numeric_limits<double>::infinity()})
    EXPECT_NE(message([&] { (void)law.with_stribeck(vs, 1.0); }).find("stribeck_velocity"),
              std::string::npos);
  for (double d : {0.0, -1.0, nan, 101.0})
    EXPECT_NE(message([&] { (void)law.with_stribeck(0.1, d); }).find("stribeck_exponent"),
              std::string::npos);
  for (double c : {-1e-9, nan})
    EXPECT_NE(message([&] { (void)law.with_viscous(c); }).find("viscous"), std::string::npos);
  for (double tol : {0.0, -1e-3, 1.0, nan}) {
    EXPECT_NE(message([&] { validate(IntegratorOptions{tol, 1e-12}); }).find("relative_tolerance"),
              std::string::npos);
    EXPECT_NE(message([&] { validate(IntegratorOptions{1e-10, tol}); }).find("absolute_tolerance"),
              std::string::npos);
  }
}

// A stopping run through the integrator (static = kinetic: the Coulomb motion) against the
// exact solver's: the same stop, rest position, process time, entry time and target times.
// The integrator locates the entry into x >= x_mu and the targets as events on its dense
// output; rtol 1e-12 leaves errors of order 1e-11 in times and positions: 1e-9.
TEST(SlipIntegrator, StoppingRunMatchesTheExactSolversWhenStaticEqualsKinetic) {
  constexpr double kTol = 1e-9;
  const ThreePhaseProfile profile({1.0, 0.084, 1.8, 1.1});
  const FieldFriction friction = two_region_friction(0.1, 0.05, 2.5);
  StoppingOptions o;
  o.fractions = {0.5, 0.9};
  o.integrator = {1e-12, 1e-14};
  const StoppingRun exact = stopping_run(profile, friction, FrictionLaw(1.0, 1.0), {0, 0, 0}, o);
  const StoppingRun integrated =
      stopping_run(profile, friction, coulomb_through_integrator(1.0), {0, 0, 0}, o);
  ASSERT_EQ(exact.kind, StopKind::permanent_stick);
  ASSERT_EQ(integrated.kind, exact.kind);
  EXPECT_NEAR(integrated.end_position, exact.end_position, kTol);
  EXPECT_NEAR(integrated.process_time, exact.process_time, kTol);
  EXPECT_NEAR(integrated.entry_time, exact.entry_time, kTol);
  ASSERT_EQ(integrated.time_to_fraction.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_FALSE(std::isnan(exact.time_to_fraction[k]));
    EXPECT_NEAR(integrated.time_to_fraction[k], exact.time_to_fraction[k], kTol) << k;
    EXPECT_EQ(integrated.periods_to_fraction[k], exact.periods_to_fraction[k]) << k;
  }
  EXPECT_EQ(integrated.stick_positions.size(), exact.stick_positions.size());
}

// F06 (issue 20): under a Stribeck law the result depended on whether a trajectory was
// sampled: a step that holds a velocity zero has stages past it, where the slip equation meets
// the kink of mu(|x'|), and the zero located on its interpolant was off (2.4e-5 in x over four
// periods at rtol 1e-12; samples shortened the steps and hid it). The zero is now placed by
// re-integrating up to it. The reproducer's profile: the final state and v̄ must not depend on
// the output step (acceptance: 1e-10), and the unsampled steady v̄ must agree with a long
// sampled run's last period.
TEST(SlipIntegrator, StribeckResultDoesNotDependOnTheOutputStep) {
  constexpr double kOutputIndependence = 1e-10;
  const std::vector<double> durations{0.31100212033695435, 0.1748469823236071,
                                      0.6437444216838664, 0.4421409393466044,
                                      0.39938983265336453};
  const std::vector<double> accels{1.0201094476681831, 1.7555842155060244, 2.853597451621262,
                                   -2.7353480504136716, -3.1342632834268382};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(durations, accels);
  const FrictionLaw law = FrictionLaw(1.3764545731279676, 1.0).with_stribeck(1e-3, 1.0);
  const UniformFriction uniform;
  const double P = profile.period();
  SimulationOptions o;
  o.method = Method::integrator;
  o.integrator = {1e-12, 1e-14};
  o.duration = 4 * P;
  o.record = false;
  const SimulationResult unsampled = simulate(profile, uniform, law, {0, 0, 0}, o);
  o.record = true;
  for (double output_step : {P / 3, P / 37, P / 4000}) {
    o.output_step = output_step;
    const SimulationResult sampled = simulate(profile, uniform, law, {0, 0, 0}, o);
    EXPECT_NEAR(sampled.final_state.x, unsampled.final_state.x, kOutputIndependence)
        << "output step " << output_step;
  }
  SteadyStateOptions so;
  so.integrator = o.integrator;
  const SteadyState steady = steady_state(profile, law, so);
  ASSERT_TRUE(steady.converged);
  o.duration = 30 * P;  // the transient has decayed below 1e-13 by then
  o.output_step = P / 500;
  const SimulationResult settled = simulate(profile, uniform, law, {0, 0, 0}, o);
  EXPECT_NEAR(steady.v_bar, settled.mean_velocity_last_period, kOutputIndependence);

  // Second method: fixed-step RK4, event by event (tests/oracles/stribeck_rk4.hpp), at
  // h = 3e-5: its v̄ moved by 1.4e-11 and x(4 Δt) by 5e-11 to h = 1e-5; 1e-9 covers both.
  // (The old unsampled path was 2.2e-5 off in v̄ and 3.7e-5 in x.)
  constexpr double kRk4Agreement = 1e-9;
  const std::vector<double> x = oracle::stribeck_rk4_positions(
      {durations, accels, law.static_coefficient(), 1.0, 1e-3, 1.0}, 30, 3e-5);
  EXPECT_NEAR(unsampled.final_state.x, x[3], kRk4Agreement);
  EXPECT_NEAR(steady.v_bar, (x[29] - x[28]) / P, kRk4Agreement);
}

// D26 (issue 20): the integrator had no work limit: a stiff slip (a viscous rate far above the
// table's, a steep Stribeck curve) or tolerances below double precision ran for hours. A
// budget of step attempts per table period now ends such runs with an error naming the likely
// cause; a non-finite state (a stiff slip at a loose tolerance) likewise. A small budget keeps
// the test fast; the default (1e6) is the same code path.
TEST(SlipIntegrator, WorkBudgetEndsStiffOrHopelessRunsNamingTheCause) {
  auto cause = [](const FrictionLaw& law, IntegratorOptions o, double budget = 1e3) {
    o.max_steps_per_period = budget;
    SteadyStateOptions so;
    so.integrator = o;
    try {
      steady_state(three_phase(), law, so);
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("no error");
  };
  const IntegratorOptions normal{1e-10, 1e-12};
  EXPECT_EQ(cause(FrictionLaw(1.0, 1.0).with_viscous(1e9), normal), "viscous");
  // A Stribeck slope (s - k) / v_s of 3e11 per unit time: named when the budget runs out (a
  // budget of 5 steps per period makes it run out here).
  EXPECT_EQ(cause(FrictionLaw(1.3, 1.0).with_stribeck(1e-12, 1.0), normal, 5),
            "stribeck_velocity");
  EXPECT_EQ(cause(FrictionLaw(1.0, 1.0).with_viscous(0.1), {1e-300, 1e-300}),
            "relative_tolerance");
  EXPECT_EQ(cause(FrictionLaw(1.0, 1.0).with_viscous(1e50), {0.5, 1e-12}), "viscous");
  // Within the budget, nothing changes: a moderate law converges as before.
  EXPECT_EQ(cause(FrictionLaw(1.3, 1.0).with_stribeck(0.01, 1.0), normal), "no error");
  EXPECT_THROW(validate(IntegratorOptions{1e-10, 1e-12, 0.5}), InvalidParameter);
}
