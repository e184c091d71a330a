// Tests for design/process_design.hpp: the recommended design, replayed through the general
// simulate() front door, reaches the target in the predicted T_p and stays in the band.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "selfalign/design/process_design.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/units.hpp"

using namespace selfalign;

namespace {
DesignRequest small_request() {
  DesignRequest q;  // 1 cm object, 10 cm travel, 2 mm stroke, 5-50 Hz, 0.2 m/s, 10 m/s^2
  q.acceleration_grid = 12;
  q.period_grid = 3;
  q.stroke_grid = 2;
  q.entries = 20;
  return q;
}

// First sample time from which the object stays within `band` of `target` until the end.
double settle_time(const Trajectory& tr, double target, double band) {
  double t = std::nan("");
  for (std::size_t i = 0; i < tr.size(); ++i) {
    const bool in = std::abs(tr.x[i] - target) <= band;
    if (in && std::isnan(t)) t = tr.t[i];
    if (!in) t = std::nan("");
  }
  return t;
}
}  // namespace

TEST(ProcessDesign, ReplayReachesTheTargetInThePredictedTimeAndStaysInTheBand) {
  for (double tolerance : {0.0, 2e-4}) {
    DesignRequest q = small_request();
    q.tolerance = tolerance;
    const DesignResult d = design_process(q);
    ASSERT_TRUE(d.feasible) << d.message;
    EXPECT_LE(d.velocity_peak, q.velocity_max * (1 + 1e-12));
    EXPECT_LE(std::max(d.a2, d.a3), q.acceleration_max * (1 + 1e-12));
    EXPECT_LE(d.stroke, q.stroke_max * (1 + 1e-12));
    EXPECT_GE(1 / d.period, q.frequency_min * (1 - 1e-12));
    EXPECT_LE(1 / d.period, q.frequency_max * (1 + 1e-12));
    if (tolerance == 0) EXPECT_EQ(d.stop, StopKind::accumulation);
    // Replay in model units (L = width) through simulate(), sampled at Δt/200.
    const Scales sc(q.width, q.mu, q.gravity);
    const ThreePhaseProfile profile(d.dimensionless);
    const FieldFriction friction = two_region_friction(d.x_mu_dimensionless, 1.0, q.c_mu);
    SimulationOptions o;
    o.duration = sc.time_from_si(d.process_time) + 20 * profile.period();
    o.output_step = profile.period() / 200;
    const SimulationResult run = simulate(profile, friction, {0, 0, 0}, o);
    const double t_in = settle_time(run.trajectory, sc.length_from_si(d.end_position),
                                    sc.length_from_si(d.error_band));
    ASSERT_FALSE(std::isnan(t_in)) << "never settled in the band";
    EXPECT_NEAR(t_in, sc.time_from_si(d.process_time), profile.period());  // within one period
    // The end position is the requested distance, within the band (+ accumulation's limit).
    EXPECT_NEAR(d.end_position, q.distance, d.error_band + 1e-12);
  }
}

TEST(ProcessDesign, InfeasibleRequestsNameTheBindingLimit) {
  DesignRequest q = small_request();
  q.acceleration_max = 2.0;  // below mu g = 2.943 m/s^2
  DesignResult d = design_process(q);
  EXPECT_FALSE(d.feasible);
  EXPECT_NE(d.message.find("acceleration_max"), std::string::npos) << d.message;
  q = small_request();
  q.velocity_max = 1e-4;
  d = design_process(q);
  EXPECT_FALSE(d.feasible);
  EXPECT_NE(d.message.find("exceed velocity_max"), std::string::npos) << d.message;
}

TEST(ProcessDesign, MisuseThrows) {
  DesignRequest q = small_request();
  q.width = -1;
  EXPECT_THROW(design_process(q), InvalidParameter);
  q = small_request();
  q.c_mu = 1.0;
  EXPECT_THROW(design_process(q), InvalidParameter);
  q = small_request();
  q.distance = std::nan("");
  EXPECT_THROW(design_process(q), InvalidParameter);
}

