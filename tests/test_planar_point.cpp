// Planar Moreau for a point contact (planar/planar_point.hpp): along one axis it is the 1-D
// scheme (time_stepping.hpp); rotating the whole setup rotates the solution; the friction
// impulse never adds kinetic energy; a stick is exactly zero relative velocity.
#include <gtest/gtest.h>

#include "planar_profiles.hpp"

#include <cmath>
#include <numbers>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/planar/planar_point.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;
using testing_support::kCross;

TEST(PlanarPoint, AlongOneAxisItIsTheOneDimensionalScheme) {
  // The table moves along x; the two-region table rises along x (eq. 7, x_mu = 0.3, w = 0.05).
  // The planar stepper must give the 1-D scheme's x and x' (rounding of m(x) aside) and y = 0.
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.3, 1.0)}) {
    const FieldFriction one_d = two_region_friction(0.3, 0.05, 2.5);
    const PlanarField field = HalfPlaneStepField{0.3, 0.0, 0.0, 0.05, 2.5};
    TimeSteppingOptions o;
    o.step = 1e-3;
    TimeSteppingState ref = make_time_stepping_state(kPaper, {0, 0, 0.2});
    PlanarTableMotion motion;
    motion.first = &kPaper;
    PlanarPointState p = make_planar_point_state(motion, 0, 0, 0, 0.2, 0);
    int sticks = 0;
    for (int block = 0; block < 200; ++block) {
      advance_time_stepping(kPaper, one_d, law, o, ref, 100);
      advance_planar_point(motion, field, law, o, p, 100);
      ASSERT_NEAR(p.x, ref.object.x, 1e-12) << block;
      ASSERT_NEAR(p.ux, ref.object.xd, 1e-12) << block;
      ASSERT_EQ(p.y, 0);
      ASSERT_EQ(p.uy, 0);
      sticks += p.stick;
    }
    EXPECT_GT(p.x, 0.3);  // it walked into the rough region
    EXPECT_GT(sticks, 0);
  }
}

TEST(PlanarPoint, RotatingTheSetupRotatesTheSolution) {
  // Two motions along x and y, a step field rising along 30 degrees, an oblique start; the same
  // setup rotated by alpha must give the rotated trajectory (to round-off).
  const double alpha = 0.7;
  const double c = std::cos(alpha), s = std::sin(alpha);
  TimeSteppingOptions o;
  o.step = 5e-4;
  const FrictionLaw law(1.2, 1.0);
  const PlanarField field = HalfPlaneStepField{0.1, -0.05, std::numbers::pi / 6, 0.08, 2.0};
  PlanarTableMotion a;
  a.first = &kPaper;
  a.second = &kCross;
  PlanarTableMotion b = a;
  b.e1_x = c, b.e1_y = s, b.e2_x = -s, b.e2_y = c;
  PlanarPointState pa = make_planar_point_state(a, 0, 0.01, 0.02, 0.3, -0.1);
  PlanarPointState pb = make_planar_point_state(b, 0, c * 0.01 - s * 0.02, s * 0.01 + c * 0.02,
                                                c * 0.3 + s * 0.1, s * 0.3 - c * 0.1);
  const PlanarField field_b = rotated_field(field, alpha);
  for (int block = 0; block < 40; ++block) {
    advance_planar_point(a, field, law, o, pa, 500);
    advance_planar_point(b, field_b, law, o, pb, 500);
    ASSERT_NEAR(pb.x, c * pa.x - s * pa.y, 1e-9) << block;
    ASSERT_NEAR(pb.y, s * pa.x + c * pa.y, 1e-9) << block;
    ASSERT_NEAR(pb.ux, c * pa.ux - s * pa.uy, 1e-9) << block;
    ASSERT_NEAR(pb.uy, s * pa.ux + c * pa.uy, 1e-9) << block;
  }
  EXPECT_GT(std::hypot(pa.x, pa.y), 0.05);  // it moved
}

TEST(PlanarPoint, FrictionNeverAddsKineticEnergyAndStickIsExactlyZero) {
  // Step by step: |u_{k+1}| <= |u_k - ΔY'| (the friction impulse only removes relative kinetic
  // energy), and whenever the table's velocity increment fits in the static disc the relative
  // velocity is exactly 0.
  PlanarTableMotion motion;
  motion.first = &kPaper;
  motion.second = &kCross;
  const PlanarField field = UniformPlanarField{1.0};
  const FrictionLaw law(2.0, 1.0);
  TimeSteppingOptions o;
  o.step = 2e-3;
  PlanarPointState p = make_planar_point_state(motion, 0, 0, 0, 0.5, 0.4);
  int sticks = 0, slides = 0;
  for (int k = 0; k < 20'000; ++k) {
    const PlanarPointState before = p;
    advance_planar_point(motion, field, law, o, p, 1);
    const double vx = before.ux - (p.table_vx - before.table_vx);
    const double vy = before.uy - (p.table_vy - before.table_vy);
    ASSERT_LE(std::hypot(p.ux, p.uy), std::hypot(vx, vy) * (1 + 1e-15)) << k;
    const bool rest = before.ux == 0 && before.uy == 0;
    if (rest && std::hypot(vx, vy) <= o.step * 2.0 * (1 - 1e-12)) {
      ASSERT_EQ(p.ux, 0);
      ASSERT_EQ(p.uy, 0);
    }
    sticks += p.stick;
    slides += !p.stick;
  }
  EXPECT_GT(sticks, 100);
  EXPECT_GT(slides, 100);
}

TEST(PlanarPoint, BadInputNamesTheParameter) {
  PlanarTableMotion motion;
  motion.first = &kPaper;
  motion.e1_x = 0.9;
  EXPECT_THROW(make_planar_point_state(motion, 0, 0, 0, 0, 0), InvalidParameter);
  motion.e1_x = 1;
  PlanarPointState p = make_planar_point_state(motion, 0, 0, 0, 0, 0);
  EXPECT_THROW(advance_planar_point(motion, HalfPlaneStepField{0, 0, 0, -1, 2}, FrictionLaw{},
                                    {}, p, 1),
               InvalidParameter);
  EXPECT_THROW(advance_planar_point(motion, UniformPlanarField{1}, FrictionLaw(1.0, 1.0, 0.8),
                                    {}, p, 1),
               InvalidParameter);  // not isotropic
}

}  // namespace
}  // namespace selfalign
