// Tests for simulate/smooth_exact.hpp: the exact solver for smooth table motions (Fourier
// series) on piecewise-constant friction levels, against independent numbers:
//  - the steady state of a two-harmonic profile derived by hand (docs/single-harmonic-steady-
//    state.md; tests/oracles/single_harmonic.hpp, itself checked against a 32-digit brute-force
//    simulation by its .py companion), to 1e-12, for static = kinetic and static > kinetic;
//  - Moreau time-stepping converges to it with observed order about 1;
//  - stick breaking and slip reversals never step over a zero: a period's arcs alternate as the
//    law says (no zero-length slips), and during every stick x' is exactly 0.
#include <gtest/gtest.h>

#include "arc_list.hpp"

#include <cmath>
#include <numbers>
#include <cstdio>
#include <vector>

#include "moreau_order.hpp"
#include "opaque_profile.hpp"
#include "oracles/single_harmonic.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/time_stepping.hpp"

using namespace selfalign;

namespace {

FourierProfile profile_of(const oracle::SingleHarmonicCase& c) {
  return FourierProfile(c.period, {c.A1, c.A2}, {0.0, 0.0});
}

using selfalign::testing_support::ArcList;
}  // namespace

// v̄ of the exact steady state equals the hand derivation (cases E1-E8 of the doc) to 1e-12:
// both sides are closed forms evaluated to rounding; the oracle's own agreement with the
// brute-force simulation is 1e-16 V.
TEST(SmoothExact, TwoHarmonicSteadyVelocityMatchesTheHandDerivation) {
  constexpr double kVbarTol = 1e-12;
  const oracle::SingleHarmonicCase cases[] = {
      {(2 * std::numbers::pi), 1.1, 0.1, 1.0, 1.0},     {(2 * std::numbers::pi), 1.5, 0.1, 1.0, 1.0},
      {(2 * std::numbers::pi), 1.5, 0.3, 1.0, 1.0},     {1.0, 0.04, 0.004, 1.2, 1.0},
      {1.0, 0.04, 0.002, 1.2, 1.0},     {1.0, 0.045, 0.008, 1.5, 1.0},
      {2.5, 0.3, -0.02, 1.6, 1.0},      {0.5, 0.005, 0.0008, 0.8, 0.5},
      {(2 * std::numbers::pi), 1.3, 0.0, 1.0, 1.0},     {1.0, 0.035, 0.0, 1.2, 1.0},  // pure harmonics: 0
  };
  for (const auto& c : cases) {
    const oracle::SingleHarmonicResult expected = oracle::single_harmonic_vbar(c);
    ASSERT_TRUE(expected.valid()) << c.A1 << " " << c.A2;
    const FourierProfile profile = profile_of(c);
    const SteadyState r = steady_state(profile, FrictionLaw(c.s, c.k));
    ASSERT_EQ(r.method, Method::exact);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.v_bar, expected.vbar, kVbarTol) << "A1 " << c.A1 << " A2 " << c.A2 << " s "
                                                  << c.s << " k " << c.k;
  }
}

// Moreau time-stepping converges to the exact solution: RMS over 4 grid phases of x after 5
// periods, h = 1e-3 .. 1e-6; from h = 1e-4 on each decade gains >= 0.8 orders (the coarsest
// grid is still in the event lottery).
TEST(SmoothExact, MoreauConvergesToItWithOrderOne) {
  const FourierProfile profile(1.0, {0.02, 0.0}, {0.0, 0.008});
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.3, 1.0)}) {
    std::vector<double> err;
    for (double h : {1e-4, 1e-5, 1e-6})
      err.push_back(testing_support::moreau_rms_error(profile, law, 5.0, h, 4));
    RecordProperty("errors", ::testing::PrintToString(err));
    EXPECT_GE(std::log10(err[0] / err[1]), 0.8) << law.describe();
    EXPECT_GE(std::log10(err[1] / err[2]), 0.8) << law.describe();
  }
}

// The arcs of a run obey the law: every stick has x' = 0 throughout (it is a StickArc: exact
// zero, no creep), slips have positive length, and a slip ends at x' = 0 only where the slip
// velocity's closed form vanishes (checked at the event to 1e-12 of the velocity scale).
TEST(SmoothExact, ArcsAreStickOrSlipWithNoZeroLengthSlips) {
  const FourierProfile profile(1.0, {0.02, 0.0}, {0.0, 0.008});
  const UniformFriction uniform;
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.3, 1.0)}) {
    const SmoothSetup setup{profile, *uniform.piecewise_affine(), law};
    ArcList list;
    ObjectState s{0, 0, 0};
    advance_smooth(setup, s, 20.0, &list);
    int sticks = 0, slips = 0;
    for (const Arc& a : list.arcs) {
      if (a.kind() == ArcKind::stick) {
        ++sticks;
        EXPECT_EQ(a.xd0, 0.0);
        EXPECT_EQ(a.xd1, 0.0);
        continue;
      }
      ++slips;
      ASSERT_EQ(a.kind(), ArcKind::driven);
      EXPECT_GT(a.t1, a.t0) << law.describe();
      if (a.end == ArcEnd::velocity_zero)
        EXPECT_NEAR(std::get<DrivenArc>(a.shape).state(a.x0, a.xd0, a.t1 - a.t0).xd, 0.0, 1e-12);
    }
    EXPECT_GE(sticks, 19) << law.describe();  // one rest a period at least
    EXPECT_GE(slips, 19) << law.describe();
  }
}

