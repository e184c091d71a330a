// Tests for friction/friction_map.hpp and the paper's two-region table (friction_field.hpp):
// eqs. (7)-(9) evaluated by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"

using namespace selfalign;

TEST(TwoRegionTable, MatchesEquationsSevenToNine) {
  const FieldFriction f = two_region_friction(0.3, 0.05, 2.5);
  EXPECT_EQ(f.bound(-10.0), 1.0);  // low-friction region: mu_1
  EXPECT_EQ(f.bound(0.3), 1.0);    // z = 0 at x = x_mu
  // Halfway across: z = w/2, mu_bar = (w - z)/w mu_1 + z/w mu_2 = (1 + 2.5)/2 = 1.75 (eq. 7).
  EXPECT_NEAR(f.bound(0.325), 1.75, 1e-14);
  EXPECT_NEAR(f.bound(0.35), 2.5, 1e-14);  // z = w: fully on mu_2
  EXPECT_EQ(f.bound(7.0), 2.5);
  ASSERT_NE(f.two_region(), nullptr);
  EXPECT_NEAR(f.two_region()->b1(), 30.0, 1e-13);              // (c_mu - 1)/w
  EXPECT_NEAR(f.two_region()->b2(), 30.0 * 0.3 - 1.0, 1e-13);  // (c_mu - 1) x_mu / w - 1
}

TEST(TwoRegionTable, PiecewiseAffineFormAgreesWithBound) {
  const FieldFriction f = two_region_friction(-0.2, 0.1, 3.0);
  const PiecewiseAffineFriction* pa = f.piecewise_affine();
  ASSERT_NE(pa, nullptr);
  ASSERT_EQ(pa->pieces().size(), 3u);
  for (double x = -1.0; x <= 1.0; x += 0.0137) EXPECT_NEAR(pa->bound(x), f.bound(x), 1e-14) << x;
}

TEST(TwoRegionTable, RejectsMisuseNamingTheParameter) {
  auto name_of = [](auto make) {
    try {
      make();
    } catch (const InvalidParameter& e) {
      return e.name() + ": " + e.allowed();
    }
    return std::string("no throw");
  };
  EXPECT_EQ(name_of([] { two_region_friction(0, -0.05, 2.5); }), "width: must be > 0");
  EXPECT_EQ(name_of([] { two_region_friction(0, 0.05, 1.0); }), "c_mu: must be > 1");
  EXPECT_EQ(name_of([] { TwoRegionTable(0, 0.05, 1.0); }), "c_mu: must be > 1");
  EXPECT_EQ(name_of([] { two_region_friction(std::nan(""), 0.05, 2.5); }),
            "x_mu: must be a finite number");
  EXPECT_EQ(name_of([] { UniformFriction(0.0); }), "friction level: must be > 0");
}

TEST(PiecewiseAffineFriction, RejectsGapsAndNegativeBounds) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const AffinePiece gap[2] = {{-inf, 0, 1, 0}, {1, inf, 1, 0}};
  EXPECT_THROW(PiecewiseAffineFriction{gap}, InvalidParameter);
  const AffinePiece negative[3] = {{-inf, 0, 1, 0}, {0, 1, 1, -2}, {1, inf, 1, 0}};
  EXPECT_THROW(PiecewiseAffineFriction{negative}, InvalidParameter);
  const AffinePiece bounded[1] = {{0, 1, 1, 0}};
  EXPECT_THROW(PiecewiseAffineFriction{bounded}, InvalidParameter);
}

// The capability queries that replace casts (issue 21): the two-region table is a field built
// by its named constructor, and answers with its parameters; a uniform level is neither.
TEST(FrictionCapabilities, EachMapAnswersForItselfOnly) {
  const selfalign::FieldFriction two = selfalign::two_region_friction(0.5, 0.1, 2.0);
  const selfalign::UniformFriction uniform;
  ASSERT_NE(two.two_region(), nullptr);
  EXPECT_EQ(two.two_region()->x_mu(), 0.5);
  EXPECT_EQ(two.two_region()->width(), 0.1);
  EXPECT_EQ(two.two_region()->c_mu(), 2.0);
  EXPECT_EQ(two.field_friction(), &two);
  EXPECT_EQ(uniform.two_region(), nullptr);
  EXPECT_EQ(uniform.field_friction(), nullptr);
  EXPECT_EQ(uniform.uniform(), &uniform);
  EXPECT_EQ(two.uniform(), nullptr);
}
