// Tests for analysis/period_map.hpp, the one period map every analysis uses: which solver it
// chooses, the map P against a period computed by hand, its runs against repeated maps, its
// two monodromy matrices against each other, and the time-stepping map against the exact one.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "opaque_profile.hpp"
#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

// y'' = +3 on [0, 1/2), -3 on [1/2, 1): the hand computation below.
PiecewisePolynomialProfile square_wave() {
  const double durations[] = {0.5, 0.5}, accels[] = {3.0, -3.0};
  return PiecewisePolynomialProfile::from_accelerations(durations, accels);
}

// The closed forms are evaluated in a handful of floating-point operations: a few ulps.
constexpr double kClosedFormTol = 1e-14;

// Run::jump_periods against the second method, advancing period by period: a case-1 walk on
// the uniform table repeats every period after its first stick, so jumping N - 2 periods with
// the last period's displacement lands where N periods of arcs do (to the rounding of the
// positions summed: 1e-12 relative over 50 periods), at the same time, bit for bit.
TEST(PeriodMap, JumpingPeriodsOfARepeatingWalkLandsWhereAdvancingDoes) {
  const ThreePhaseProfile profile({1.0, 0.084, 3.0, 0.9});
  const PeriodMap map(profile);
  const double t1 = profile.solution().t1;  // a switch: the look of a stopping run
  constexpr long long n = 50;
  PeriodMap::Run stepped = map.start({t1, 0, 0});
  for (long long k = 1; k <= n; ++k) stepped.advance_to(static_cast<double>(k) + t1);
  PeriodMap::Run jumped = map.start({t1, 0, 0});
  const double x1 = jumped.advance_to(1 + t1).x, x2 = jumped.advance_to(2 + t1).x;
  ASSERT_GT(x2 - x1, 0.0);
  ASSERT_TRUE(jumped.jump_periods(n - 2, static_cast<double>(n - 2) * (x2 - x1)));
  EXPECT_EQ(jumped.state().t, stepped.state().t);
  EXPECT_NEAR(jumped.state().x, stepped.state().x, 1e-12 * stepped.state().x);
  EXPECT_EQ(jumped.state().xd, 0.0);
  // and they go on alike
  EXPECT_NEAR(jumped.advance_to(n + 1 + t1).x, stepped.advance_to(n + 1 + t1).x,
              1e-12 * stepped.state().x);
  // not at a switch, or another method: refused, nothing changed
  PeriodMap::Run off = map.start({0.3, 0, 0});
  EXPECT_FALSE(off.jump_periods(5, 1.0));
  EXPECT_EQ(off.state().x, 0.0);
  PeriodMapOptions time_stepping;
  time_stepping.method = Method::time_stepping;
  const PeriodMap stepping(profile, FrictionLaw{}, time_stepping);
  PeriodMap::Run ts = stepping.start({t1, 0, 0});
  EXPECT_FALSE(ts.jump_periods(5, 1.0));
}

TEST(PeriodMap, ChoosesTheSolverTheProfileAndLawAllow) {
  const PiecewisePolynomialProfile square = square_wave();
  const FourierProfile fourier(1.0, {0.01}, {0.02});
  const testing_support::Opaque opaque(square);
  const FrictionLaw stribeck = FrictionLaw(1.2, 1.0).with_stribeck(0.1);
  EXPECT_EQ(PeriodMap(square).method(), Method::exact);
  EXPECT_TRUE(PeriodMap(square).has_arcs());
  EXPECT_EQ(PeriodMap(fourier).method(), Method::exact);  // smooth exact on a uniform level
  EXPECT_EQ(PeriodMap(square, stribeck).method(), Method::integrator);
  EXPECT_FALSE(PeriodMap(square, stribeck).has_arcs());
  EXPECT_EQ(PeriodMap(opaque).method(), Method::time_stepping);
  EXPECT_GT(PeriodMap(opaque).step(), 0.0);
  EXPECT_EQ(PeriodMap(square).step(), 0.0);
}

