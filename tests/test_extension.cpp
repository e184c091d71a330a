// The extension test: a new friction level and a new profile family, written here and nowhere
// in the library, run through steady state, Floquet, stopping and a sweep without editing a
// library source. Each result is checked against a second method: the exact solver against
// time-stepping (the same profile behind an opaque wrapper, so only the stepper can take it),
// saltation against finite differences, the stop against eq. (40) under the law.
#include <gtest/gtest.h>

#include "selfalign/special_values.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "opaque_profile.hpp"
#include "selfalign/analysis/floquet.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

using namespace selfalign;
using testing_support::Opaque;

namespace {


// A terraced table: the level climbs in two steps, each spread over `ramp` (a point contact on
// a table with two chamfered steps): 1 -> 1.5 over [x1, x1 + ramp], 1.5 -> 8 over
// [x2, x2 + ramp].
class TerracedFriction final : public FrictionMap {
 public:
  TerracedFriction(double x1, double x2, double ramp) : affine_(make(x1, x2, ramp)) {}
  double bound(double x) const override { return affine_.bound(x); }
  const PiecewiseAffineFriction* piecewise_affine() const override { return &affine_; }

 private:
  static PiecewiseAffineFriction make(double x1, double x2, double r) {
    const AffinePiece p[5] = {{-kInf, x1, 1.0, 0.0},
                              {x1, x1 + r, 1.0, 0.5 / r},
                              {x1 + r, x2, 1.5, 0.0},
                              {x2, x2 + r, 1.5, 6.5 / r},
                              {x2 + r, kInf, 8.0, 0.0}};
    return PiecewiseAffineFriction(p);
  }
  PiecewiseAffineFriction affine_;
};

// An S-curve family: y'' rises linearly to -a, holds, swings linearly to +b and back to 0,
// with a rest at the start; the swing lasts a fixed fraction of the period. Accelerations scale
// with Δy / Δt^2 like ScaledShapeFamily, but the family is built from breakpoints.
class SCurveFamily final : public ProfileFamily {
 public:
  std::unique_ptr<TableProfile> make(double period, double stroke) const override {
    // Unit shape on [0, 1]: rest on [0, .3], ramp to -c at .4, hold to .55, ramp to +1 at
    // .75, hold to .85, ramp back to 0 at 1. Net velocity change (trapezoids):
    //   -0.05 c - 0.15 c + 0.1 (1 - c) + 0.1 + 0.075 = 0.275 - 0.3 c = 0  ->  c = 11/12.
    const double t[6] = {0, 0.3, 0.4, 0.55, 0.75, 0.85};
    const double c = 0.275 / 0.3;
    const double a_bal[6] = {0, 0, -c, -c, 1, 1};
    auto unit = PiecewisePolynomialProfile::from_breakpoints(t, a_bal, 1.0, "s-curve");
    const double accel_scale = stroke / unit.stroke() / (period * period);
    std::vector<double> tt(6), aa(6);
    for (int i = 0; i < 6; ++i) tt[i] = t[i] * period, aa[i] = a_bal[i] * accel_scale;
    return std::make_unique<PiecewisePolynomialProfile>(
        PiecewisePolynomialProfile::from_breakpoints(tt, aa, period, "s-curve"));
  }
  std::string name() const override { return "s-curve"; }
};


}  // namespace

TEST(Extension, NewProfileFamilyRunsThroughSteadyStateFloquetAndASweep) {
  const SCurveFamily family;
  const auto profile = family.make(2.0, 0.5);
  const FrictionLaw law(1.25, 1.0);
  // Steady state: exact vs time-stepping (h = Δt/20000; first order: agreement to ~10 h).
  const SteadyState exact = steady_state(*profile, law);
  const Opaque hidden(*profile);
  SteadyStateOptions o;
  o.steps_per_period = 20000;
  const SteadyState stepped = steady_state(hidden, law, o);
  ASSERT_EQ(exact.method, Method::exact);
  ASSERT_EQ(stepped.method, Method::time_stepping);
  EXPECT_GT(std::abs(exact.v_bar), 1e-3);  // it moves the part
  EXPECT_NEAR(exact.v_bar, stepped.v_bar, 10 * 2.0 / 20000);
  // Floquet: saltation against finite differences of the same map.
  const PeriodMap map(*profile, law);
  const FloquetAnalysis f = floquet_multipliers(map);
  EXPECT_LE(f.spread, 1e-6) << exact.pattern;
  // A sweep over the period: each point equals the member's own steady state, and a member
  // of a new family needs no library edit to be swept.
  SweepOptions so;
  so.law = law;
  so.threads = 1;
  const std::vector<double> periods{1.5, 2.0, 2.5};
  const auto pts = sweep_period(family, 0.5, periods, so);
  ASSERT_EQ(pts.size(), 3u);
  for (const FamilyPoint& pt : pts) {
    EXPECT_TRUE(pt.failure.empty()) << pt.failure;
    const auto member = family.make(pt.period, 0.5);
    const SteadyState ts = steady_state(Opaque(*member), law, o);
    EXPECT_NEAR(pt.v_bar, ts.v_bar, 10 * pt.period / 20000) << pt.period;
  }
}

TEST(Extension, NewFrictionLevelStopsThePartWhereTheStaticLawHoldsIt) {
  const SCurveFamily family;
  const auto profile = family.make(2.0, 1.0);  // peak 6.6: it climbs the first terrace
  const double peak = profile->peak_acceleration();
  const TerracedFriction terraced(0.5, 1.0, 0.05);
  for (const FrictionLaw& law : {FrictionLaw{}, FrictionLaw(1.25, 1.0)}) {
    StoppingOptions o;
    o.max_periods = 2000;
    const StoppingRun run = stopping_run(*profile, terraced, law, {0, 0, 0}, o);
    ASSERT_EQ(run.kind, StopKind::permanent_stick)
        << law.describe() << " x_stick_min " << run.x_stick_min << " entry " << run.entry_time
        << " stops " << run.stick_positions.size() << " last "
        << (run.stick_positions.empty() ? -1.0 : run.stick_positions.back()) << " peak " << peak;
    // Eq. (40) under the law holds where it stopped, and x_stick,min is where the terraced
    // level first holds the peak for good: s m(x) = peak on a ramp, solved by hand here.
    EXPECT_GE(law.static_coefficient() * terraced.bound(run.end_position), peak);
    EXPECT_GE(run.end_position, run.x_stick_min);
    const double s = law.static_coefficient(), level = peak / s;
    const double expected = level <= 1     ? 0.5
                            : level <= 1.5 ? 0.5 + 0.05 * (level - 1) / 0.5
                            : level <= 8   ? 1.0 + 0.05 * (level - 1.5) / 6.5
                                           : kInf;
    EXPECT_NEAR(run.x_stick_min, expected, 1e-14) << law.describe();
    // Time-stepping (a second method) stops it at the same place to O(h).
    const Opaque hidden(*profile);
    SimulationOptions so;
    so.method = Method::time_stepping;
    so.step = 1e-4;
    so.duration = 2.0 * 400;
    so.record = false;
    const SimulationResult r = simulate(hidden, terraced, law, {0, 0, 0}, so);
    ASSERT_LT(run.process_time, 0.9 * so.duration);  // the stepper has time to stop it too
    EXPECT_NEAR(r.final_state.x, run.end_position, 1e-2) << law.describe();
  }
}
