// The 1-D friction field as the planar family's one-axis case (planar/planar_field.hpp,
// AxisField), checked by second methods:
//  - its level by hand at points off and on the axis (the projection n . (p - origin));
//  - a ramp field along a direction is the half-plane step field of the same band (two closed
//    forms): levels to rounding, and planar stopping runs on a contact patch that end where the
//    half-plane's runs end;
//  - a point part on a table moving along x, on an axis field along x, is the 1-D Moreau scheme
//    on the same field under a point footprint (time_stepping.hpp: the same step, written once
//    per wing).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_rigid.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {
namespace {

using testing_support::kPaper;

// Rounding of a projection of coordinates of order 1 (a few ulps), and of the planar and 1-D
// schemes' positions after a few thousand steps that read the same levels (each step's update
// is the same arithmetic up to the planar scheme's rotation terms, which are 0 here).
constexpr double kProjectionRounding = 1e-15;
constexpr double kSameScheme = 1e-10;

TEST(AxisField, ReadsTheOneDimensionalFieldAtTheProjection) {
  // Steps 1 -> 3 at position 0.3, laid along +y from (0, 0.1): m = 3 where y - 0.1 >= 0.3.
  const AxisField up{FrictionField::steps({0.3}, {1, 3}), 0.0, 0.1, std::numbers::pi / 2};
  EXPECT_EQ(planar_level(up, 5.0, 0.35), 1.0);  // position 0.25: before the step, any x
  EXPECT_EQ(planar_level(up, -2.0, 0.45), 3.0);  // position 0.35: after it
  // Ramps 1 -> 2 over positions [0, 1] along +x from (0.5, 0): position 0.5 gives 1.5, any y.
  const AxisField along{FrictionField::ramps({0, 1}, {1, 2}), 0.5, 0.0, 0.0};
  EXPECT_NEAR(planar_level(along, 1.0, 7.0), 1.5, kProjectionRounding);
  EXPECT_EQ(planar_level(along, -3.0, 0.0), 1.0);
  EXPECT_EQ(planar_level(along, 9.0, -4.0), 2.0);
  // Rotating the setup rotates the field: the rotated field at the rotated point.
  const double a = 0.7, c = std::cos(a), s = std::sin(a);
  const PlanarField turned = rotated_field(PlanarField(along), a);
  for (double x : {0.2, 0.9, 1.3})
    for (double y : {-1.0, 0.4})
      EXPECT_NEAR(planar_level(turned, c * x - s * y, s * x + c * y), planar_level(along, x, y),
                  1e-12)
          << x << " " << y;
}

TEST(AxisField, RefusesALevelThatHoldsNothing) {
  const AxisField zero{FrictionField::steps({0.0}, {1, 0}), 0, 0, 0};
  try {
    validate(PlanarField(zero));
    FAIL() << "a level of 0 was accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "levels");
  }
  const AxisField fine{FrictionField::steps({0.0}, {1, 2}), 0, 0, 0};
  EXPECT_NO_THROW(validate(PlanarField(fine)));
}

TEST(AxisField, ARampAlongADirectionIsTheHalfPlaneStep) {
  const double angle = 0.4, ox = 0.3, oy = -0.1, w = 0.05, c_mu = 4.0;
  const HalfPlaneStepField half{ox, oy, angle, w, c_mu};
  const AxisField ramp{FrictionField::ramps({0, w}, {1, c_mu}), ox, oy, angle};
  for (int i = -30; i <= 30; ++i)
    for (int j = -3; j <= 3; ++j) {
      const double x = ox + 0.004 * i, y = oy + 0.1 * j;
      EXPECT_NEAR(planar_level(ramp, x, y), planar_level(half, x, y), 4 * c_mu * 2.3e-16 / w)
          << x << " " << y;
    }
  // Stopping runs of a rectangular patch on both: the same ends (the levels differ by rounding
  // only, so the runs do too, well inside the 1e-9 the stopping analysis resolves).
  PlanarProblem p;
  p.motion.first = &kPaper;
  p.part.patch = rectangle_patch(0.04, 0.02, 3, 2);
  p.options.step = 1.0 / 200;
  const std::vector<PlanarPose> entries = {{0.2, 0.0, 0.0}, {0.25, 0.02, 0.3}};
  p.field = half;
  const PlanarStopSummary on_half = planar_stop(p, entries, 200, {}, 1);
  p.field = ramp;
  const PlanarStopSummary on_ramp = planar_stop(p, entries, 200, {}, 1);
  ASSERT_EQ(on_half.stopped, 2) << "the entries must stop in the rough region";
  ASSERT_EQ(on_ramp.stopped, 2);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_NEAR(on_ramp.runs[k].end.x, on_half.runs[k].end.x, 1e-9) << k;
    EXPECT_NEAR(on_ramp.runs[k].end.y, on_half.runs[k].end.y, 1e-9) << k;
    EXPECT_NEAR(on_ramp.runs[k].end.angle, on_half.runs[k].end.angle, 1e-9) << k;
    EXPECT_EQ(on_ramp.runs[k].periods, on_half.runs[k].periods) << k;
  }
}

TEST(AxisField, APointPartAlongTheAxisIsTheOneDimensionalScheme) {
  // A staircase and a ramp the part walks across under the paper's motion (Sect. 7.2).
  const FrictionField field = FrictionField::ramps({0.05, 0.08, 0.1, 0.16}, {1, 1.4, 1.2, 4});
  const TimeSteppingOptions options{1e-3, 0.5};
  const long long steps = 6000;  // 6 periods
  TimeSteppingState one_d = make_time_stepping_state(kPaper, {0, 0.0, 0.0});
  advance_time_stepping(kPaper, FieldFriction(field, PointFootprint{}), options, one_d, steps);

  PlanarTableMotion motion;
  motion.first = &kPaper;
  const AxisField axis{field, 0, 0, 0};
  PlanarRigidState planar = make_planar_rigid_state(motion, 0, {0, 0, 0}, {});
  advance_planar_rigid(motion, axis, FrictionLaw{}, RigidPart{}, options, planar, steps);
  EXPECT_GT(one_d.object.x, 0.1) << "the part must walk onto the rising friction";
  EXPECT_NEAR(planar.pose.x, one_d.object.x, kSameScheme);
  EXPECT_NEAR(planar.twist.ux, one_d.object.xd, kSameScheme);
  EXPECT_EQ(planar.pose.y, 0.0);
  EXPECT_EQ(planar.pose.angle, 0.0);
}

}  // namespace
}  // namespace selfalign