TEST(PeriodMap, OnePeriodFromRestIsTheHandComputedOne) {
  // Uniform m = 1, Coulomb law s = k = 1, x'' = -sigma - y'' while slipping (eqs. 15, 18).
  // [0, 1/2):  y'' = 3 > 1: slip backward (sigma = -1), x'' = 1 - 3 = -2:
  //            x'(1/2) = -1, x(1/2) = -1/4.
  // [1/2, 1):  still backward, x'' = 1 + 3 = 4: x' = 0 at tau = 1/4 (t = 3/4),
  //            x(3/4) = -1/4 - 1/4 + 2 (1/4)^2 = -3/8.
  //            At rest, -y'' = 3 > 1: slip forward, x'' = -1 + 3 = 2 over 1/4:
  //            x'(1) = 1/2, x(1) = -3/8 + (1/4)^2 = -5/16.
  const PiecewisePolynomialProfile square = square_wave();
  const PeriodMap map(square);
  const ObjectState end = map(0.0, 0.0);
  EXPECT_NEAR(end.t, 1.0, kClosedFormTol);
  EXPECT_NEAR(end.x, -5.0 / 16, kClosedFormTol);
  EXPECT_NEAR(end.xd, 0.5, kClosedFormTol);
  // Its arcs: backward slip to the switch, backward slip to the stop, forward slip to the end;
  // contiguous, and the last ends where the map does.
  const std::vector<Arc> arcs = map.arcs(0.0, 0.0);
  ASSERT_EQ(arcs.size(), 3u);
  EXPECT_EQ(arcs[0].direction, -1);
  EXPECT_EQ(arcs[1].direction, -1);
  EXPECT_EQ(arcs[1].end, ArcEnd::velocity_zero);
  EXPECT_NEAR(arcs[1].t1, 0.75, kClosedFormTol);
  EXPECT_EQ(arcs[2].direction, 1);
  for (std::size_t i = 1; i < arcs.size(); ++i) {
    EXPECT_EQ(arcs[i].t0, arcs[i - 1].t1);
    EXPECT_EQ(arcs[i].x0, arcs[i - 1].x1);
  }
  EXPECT_EQ(arcs.back().x1, end.x);
  EXPECT_EQ(arcs.back().xd1, end.xd);
}

TEST(PeriodMap, ARunIsTheMapRepeated) {
  // Across periods a run continues where the last period ended; the map restarts at phase 0
  // from the state it is given. The two agree to rounding (the run's times are n + phase).
  const ThreePhaseProfile profile({1.0, 0.084, 1.8, 1.1});  // case 3, stick-slip
  const PeriodMap map(profile);
  PeriodMap::Run run = map.start({0.0, 0.2, -0.1});
  double x = 0.2, v = -0.1;
  for (int n = 1; n <= 5; ++n) {
    const ObjectState mapped = map(x, v);
    const ObjectState& ran = run.advance_to(n * profile.period());
    x = mapped.x;
    v = mapped.xd;
    EXPECT_NEAR(ran.x, x, 1e-12 * (1 + std::abs(x))) << n;
    EXPECT_NEAR(ran.xd, v, 1e-12) << n;
  }
}

TEST(PeriodMap, SaltationMonodromyAgreesWithFiniteDifferences) {
  // Two independent methods: the arcs' transition matrices coupled by saltation matrices
  // against central differences of the map (truncation O(h^2) = 1e-12 for h = 1e-6, rounding
  // O(eps/h) ~ 1e-10 times the map's scale). Points in slip (no stick in the period, so the
  // map is smooth around them) on the square wave and on the paper's case-4 profile.
  const PiecewisePolynomialProfile square = square_wave();
  const ThreePhaseProfile slip_slip({1.0, 0.084, 1.05, 2.0});
  constexpr double kFdTol = 1e-7;
  for (const TableProfile* p : {static_cast<const TableProfile*>(&square),
                                static_cast<const TableProfile*>(&slip_slip)}) {
    const PeriodMap map(*p);
    for (const auto& [x0, v0] : {std::pair{0.0, 0.3}, std::pair{0.1, -0.4}}) {
      const Eigen::Matrix2d s = map.saltation_monodromy(x0, v0);
      const Eigen::Matrix2d fd = map.finite_difference_monodromy(x0, v0, 1e-6);
      EXPECT_LT((s - fd).cwiseAbs().maxCoeff(), kFdTol) << p->kind() << " " << x0 << ", " << v0
                                                        << "\n" << s << "\n" << fd;
    }
  }
}

