// Tests for friction/friction_law.hpp and its use by both solvers: static >= kinetic and
// direction-dependent kinetic coefficients.
//  - The exact steady state of a two-level table acceleration against the hand derivation of
//    docs/static-kinetic-two-level.md (tests/oracles/two_level_static_kinetic.hpp, itself
//    checked against an exact-rational simulation by its .py companion).
//  - Moreau time-stepping converges to the exact solution with observed order about 1.
//  - The uniform solver and the general one (two identical friction pieces force it) give the
//    same arcs: two codes, one law.
#include <gtest/gtest.h>

#include "arc_list.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "moreau_order.hpp"
#include "oracles/two_level_static_kinetic.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/exact.hpp"

using namespace selfalign;

namespace {

PiecewisePolynomialProfile two_level(const oracle::TwoLevelCase& c) {
  const double d[3] = {c.T1, c.T2, c.T3}, a[3] = {c.a_s, -c.a_max, c.a_max};
  return PiecewisePolynomialProfile::from_accelerations(d, a);
}

oracle::TwoLevelCase with_balanced_stick_phase(double s, double k, double a_max, double T1,
                                               double T2, double T3) {
  return {s, k, a_max, a_max * (T2 - T3) / T1, T1, T2, T3};  // zero net velocity change
}

using selfalign::testing_support::ArcList;

}  // namespace

TEST(FrictionLaw, DefaultIsThePapersLawAndRefusesKineticAboveStatic) {
  EXPECT_TRUE(FrictionLaw{}.is_unit());
  const FrictionLaw law(1.2, 1.0, 0.8);
  EXPECT_EQ(law.kinetic(+1), 1.0);
  EXPECT_EQ(law.kinetic(-1), 0.8);
  try {
    FrictionLaw(1.0, 1.2);
    FAIL() << "kinetic above static accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(std::string(e.what()),
              "invalid mu_static, mu_kinetic = 1, 1.2: the static coefficient must be >= the "
              "kinetic one (mu_kinetic <= mu_static)");
  }
  EXPECT_THROW(FrictionLaw(1.0, 1.0, 1.5), InvalidParameter);
  EXPECT_THROW(FrictionLaw(1.0, -1.0), InvalidParameter);
  EXPECT_THROW(FrictionLaw(std::nan(""), 1.0), InvalidParameter);
}

