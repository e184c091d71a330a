// Tests for analysis/steady_state.hpp: v̄ against the closed form of eqs. (15)-(24), pure
// stick, slip-slip convergence, and exact vs time-stepping steady states (a second method).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/profiles/piecewise_constant.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"

using namespace selfalign;

namespace {
// Hides the piecewise-constant form of a profile, forcing the time-stepping path.
class Opaque final : public TableProfile {
 public:
  explicit Opaque(const TableProfile& p) : p_(p) {}
  double period() const override { return p_.period(); }
  TableState state(double t) const override { return p_.state(t); }
  double peak_acceleration() const override { return p_.peak_acceleration(); }
  double stroke() const override { return p_.stroke(); }
  std::string kind() const override { return "opaque"; }

 private:
  const TableProfile& p_;
};
}  // namespace

TEST(SteadyState, CaseOneAverageVelocityEqualsClosedForm) {
  const ThreePhaseParameters p{1.0, 0.084, 3.0, 0.9};
  const ThreePhaseProfile profile(p);
  const ThreePhaseSolution& r = profile.solution();
  // eqs. (15)-(24) with x'_0s = 0: slip on [t1, t2] at y2'' - 1, then decelerate at 1 + y3''.
  const double T2 = r.t2 - r.t1, v2 = (p.a2 - 1) * T2, x2 = 0.5 * (p.a2 - 1) * T2 * T2;
  const double x3 = x2 + v2 * v2 / (2 * (1 + p.a3));  // x(t_{x'=0}) = x(t3), eqs. (20), (21), (24)
  const SteadyState s = steady_state(profile);
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(s.method, Method::exact);
  EXPECT_EQ(s.motion_case, StickSlipCase::stick_slip_forward);
  EXPECT_EQ(s.x_dot_0s, 0.0);  // the mass is stuck at t0 (Sect. 5.1)
  // One period of O(1) closed-form arithmetic: rounding ~1e-16; 1e-14 leaves headroom.
  EXPECT_NEAR(s.v_bar, x3 / p.period, 1e-14);  // eq. (10)
  EXPECT_NEAR(s.f, 1.0 / (1e4 * s.v_bar * s.v_bar), 1e-12 * s.f);  // eq. (11)
}

TEST(SteadyState, PureStickHasZeroVelocityAndInfiniteObjective) {
  const SteadyState s = steady_state(ThreePhaseProfile({2.0, 0.084, 0.9, 0.9}));
  EXPECT_EQ(s.motion_case, StickSlipCase::pure_stick);
  EXPECT_EQ(s.v_bar, 0.0);
  EXPECT_TRUE(std::isinf(s.f));
  EXPECT_GT(s.f, 0);
  EXPECT_TRUE(std::isinf(objective_f(0.0)));
}

TEST(SteadyState, SlowlyContractingSlipSlipIsAFixedPointOfThePeriodMap) {
  // High accelerations: lambda2 = c4 close to 1, so plain iteration would take thousands of
  // periods. The returned x'_0s must reproduce itself over 50 further periods.
  const ThreePhaseParameters p{0.072, 0.021, 37.9379, 233.673};
  const ThreePhaseProfile profile(p);
  const SteadyState s = steady_state(profile);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.motion_case, StickSlipCase::slip_slip);
  EXPECT_LT(s.periods, 40);
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_constant(), *friction.piecewise_affine()};
  ExactState st = make_exact_state(setup, {0, 0, s.x_dot_0s});
  advance_exact(setup, st, 50 * p.period);
  EXPECT_NEAR(st.object.xd, s.x_dot_0s, 1e-10);
  EXPECT_NEAR(st.object.x / (50 * p.period), s.v_bar, 1e-10);
}

TEST(SteadyState, TimeSteppingPathAgreesWithExactToOrderH) {
  // The same profile through the time-stepping path (piecewise form hidden): Moreau's error in
  // v̄ is O(h) with h = Δt/4000 = 2.5e-4; a 2e-3 band is 8 h.
  for (auto [a2, a3] : {std::pair{3.0, 0.9}, std::pair{2.3, 1.3}, std::pair{1.05, 2.0}}) {
    const ThreePhaseProfile profile({1.0, 0.084, a2, a3});
    const SteadyState exact = steady_state(profile);
    const SteadyState stepped = steady_state(Opaque(profile));
    EXPECT_EQ(stepped.method, Method::time_stepping);
    EXPECT_TRUE(stepped.converged);
    EXPECT_NEAR(stepped.v_bar, exact.v_bar, 2e-3) << a2 << ", " << a3;
    EXPECT_EQ(stepped.motion_case, exact.motion_case) << a2 << ", " << a3;
  }
}

TEST(SteadyState, ManySegmentProfilesGiveAPhysicalFixedPoint) {
  // Regression: smooth many-segment profiles (as the Fourier optimiser builds) once sent the
  // secant iteration to v̄ ~ 1e15 while reporting convergence (a tolerance relative to the
  // runaway |v|). Check: the result is physical (|x'_0s| within the velocity the table can
  // impart in a period, (max|y''| + 1) Δt) and it is the fixed point of the period map over 20
  // periods (by Sect. 6.2 the only one). These slip-slip responses contract slowly (λ2 near 1),
  // so plain simulation from rest is no second method here.
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const int m = 256;
    std::vector<double> d(m, 0.072 / m), a(m);
    for (int i = 0; i < m; ++i) {
      const double t = (i + 0.5) / m;
      a[i] = 800 * std::sin(2 * M_PI * t + 0.37 * seed) + 300.0 * seed * std::sin(4 * M_PI * t) +
             150 * std::cos(6 * M_PI * t + seed);
    }
    double mean = 0;
    for (double v : a) mean += v / m;
    for (double& v : a) v -= mean;  // the velocity returns (to rounding)
    const auto profile = PiecewiseConstantProfile::from_accelerations(d, a);
    const SteadyState s = steady_state(profile);
    ASSERT_TRUE(s.converged) << "seed " << seed;
    EXPECT_LE(std::abs(s.x_dot_0s), (profile.peak_acceleration() + 1) * 0.072) << "seed " << seed;
    const UniformFriction friction;
    const ExactSetup setup{profile, *friction.piecewise_affine()};
    ExactState st = make_exact_state(setup, {0, 0, s.x_dot_0s});
    advance_exact(setup, st, 20 * 0.072);
    EXPECT_NEAR(st.object.xd, s.x_dot_0s, 1e-9) << "seed " << seed;
    EXPECT_NEAR(st.object.x / (20 * 0.072), s.v_bar, 1e-9) << "seed " << seed;
  }
}
