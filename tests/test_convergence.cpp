// Tests for analysis/convergence.hpp: the Lyapunov argument of Sect. 6.2 (eqs. 35-37).
#include <gtest/gtest.h>

#include "selfalign/special_values.hpp"

#include "selfalign/analysis/convergence.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"

#include <cmath>
#include <limits>

using namespace selfalign;

namespace {
// V is formed from velocities of O(1): equal-sign intervals keep v1 - v2 constant up to
// rounding of a few operations per arc.
constexpr double kFlatTol = 1e-12;

// Checks V' = 0 on '=' intervals and V' <= 0 on '≠' intervals (eq. 36) at the samples.
void expect_lyapunov_shape(const VelocityConvergence& c) {
  std::size_t k = 0;
  for (const SignInterval& iv : c.intervals) {
    while (k + 1 < c.t.size() && c.t[k] < iv.t_begin) ++k;
    for (std::size_t j = k; j + 1 < c.t.size() && c.t[j + 1] <= iv.t_end; ++j) {
      if (iv.same)
        EXPECT_NEAR(c.lyapunov[j + 1], c.lyapunov[j], kFlatTol) << "'=' at t = " << c.t[j];
      else
        EXPECT_LE(c.lyapunov[j + 1], c.lyapunov[j] + kFlatTol) << "'≠' at t = " << c.t[j];
    }
  }
}
}  // namespace

TEST(Convergence, CaseOneCoincidesInFiniteTime) {
  const ThreePhaseProfile profile({1.0, 0.084, 3.0, 0.9});
  ConvergenceOptions o;
  o.v1 = 0.6;
  o.v2 = -0.4;
  o.duration = 6;
  const VelocityConvergence c = velocity_convergence(profile, o);
  ASSERT_TRUE(c.t_coincide.has_value());
  EXPECT_GT(*c.t_coincide, 0.0);
  EXPECT_LT(*c.t_coincide, o.duration);
  EXPECT_DOUBLE_EQ(c.lyapunov.front(), 0.5);  // (0.6 - (-0.4))^2 / 2
  for (std::size_t i = 0; i < c.t.size(); ++i)
    if (c.t[i] >= *c.t_coincide) EXPECT_EQ(c.lyapunov[i], 0.0) << "t = " << c.t[i];
  expect_lyapunov_shape(c);
  // V decreases somewhere, only on '≠' intervals, and both kinds of interval occur.
  bool saw_same = false, saw_different = false;
  for (const SignInterval& iv : c.intervals) (iv.same ? saw_same : saw_different) = true;
  EXPECT_TRUE(saw_same);
  EXPECT_TRUE(saw_different);
}

TEST(Convergence, SlipSlipConvergesOnlyAsymptotically) {
  const ThreePhaseProfile profile({1.0, 0.084, 1.05, 2.0});
  ConvergenceOptions o;
  o.v1 = 0.3;
  o.v2 = -0.3;
  o.duration = 5;
  const VelocityConvergence c = velocity_convergence(profile, o);
  EXPECT_FALSE(c.t_coincide.has_value());
  EXPECT_GT(c.lyapunov.back(), 0.0);
  EXPECT_LT(c.lyapunov.back(), 1e-3 * c.lyapunov.front());
  expect_lyapunov_shape(c);
}

// Python API fuzz (issue 9, seed 8): a duration below the rounding of t0 left both arc lists
// empty and the sampling read past them (segfault). It is misuse, refused by name.
TEST(Convergence, DurationBelowTheRoundingOfT0IsRefused) {
  const ThreePhaseProfile profile({1.0, 0.084, 3.0, 0.9});
  ConvergenceOptions o;
  o.t0 = 1e-300;
  o.duration = 5e-324;
  o.samples_per_period = 1;
  EXPECT_THROW(velocity_convergence(profile, o), InvalidParameter);
  o.t0 = 1e7;
  o.duration = 1e-10;  // 1e-10 periods: beyond the floor of 1e-9 periods
  EXPECT_THROW(velocity_convergence(profile, o), InvalidParameter);
  o.duration = 1e-9 * 1.5;  // above the floor and resolvable at t0 = 1e7 (ulp 1.9e-9)
  EXPECT_NO_THROW(velocity_convergence(profile, o));
}

namespace {

// Closed-form reference for a viscous law on a piecewise-constant table acceleration
// (docs/slip-integrator.md, V1-V3): in a slip of direction sigma under y'' = A,
//   x'' = -sigma k - c x' - A,  x'(t) = (v0 + b/c) e^{-c t} - b/c,  b = sigma k + A,
// reaching x' = 0 at t* = ln(1 + c v0 / b) / c when sigma b > 0; at x' = 0 the object sticks
// while |A| <= s, else slips against A. Event by event, no integrator.
double viscous_velocity(const PiecewisePolynomialProfile& p, double s, double k, double c,
                        double v, double t_end) {
  const auto segs = p.segments();
  double t = 0;
  for (std::size_t i = 0; t < t_end; i = (i + 1) % segs.size()) {
    const double period_start = std::floor(t / p.period() + 1e-12) * p.period();
    const double seg_end = std::min(t_end, period_start + segs[i].begin + segs[i].duration);
    if (seg_end <= t) continue;
    const double A = segs[i].accel;
    while (t < seg_end) {
      if (v == 0) {
        if (std::abs(A) <= s) { t = seg_end; break; }
      }
      const double sigma = v > 0 ? 1 : v < 0 ? -1 : (A > 0 ? -1 : 1);
      const double b = sigma * k + A;
      // The time to the velocity zero (a slip from rest first moves against A).
      const double t_star = v != 0 && sigma * b > 0 ? std::log(1 + c * v / b) / c : kInf;
      const double tau = std::min(t_star, seg_end - t);
      v = tau == t_star ? 0.0 : (v + b / c) * std::exp(-c * tau) - b / c;
      t += tau;
    }
  }
  return v;
}
}  // namespace

// D22: under a speed-dependent law the analysis read past an empty arc list (SIGSEGV). Now
// the slip integrator runs both responses; their velocities match the closed-form viscous
// reference above, and eq. (36)'s shape holds.
TEST(Convergence, ViscousLawMatchesTheClosedFormResponses) {
  const ThreePhaseProfile profile({1.0, 0.084, 2.3, 1.3});
  const double c = 0.7;
  const FrictionLaw law = FrictionLaw(1.2, 1.0).with_viscous(c);
  ConvergenceOptions o;
  o.v1 = 0.5;
  o.v2 = -0.5;
  o.duration = 3;
  o.samples_per_period = 20;
  const VelocityConvergence r = velocity_convergence(profile, law, o);
  ASSERT_FALSE(r.t.empty());
  // The integrator at its default rtol 1e-10 over 3 periods: 1e-8 is 100 tolerances.
  constexpr double kIntegratorTol = 1e-8;
  for (std::size_t j = 0; j < r.t.size(); j += 7) {
    const PiecewisePolynomialProfile& p = *profile.piecewise_polynomial();
    EXPECT_NEAR(r.v1[j], viscous_velocity(p, 1.2, 1.0, c, o.v1, r.t[j]), kIntegratorTol)
        << "t = " << r.t[j];
    EXPECT_NEAR(r.v2[j], viscous_velocity(p, 1.2, 1.0, c, o.v2, r.t[j]), kIntegratorTol)
        << "t = " << r.t[j];
  }
  EXPECT_LE(r.lyapunov.back(), r.lyapunov.front());
  EXPECT_NO_THROW(velocity_convergence(profile, FrictionLaw(1.2, 1.0).with_stribeck(0.1), o));
}