// The front ends' convention (issue 20, F07, D32): absolute coefficients, their ratios to the
// kinetic mu formed after each is checked as given.
TEST(FrictionLaw, OfCoefficientsTakesRatiosToMuAfterCheckingEachAsGiven) {
  const FrictionLaw law = law_of_coefficients(0.59, 0.72, std::nullopt);
  EXPECT_EQ(law.static_coefficient(), 0.72 / 0.59);
  EXPECT_EQ(law.kinetic_forward(), 1.0);
  EXPECT_EQ(law.kinetic_backward(), 1.0);
  EXPECT_TRUE(law_of_coefficients(0.3, std::nullopt, std::nullopt).is_unit());
  EXPECT_EQ(law_of_coefficients(0.3, 0.36, 0.24).kinetic_backward(), 0.24 / 0.3);
  const auto message = [](double mu, std::optional<double> s, std::optional<double> b) {
    try {
      law_of_coefficients(mu, s, b);
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // 1e-300 was refused as the ratio "mu_kinetic_backward = 3.3e-300".
  EXPECT_EQ(message(0.3, std::nullopt, 1e-300),
            "invalid mu_backward = 1e-300: must be > 0, within [1e-50, 1e50]");
  EXPECT_EQ(message(0.3, std::nan(""), std::nullopt),
            "invalid mu_static = nan: must be > 0, within [1e-50, 1e50]");
  EXPECT_EQ(message(0.3, 0.2, std::nullopt),
            "invalid mu_static = 0.2: must be >= mu = 0.3 (the static coefficient is >= the "
            "kinetic one)");
  EXPECT_EQ(message(0.3, std::nullopt, 0.5),
            "invalid mu_backward = 0.5: must be <= mu_static = 0.3 (the static coefficient is "
            ">= the kinetic one)");
  // The ratios stay within FrictionLaw's own range [1e-50, 1e50].
  EXPECT_EQ(message(1e40, std::nullopt, 1e-20).rfind("invalid mu_backward = 1e-20: must be >= 1e-50 mu", 0), 0u);
  EXPECT_EQ(message(1e-40, 1e20, std::nullopt).rfind("invalid mu_static = 1e+20: must be <= 1e50 mu", 0), 0u);
}

// v̄ of the exact steady state equals the hand derivation to 1e-12 (the closed form is a few
// dozen flops of O(1) numbers, the solver's arcs are closed forms: both far below 1e-12).
TEST(StaticKinetic, TwoLevelSteadyVelocityMatchesTheHandDerivation) {
  constexpr double kVbarTol = 1e-12;
  const oracle::TwoLevelCase cases[] = {
      with_balanced_stick_phase(1.0, 1.0, 2.0, 1, 1, 1),        // S1: pattern A, mu_s = mu_k
      with_balanced_stick_phase(1.5, 1.0, 2.0, 1, 1, 1),        // S2: A, mu_s > mu_k
      with_balanced_stick_phase(1.0, 1.0, 3.0, 1, 1, 1.5),      // S3: B (no stick)
      with_balanced_stick_phase(1.2, 1.0, 3.0, 1, 1, 1.5),      // S4: B
      with_balanced_stick_phase(1.6, 1.0, 3.0, 1, 1, 1.5),      // S5: A: mu_s holds a_s
      with_balanced_stick_phase(2.5, 1.0, 3.0, 1, 1, 1.5),      // S6: A
      with_balanced_stick_phase(3.5, 1.0, 3.0, 1, 1, 1.5),      // S7: locked
      with_balanced_stick_phase(0.8, 0.5, 1.7, 0.7, 0.4, 0.55), // S8: A
      with_balanced_stick_phase(1.0, 1.0, 2.0, 1, 1.1, 1),      // S9: A
      with_balanced_stick_phase(0.5, 0.5, 2.0, 0.8, 0.3, 0.6),  // S10: B
      with_balanced_stick_phase(0.8, 0.5, 2.0, 0.8, 0.3, 0.6),  // S11: A
  };
  int patterns[4] = {0, 0, 0, 0};
  for (const oracle::TwoLevelCase& c : cases) {
    const oracle::TwoLevelResult expected = oracle::two_level_vbar(c);
    ASSERT_TRUE(expected.valid()) << "mu_s " << c.mu_s << " a_max " << c.a_max;
    ++patterns[static_cast<int>(expected.pattern)];
    const auto profile = two_level(c);
    const SteadyState r = steady_state(profile, FrictionLaw(c.mu_s, c.mu_k));
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.v_bar, expected.vbar, kVbarTol)
        << "mu_s " << c.mu_s << " mu_k " << c.mu_k << " a_max " << c.a_max;
  }
  EXPECT_GT(patterns[0], 0);  // locked, stick-slip and slip-slip all exercised
  EXPECT_GT(patterns[1], 0);
  EXPECT_GT(patterns[2], 0);
}

// The static coefficient changes the answer: the same table motion gives v̄_B for
// mu_k <= mu_s < |a_s| and v̄_A for |a_s| <= mu_s (docs/static-kinetic-two-level.md, S3-S6).
TEST(StaticKinetic, TheStaticCoefficientDecidesTheStickAndSoTheVelocity) {
  const auto profile = two_level(with_balanced_stick_phase(1.2, 1.0, 3.0, 1, 1, 1.5));
  const double vb = steady_state(profile, FrictionLaw(1.2, 1.0)).v_bar;
  const double va = steady_state(profile, FrictionLaw(1.6, 1.0)).v_bar;
  EXPECT_NEAR(vb, -1.0 / 168, 1e-12);  // exact rationals of the derivation
  EXPECT_NEAR(va, -3.0 / 35, 1e-12);
  EXPECT_EQ(steady_state(profile, FrictionLaw(1.2, 1.0)).pattern, "forward,backward");
  EXPECT_EQ(steady_state(profile, FrictionLaw(1.6, 1.0)).pattern, "stick,forward,backward");
}

// Direction-dependent kinetic coefficients: on a table with only one slip direction per
// half-period, the forward-slip acceleration uses k_+, the backward k_-. Pattern A with
// k_- != k_+ follows from the derivation with k replaced per direction; here it is checked on
// a single forward slip from rest: x'' = a_max - k_+ until the table reverses.
TEST(StaticKinetic, ForwardSlipUsesTheForwardKineticCoefficient) {
  const double d[2] = {1.0, 1.0}, acc[2] = {-2.0, 2.0};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(d, acc);
  const UniformFriction uniform;
  const FrictionLaw law(1.5, 0.7, 1.1);
  const ExactSetup setup{profile, *uniform.piecewise_affine(), law};
  ArcList list;
  ExactState s = make_exact_state(setup, {0, 0, 0});
  advance_exact(setup, s, 2.0, &list);
  ASSERT_GE(list.arcs.size(), 2u);
  // [0, 1): A = -2, |A| > 1.5: forward slip with x'' = 2 - 0.7 = 1.3, x'(1) = 1.3.
  EXPECT_EQ(list.arcs[0].direction, 1);
  EXPECT_NEAR(list.arcs[0].xd1, 1.3, 1e-15);
  // [1, 2): A = +2: x'' = -0.7 - 2 = -2.7, stop at 1 + 1.3/2.7, then |A| = 2 > 1.5: backward
  // slip with x'' = 1.1 - 2 = -0.9.
  EXPECT_NEAR(list.arcs[1].t1, 1 + 1.3 / 2.7, 1e-15);
  EXPECT_EQ(list.arcs[2].direction, -1);
  EXPECT_NEAR(std::get<PolynomialArc>(list.arcs[2].shape).accel, -0.9, 1e-15);
}

// Two codes, one law: two identical constant pieces send the solver down its general path;
// the uniform path must give the same arcs (to rounding: the general path forms the same
// closed forms).
TEST(StaticKinetic, UniformAndGeneralSolversAgree) {
  constexpr double kTol = 1e-13;
  const double inf = std::numeric_limits<double>::infinity();
  const AffinePiece two[2] = {{-inf, 0.37, 1.0, 0.0}, {0.37, inf, 1.0, 0.0}};
  const PiecewiseAffineFriction split(two);
  const UniformFriction uniform;
  const double d[3] = {0.6, 0.5, 0.9}, acc[3] = {0.3, -2.6, (2.6 * 0.5 - 0.3 * 0.6) / 0.9};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(d, acc);
  for (const FrictionLaw& law :
       {FrictionLaw{}, FrictionLaw(1.4, 1.0), FrictionLaw(1.4, 0.9, 1.2)}) {
    ArcList a, b;
    const ExactSetup fast{profile, *uniform.piecewise_affine(), law};
    const ExactSetup general{profile, split, law};
    ExactState sa = make_exact_state(fast, {0, 0, 0}), sb = make_exact_state(general, {0, 0, 0});
    advance_exact(fast, sa, 20.0, &a);
    advance_exact(general, sb, 20.0, &b);
    EXPECT_NEAR(sa.object.x, sb.object.x, kTol) << law.describe();
    EXPECT_NEAR(sa.object.xd, sb.object.xd, kTol) << law.describe();
    std::size_t stops_a = 0, stops_b = 0;
    for (const Arc& arc : a.arcs) stops_a += arc.end == ArcEnd::velocity_zero;
    for (const Arc& arc : b.arcs) stops_b += arc.end == ArcEnd::velocity_zero;
    EXPECT_EQ(stops_a, stops_b) << law.describe();
  }
}

// Moreau's scheme with the static bound for sticking and the kinetic impulse for sliding is
// first order: RMS error over 8 grid phases after 10 periods, h = 1e-3, 1e-4, 1e-5; each
// decade gains at least 0.8 orders (the event lottery is averaged, not removed: 0.8, not 1).
TEST(StaticKinetic, MoreauConvergesWithOrderOneForStaticAboveKinetic) {
  constexpr double kMinOrder = 0.8;
  const auto c = with_balanced_stick_phase(1.6, 1.0, 3.0, 1, 1, 1.5);  // S5: stick-slip
  const auto profile = two_level(c);
  const FrictionLaw law(1.6, 1.0);
  const double duration = 10 * profile.period();
  const double e3 = testing_support::moreau_rms_error(profile, law, duration, 1e-3);
  const double e4 = testing_support::moreau_rms_error(profile, law, duration, 1e-4);
  const double e5 = testing_support::moreau_rms_error(profile, law, duration, 1e-5);
  RecordProperty("errors", ::testing::PrintToString(std::vector<double>{e3, e4, e5}));
  EXPECT_GE(std::log10(e3 / e4), kMinOrder) << e3 << " " << e4 << " " << e5;
  EXPECT_GE(std::log10(e4 / e5), kMinOrder) << e3 << " " << e4 << " " << e5;
}

// The same for a finite-jerk profile under static > kinetic (stick breaks inside ramps).
TEST(StaticKinetic, MoreauConvergesWithOrderOneForAFiniteJerkProfile) {
  constexpr double kMinOrder = 0.8;
  const JerkLimitedThreePhaseProfile profile({2.0, 0.1, 2.5, 1.5, 40.0});
  const FrictionLaw law(1.3, 1.0);
  const double duration = 10 * profile.period();
  const double e3 = testing_support::moreau_rms_error(profile, law, duration, 1e-3);
  const double e4 = testing_support::moreau_rms_error(profile, law, duration, 1e-4);
  const double e5 = testing_support::moreau_rms_error(profile, law, duration, 1e-5);
  RecordProperty("errors", ::testing::PrintToString(std::vector<double>{e3, e4, e5}));
  EXPECT_GE(std::log10(e3 / e4), kMinOrder) << e3 << " " << e4 << " " << e5;
  EXPECT_GE(std::log10(e4 / e5), kMinOrder) << e3 << " " << e4 << " " << e5;
}