// The Fig. 6 setting: an order-12 Fourier profile's exact steady state converges, and agrees
// with time-stepping of the same motion at h = Δt/20000 to O(h).
TEST(SmoothExact, OrderTwelveSteadyStateConvergesAndAgreesWithTimeStepping) {
  std::vector<double> a(12), b(12);
  for (int k = 0; k < 12; ++k) {  // a smooth, asymmetric spectrum
    a[static_cast<std::size_t>(k)] = 0.004 / ((k + 1) * (k + 1));
    b[static_cast<std::size_t>(k)] = (k % 2 ? 0.002 : -0.003) / ((k + 1) * (k + 1) * (k + 1));
  }
  const FourierProfile profile(0.072, a, b);
  const SteadyState exact = steady_state(profile);
  ASSERT_EQ(exact.method, Method::exact);
  ASSERT_TRUE(exact.converged);
  EXPECT_LE(exact.x_dot_0s_error, 1e-12 * (1 + std::abs(exact.x_dot_0s)));
  SteadyStateOptions o;
#ifdef SELFALIGN_SANITIZED_TESTS
  o.steps_per_period = 4000;  // the bound below scales with the step; a Debug+ASan build is ~20x slower
#else
  o.steps_per_period = 20000;
#endif
  const testing_support::Opaque hidden(profile);  // only time-stepping can take it
  const SteadyState ts = steady_state(hidden, o);
  ASSERT_EQ(ts.method, Method::time_stepping);
  EXPECT_NEAR(exact.v_bar, ts.v_bar, 20 * 0.072 / o.steps_per_period * std::max(1.0, std::abs(exact.v_bar)));
}

namespace {
struct AffineCount final : MotionObserver {
  int harmonic = 0, hyperbolic = 0;
  void on_motion(const MotionInterval&, const Arc* arc) override {
    const Arc& a = *arc;
    if (const auto* s = std::get_if<DrivenAffineArc>(&a.shape)) ++(s->kappa > 0 ? harmonic : hyperbolic);
  }
};

// |x, x' exact - integrated| after `duration` from `start`: the closed form against the slip
// integrator at rtol 1e-13 (a second method: Dormand-Prince on the same ODE).
double gap_to_integrator(const FourierProfile& profile, const FieldFriction& friction,
                         const FrictionLaw& law, const ObjectState& start, double duration,
                         AffineCount& count) {
  ObjectState exact = start, integrated = start;
  advance_smooth({profile, *friction.piecewise_affine(), law}, exact, start.t + duration, &count);
  advance_integrated({profile, *friction.piecewise_affine(), law, {1e-13, 1e-15}}, integrated,
                     start.t + duration);
  return std::max(std::abs(exact.x - integrated.x), std::abs(exact.xd - integrated.xd));
}
}  // namespace

// Fourier motions across the paper's transition region (sloped level) are exact too: the
// harmonic-by-harmonic closed form of DrivenAffineArc (docs/fourier-transition-region.md)
// against the slip integrator, forward slips up the slope (harmonic, kappa > 0) and backward
// ones (hyperbolic), static = kinetic and static > kinetic. Measured gaps 1e-16..4e-15; 1e-12
// leaves the integrator's own error (rtol 1e-13 over 6 periods) room.
TEST(SmoothExact, TransitionRegionIsClosedFormForFourierProfiles) {
  constexpr double kGap = 1e-12;
  const FourierProfile profile(1.0, {0.035, 0.004}, {0.0, 0.0});
  const FieldFriction friction = two_region_friction(0.5, 0.05, 2.5);
  AffineCount count;
  for (const FrictionLaw& law : {FrictionLaw(1.0, 1.0), FrictionLaw(1.2, 1.0)}) {
    ASSERT_EQ(PeriodMap(profile, friction, law).method(), Method::exact);
    for (const ObjectState start : {ObjectState{0, 0.45, 0}, ObjectState{0.3, 0.53, -0.2}})
      EXPECT_LT(gap_to_integrator(profile, friction, law, start, 6.0, count), kGap)
          << law.describe() << " from x " << start.x;
  }
  EXPECT_GT(count.harmonic, 0);
  EXPECT_GT(count.hyperbolic, 0);
}

// At resonance: kappa = k dm/dx = (2 pi / Δt)^2 makes the first harmonic resonant with the
// slip's own frequency; the sinc form of the zero-state response (eqs. F4, F5) stays exact.
TEST(SmoothExact, TransitionRegionAtResonanceIsClosedForm) {
  constexpr double kGap = 1e-12;
  const double two_pi = 6.283185307179586;
  const FourierProfile profile(1.0, {0.035, 0.004}, {0.0, 0.0});
  const FieldFriction friction = two_region_friction(0.5, 0.05, 1 + two_pi * two_pi * 0.05);  // b = (2 pi)^2
  AffineCount count;
  EXPECT_LT(gap_to_integrator(profile, friction, FrictionLaw(1.0, 1.0), {0, 0.45, 0}, 10.0,
                              count),
            kGap);
  EXPECT_GT(count.harmonic, 0);
}

