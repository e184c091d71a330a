// Tests for analysis/floquet.hpp: multipliers {1, 0} for responses that stick (eq. 30) and the
// slip-slip lambda2 of eq. (33), by three methods.
#include <gtest/gtest.h>

#include <cmath>

#include "selfalign/analysis/floquet.hpp"

using namespace selfalign;

namespace {
// Analytic and saltation matrices are products of closed forms: 1e-10 (issue's bound). Central
// differences with step 1e-7 of a piecewise-smooth map: truncation O(h^2) ~ 1e-14, rounding
// ~ 1e-16/1e-7 = 1e-9; 1e-5 is the bound.
constexpr double kClosedFormTol = 1e-10;
constexpr double kFiniteDifferenceTol = 1e-5;

void expect_multipliers(const Monodromy& m, double l1, double l2, double tol) {
  ASSERT_TRUE(m.available);
  EXPECT_NEAR(m.multipliers[0].real(), l1, tol);
  EXPECT_NEAR(m.multipliers[1].real(), l2, tol);
  EXPECT_NEAR(m.multipliers[0].imag(), 0.0, tol);
  EXPECT_NEAR(m.multipliers[1].imag(), 0.0, tol);
}
}  // namespace

TEST(Floquet, StickingResponsesHaveMultipliersOneAndZero) {
  const ThreePhaseParameters settings[] = {
      {1.0, 0.084, 3.0, 0.9},  // case 1
      {1.0, 0.084, 0.9, 3.0},  // case 2
      {1.0, 0.084, 2.3, 1.3},  // case 3
      {2.0, 0.084, 0.9, 0.9},  // case 5
  };
  for (const auto& p : settings) {
    SCOPED_TRACE(::testing::Message() << p.a2 << ", " << p.a3);
    const FloquetAnalysis f = floquet_multipliers(ThreePhaseProfile(p));
    // The analytic matrix is [[1, m12], [0, 0]] by construction (eq. 30), so its multipliers
    // {1, 0} prove nothing (issue 21): it is checked entry by entry against the saltation
    // matrix, a second method (the arcs' transition matrices coupled by the saltation jumps of
    // their events, computed from the simulated period, nothing assumed about sticks).
    // m12 = d x(t3)/d x'_0s is 0 when the period starts in stick (x'_0s = 0) and the time to
    // the stick otherwise (case 3 here starts sliding back, x'_0s < 0).
    ASSERT_TRUE(f.analytic.available);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        EXPECT_NEAR(f.analytic.matrix(i, j), f.saltation.matrix(i, j), kClosedFormTol) << i << j;
    EXPECT_NEAR(f.finite_difference.matrix(0, 1), f.saltation.matrix(0, 1), kFiniteDifferenceTol);
    if (f.steady.x_dot_0s == 0) EXPECT_EQ(f.analytic.matrix(0, 1), 0.0);
    expect_multipliers(f.saltation, 1, 0, kClosedFormTol);
    expect_multipliers(f.finite_difference, 1, 0, kFiniteDifferenceTol);
    // Eigenvector of 1 is the position direction (eq. 30): the first column is [1, 0].
    EXPECT_NEAR(f.saltation.matrix(0, 0), 1, kClosedFormTol);
    EXPECT_NEAR(f.saltation.matrix(1, 0), 0, kClosedFormTol);
  }
}

TEST(Floquet, SlipSlipMultiplierMatchesEquationThirtyThree) {
  const ThreePhaseParameters settings[] = {
      {1.0, 0.084, 1.05, 2.0},
      {0.072, 0.021, 37.9379, 233.673},
  };
  for (const auto& p : settings) {
    SCOPED_TRACE(::testing::Message() << p.a2 << ", " << p.a3);
    const FloquetAnalysis f = floquet_multipliers(ThreePhaseProfile(p));
    ASSERT_EQ(f.steady.motion_case, StickSlipCase::slip_slip);
    const double lambda2 = ((p.a2 - 1) * (p.a3 - 1)) / ((p.a2 + 1) * (p.a3 + 1));  // eq. (33)
    expect_multipliers(f.analytic, 1, lambda2, kClosedFormTol);
    expect_multipliers(f.saltation, 1, lambda2, kClosedFormTol);
    expect_multipliers(f.finite_difference, 1, lambda2, kFiniteDifferenceTol);
    // The full matrices agree too (the off-diagonal m12 of eq. 33 included).
    EXPECT_NEAR(f.analytic.matrix(0, 1), f.saltation.matrix(0, 1), 1e-9);
    EXPECT_NEAR(f.finite_difference.matrix(0, 1), f.saltation.matrix(0, 1), kFiniteDifferenceTol);
    EXPECT_LT(f.spread, kFiniteDifferenceTol);
  }
}