// D29: a coefficient not given is std::nullopt (static = kinetic), never NaN; a NaN given is
// refused naming it.
TEST(ProcessDesign, AbsentCoefficientsAreNoneAndNanIsRefused) {
  DesignRequest q = small_request();
  EXPECT_FALSE(q.mu_static.has_value());
  EXPECT_TRUE(friction_law(q).is_unit());
  q.mu_static = std::nan("");
  try {
    validate(q);
    FAIL() << "mu_static = nan accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "mu_static");
  }
  q = small_request();
  q.mu_backward = std::nan("");
  EXPECT_THROW(validate(q), InvalidParameter);
  q.mu_backward = 0.9 * q.mu;
  EXPECT_EQ(friction_law(q).kinetic_backward(), 0.9 * q.mu / q.mu);
}

TEST(ProcessDesign, PinnedLimitsNameTheGridEdgesAndTheDefaults) {
  // The grid point of the lowest frequency, the full stroke and the top accelerations sits on
  // frequency_min (5 Hz, the default), stroke_max (the default) and the top of the
  // acceleration axis: c_mu mu g = 7.3575 m/s^2 below acceleration_max = 10, else
  // acceleration_max. Indices: periods outermost, then strokes (largest first), y2'', y3''.
  DesignRequest q = small_request();
  q.frequency_min = 10, q.frequency_max = 12;  // slow enough to reach the stroke at the top
  for (double a_max : {10.0, 5.0}) {
    q.acceleration_max = a_max;
    const DesignGrid grid(q);
    const std::size_t a = static_cast<std::size_t>(q.acceleration_grid);
    const std::size_t top = (static_cast<std::size_t>(q.period_grid) - 1) *
                                static_cast<std::size_t>(q.stroke_grid) * a * a +
                            a * a - 1;
    ASSERT_EQ(grid.size(), top + static_cast<std::size_t>(q.stroke_grid - 1) * a * a + 1);
    const std::optional<ThreePhaseParameters> p = grid.at(top);
    ASSERT_TRUE(p.has_value());
    const std::vector<std::string> limits = grid.pinned_limits(*p);
    ASSERT_EQ(limits.size(), 3u);
    EXPECT_EQ(limits[0], "frequency at frequency_min = 10 Hz");
    EXPECT_EQ(limits[1], "stroke at stroke_max = 0.002 m (the default)");
    if (a_max == 10)
      EXPECT_EQ(limits[2].rfind("peak acceleration at the grid's top c_mu mu g = 7.3575 m/s^2", 0), 0u)
          << limits[2];
    else
      EXPECT_EQ(limits[2], "peak acceleration at acceleration_max = 5 m/s^2");
    // The highest frequency (period index 0), full stroke, top accelerations.
    const std::optional<ThreePhaseParameters> fast = grid.at(a * a - 1);
    ASSERT_TRUE(fast.has_value());
    EXPECT_EQ(grid.pinned_limits(*fast)[0], "frequency at frequency_max = 12 Hz");
  }
}

TEST(ProcessDesign, RefusesAGridBeyondItsWorkLimit) {
  // D36: the flags' largest grid, 200^2 x 100 x 20 x 1000 = 8e10 steady entries (more than 6.5 GB
  // as a list), is refused up front; 1e9 entries is the limit.
  DesignRequest q = small_request();
  q.acceleration_grid = 200, q.period_grid = 100, q.stroke_grid = 20, q.entries = 1000;
  try {
    design_process(q);
    ADD_FAILURE() << "no error";
  } catch (const InvalidParameter& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("8e+10"), std::string::npos) << what;
    EXPECT_NE(what.find("acceleration_grid^2 x period_grid x stroke_grid x entries"),
              std::string::npos) << what;
  }
}