TEST(PeriodMap, TimeSteppingConvergesToTheExactMap) {
  // The same profile hidden from the exact solver: Moreau's map, first order in h. The
  // switch at 0.37 and the start in slip put the events off the step grid (on the grid,
  // Moreau is exact for piecewise-constant accelerations and the test could not fail).
  const double durations[] = {0.37, 0.63}, accels[] = {3.0, -3.0 * 0.37 / 0.63};
  const auto profile = PiecewisePolynomialProfile::from_accelerations(durations, accels);
  const testing_support::Opaque opaque(profile);
  PeriodMapOptions coarse, fine;
  coarse.steps_per_period = 1000;
  fine.steps_per_period = 10000;
  const ObjectState exact = PeriodMap(profile)(0.0, 0.123);
  const double e_coarse =
      std::abs(PeriodMap(opaque, FrictionLaw{}, coarse)(0.0, 0.123).x - exact.x);
  const double e_fine = std::abs(PeriodMap(opaque, FrictionLaw{}, fine)(0.0, 0.123).x - exact.x);
  EXPECT_LT(e_coarse, 10.0 / coarse.steps_per_period);
  EXPECT_GT(e_coarse, 1e-3 / coarse.steps_per_period);  // not exact by accident
  EXPECT_LT(e_fine, e_coarse / 4);  // order about one: a tenth of the step, about a tenth
}

// Every piece, in order, of one period: contiguous, and ending where the map ends.
struct Pieces final : MotionObserver {
  std::vector<MotionInterval> pieces;
  int with_arc = 0;
  void on_motion(const MotionInterval& piece, const Arc* arc) override {
    pieces.push_back(piece);
    if (arc) {
      ++with_arc;
      EXPECT_EQ(static_cast<const MotionInterval*>(arc), &piece) << "the piece is the arc";
    }
  }
  void expect_chain(double x0, double v0, const ObjectState& end) const {
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front().t0, 0.0);
    EXPECT_EQ(pieces.front().x0, x0);
    EXPECT_EQ(pieces.front().xd0, v0);
    for (std::size_t i = 1; i < pieces.size(); ++i) {
      EXPECT_EQ(pieces[i].x0, pieces[i - 1].x1) << i;
      EXPECT_EQ(pieces[i].xd0, pieces[i - 1].xd1) << i;
    }
    EXPECT_EQ(pieces.back().x1, end.x);
    EXPECT_EQ(pieces.back().xd1, end.xd);
  }
};

// The one observer hears every stepper: the exact map's arcs (with their closed form), the
// integrator's intervals and time-stepping's steps (without). A sink given to a time-stepping
// map was refused before (it only took arcs); arcs() still needs a closed form.
TEST(PeriodMap, EveryStepperFeedsTheOneObserver) {
  const PiecewisePolynomialProfile square = square_wave();
  const testing_support::Opaque opaque(square);
  const PeriodMap exact(square), stepping(opaque);
  const PeriodMap integrated(square, FrictionLaw(1.2, 1.0).with_stribeck(0.1));
  Pieces e, s, i;
  e.expect_chain(0.0, 0.1, exact(0.0, 0.1, &e));
  s.expect_chain(0.0, 0.1, stepping(0.0, 0.1, &s));
  i.expect_chain(0.0, 0.1, integrated(0.0, 0.1, &i));
  EXPECT_EQ(e.with_arc, static_cast<int>(e.pieces.size()));
  EXPECT_EQ(s.with_arc, 0);
  EXPECT_EQ(i.with_arc, 0);
  EXPECT_EQ(s.pieces.size(), 4000u);  // PeriodMapOptions::steps_per_period
  for (const MotionInterval& p : s.pieces) EXPECT_EQ(p.end, ArcEnd::time_step);
  EXPECT_THROW(stepping.arcs(0.0, 0.0), InvalidParameter);
  // Second method: the farthest point of the period, exact against Moreau's first-order steps
  // (h = 1/4000; the position error of the scheme is O(h), a few h here).
  Reach exact_reach, stepping_reach;
  exact(0.0, 0.1, &exact_reach);
  stepping(0.0, 0.1, &stepping_reach);
  EXPECT_NEAR(stepping_reach.x, exact_reach.x, 10.0 / 4000);
  // The census from time steps sees the exact map's stick/slip pattern.
  MotionCensus exact_census, stepping_census;
  exact(0.0, 0.0, nullptr, &exact_census);
  stepping(0.0, 0.0, nullptr, &stepping_census);
  EXPECT_NE(exact_census.sequence.find('+'), std::string::npos);  // |y''| = 3 > 1: it slips
  EXPECT_EQ(stepping_census.sequence, exact_census.sequence);
}

}  // namespace
}  // namespace selfalign