// Moreau converges to the closed form across the transition region with order about 1 (RMS
// over 8 grid phases of x after 6 periods from rest at x = 0.45, which walks the object into
// the ramp at x_mu = 0.5); the saltation monodromy of a period through the region equals
// central finite differences (h = 1e-7: truncation O(h^2), rounding 1e-16 / 1e-7): 1e-6.
TEST(SmoothExact, TransitionRegionMoreauOrderAndSaltation) {
  const FourierProfile profile(1.0, {0.035, 0.004}, {0.0, 0.0});
  const FieldFriction friction = two_region_friction(0.5, 0.05, 2.5);
  const FrictionLaw law(1.2, 1.0);
  const PeriodMap map(profile, friction, law);
  ASSERT_EQ(map.method(), Method::exact);
  const double T = 6 * profile.period();
  std::vector<double> errors;
  for (int n : {1000, 10000, 100000}) {
    const double h = profile.period() / n;
    double sum_sq = 0;
    for (int j = 0; j < 8; ++j) {
      const double t0 = h * (j + 0.5) / 8;
      const double x_ref = map.start({t0, 0.45, 0}).advance_to(t0 + T).x;
      TimeSteppingState ts = make_time_stepping_state(profile, {t0, 0.45, 0});
      advance_time_stepping(profile, friction, law, {h, 0.5}, ts, 6LL * n);
      sum_sq += std::pow(ts.object.x - x_ref, 2);
    }
    errors.push_back(std::sqrt(sum_sq / 8));
  }
  const double order = std::log10(errors[0] / errors[2]) / 2;
  char text[96];
  std::snprintf(text, sizeof text, "%.3g %.3g %.3g", errors[0], errors[1], errors[2]);
  RecordProperty("moreau_errors", text);
  EXPECT_GT(order, 0.7);
  EXPECT_LT(order, 1.5);
  const PeriodMap uniform_law(profile, friction, FrictionLaw(1.0, 1.0));
  for (double x0 : {0.49, 0.505, 0.52}) {
    const Eigen::Matrix2d s = uniform_law.saltation_monodromy(x0, 0.05);
    const Eigen::Matrix2d f = uniform_law.finite_difference_monodromy(x0, 0.05, 1e-7);
    EXPECT_LT((s - f).cwiseAbs().maxCoeff(), 1e-6) << x0;
  }
}

// The a posteriori longer steps (Hermite check against the fifth-derivative bound) change how
// far the solver steps, not what it finds: the same motion with that bound hidden (every step
// a safe step) gives the same arcs, events and state, over 20 periods of the order-12
// Fig. 6-like series and the two-harmonic motion (rounding: 1e-12).
TEST(SmoothExact, LongerStepsFindTheSameEventsAsSafeStepsAlone) {
  struct WithoutFifthBound final : SmoothMotion {
    const FourierProfile& p;
    explicit WithoutFifthBound(const FourierProfile& q) : p(q) {}
    std::array<double, 4> derivatives(double t) const override { return p.derivatives(t); }
    double jerk_bound() const override { return p.jerk_bound(); }
    double snap_bound() const override { return p.snap_bound(); }
  };
  struct Count final : MotionObserver {
    std::vector<Arc> arcs;
    void on_motion(const MotionInterval&, const Arc* arc) override {
    const Arc& a = *arc;
    arcs.push_back(a);
  }
  };
  std::vector<double> a, b;
  const ThreePhaseProfile three({0.072, 0.021, 1000, 80});
  fourier_series_of(*three.piecewise_polynomial(), 12, a, b);
  const FourierProfile fig6(0.072, a, b);
  const FourierProfile two((2 * std::numbers::pi), {1.5, 0.1}, {0.0, 0.2});
  const UniformFriction uniform;
  for (const FourierProfile* profile : {&fig6, &two}) {
    ASSERT_TRUE(std::isfinite(profile->fifth_derivative_bound()));
    const WithoutFifthBound hidden(*profile);
    Count fast, safe;
    ObjectState s1{0, 0, 0}, s2{0, 0, 0};
    const FrictionLaw law(1.2, 1.0);
    advance_smooth({*profile, *uniform.piecewise_affine(), law}, s1, 20 * profile->period(), &fast);
    advance_smooth({hidden, *uniform.piecewise_affine(), law}, s2, 20 * profile->period(), &safe);
    ASSERT_EQ(fast.arcs.size(), safe.arcs.size());
    for (std::size_t i = 0; i < fast.arcs.size(); ++i) {
      EXPECT_EQ(fast.arcs[i].end, safe.arcs[i].end) << i;
      EXPECT_NEAR(fast.arcs[i].t1, safe.arcs[i].t1, 1e-12) << i;
    }
    EXPECT_NEAR(s1.x, s2.x, 1e-12);
    EXPECT_NEAR(s1.xd, s2.xd, 1e-12);
  }
}
