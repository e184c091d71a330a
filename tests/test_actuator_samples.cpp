// One period sampled for a motion controller (design/actuator_samples.hpp): the samples follow
// the three-phase closed form (y'' = 0, -y2'', +y3'' between the switch times the design
// reports), loop seamlessly, and the jerk and force columns are the ramps' +-j and m y''.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "selfalign/design/actuator_samples.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {

DesignRequest small_request() {
  DesignRequest q;
  q.acceleration_grid = 6, q.period_grid = 2, q.stroke_grid = 1, q.entries = 4;
  return q;
}

TEST(ActuatorSamples, FollowTheThreePhaseClosedFormAndLoopSeamlessly) {
  const DesignRequest q = small_request();
  const DesignResult d = design_process(q);
  ASSERT_TRUE(d.feasible);
  const double rate = 997;  // not a multiple of the frequency: the rate is adjusted
  const ActuatorSamples s = actuator_samples(q, d, rate, 2.5);
  const long long n = std::llround(d.period * rate);
  ASSERT_EQ(s.samples_per_period, n);
  ASSERT_EQ(static_cast<long long>(s.t.size()), n);
  EXPECT_NEAR(s.sample_rate, n / d.period, 1e-9 * s.sample_rate);
  EXPECT_EQ(s.t.front(), 0);
  EXPECT_NEAR(s.t.back(), d.period * (n - 1) / n, 1e-15);  // no repeated endpoint
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const double t = s.t[i];
    // Between the switch times the design reports (away from the switches by a sample's
    // rounding), y'' is the plateau of eqs. (61)-(67): 0, -y2'', +y3''.
    const double expected = t < d.t1 ? 0 : t < d.t2 ? -d.a2 : d.a3;
    if (std::abs(t - d.t1) > 1e-12 && std::abs(t - d.t2) > 1e-12)
      EXPECT_NEAR(s.y_ddot[i], expected, 1e-9 * d.a2) << t;
    EXPECT_EQ(s.y_dddot[i], 0);                     // jump profile: plateaus
    EXPECT_DOUBLE_EQ(s.force[i], 2.5 * s.y_ddot[i]);
  }
  // Seamless loop: y and y' of the last sample, carried one sample step on its plateau (+y3''),
  // land on the first sample's.
  const double h = 1 / s.sample_rate;
  EXPECT_NEAR(s.y_dot.back() + d.a3 * h, s.y_dot.front(), 1e-9);
  EXPECT_NEAR(s.y.back() + s.y_dot.back() * h + 0.5 * d.a3 * h * h, s.y.front(), 1e-12);
  // The stroke is the design's.
  const auto [lo, hi] = std::minmax_element(s.y.begin(), s.y.end());
  EXPECT_NEAR(*hi - *lo, d.stroke, d.stroke * 1e-3);
}

TEST(ActuatorSamples, JerkColumnIsTheRampsJerk) {
  DesignRequest q = small_request();
  q.jerk_max = 5000;
  const DesignResult d = design_process(q);
  ASSERT_TRUE(d.feasible);
  const ActuatorSamples s = actuator_samples(q, d, 20'000);
  EXPECT_TRUE(s.force.empty());
  std::set<long long> values;
  for (double j : s.y_dddot) values.insert(std::llround(j));
  EXPECT_EQ(values, (std::set<long long>{-5000, 0, 5000}));
}

TEST(ActuatorSamples, BadInputNamesTheParameter) {
  const DesignRequest q = small_request();
  const DesignResult d = design_process(q);
  EXPECT_THROW(actuator_samples(q, d, 0), InvalidParameter);
  EXPECT_THROW(actuator_samples(q, d, 1e12), InvalidParameter);
  EXPECT_THROW(actuator_samples(q, d, 1000, -1), InvalidParameter);
}

}  // namespace
}  // namespace selfalign
