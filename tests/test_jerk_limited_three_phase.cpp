// Tests for profiles/jerk_limited_three_phase.hpp (docs/jerk-limited-three-phase.md).
// Expected values come from hand integration of the six phases written out here, from the
// generic PiecewisePolynomialProfile built from hand-written durations, from ThreePhaseProfile,
// or from the hand-computed cases of the docs (exact rationals) -- never from the solver.
#include <gtest/gtest.h>

#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/three_phase.hpp"

using namespace selfalign;

namespace {
using Params = JerkLimitedThreePhaseParameters;
using Solution = JerkLimitedThreePhaseSolution;

struct Integrated {
  double y_end, yd_end, y_min, y_max, mean_velocity;
};

// Integrates the six phases y'' = 0, 0 -> -a2, -a2, -a2 -> a3, a3, a3 -> 0 (durations from the
// solution) from y = 0, y' = yd_ini with exact cubics, and finds the extrema of y where y' = 0.
Integrated integrate(const Params& p, const Solution& r) {
  const double a = p.a2, b = p.a3;
  const auto d = r.durations();
  const double acc0[6] = {0, 0, -a, -a, b, b}, acc1[6] = {0, -a, -a, b, b, 0};
  double y = 0, yd = r.yd_ini, y_min = 0, y_max = 0, area = 0, T = 0;
  auto y_at = [](double y0, double v0, double a0, double jj, double t) {
    return y0 + v0 * t + a0 * t * t / 2 + jj * t * t * t / 6;
  };
  for (int i = 0; i < 6; ++i) {
    if (d[i] == 0) continue;
    const double jj = (acc1[i] - acc0[i]) / d[i];
    // roots of y' = yd + acc0 t + jj t^2/2 on (0, d)
    std::vector<double> roots;
    if (jj == 0) {
      if (acc0[i] != 0) roots.push_back(-yd / acc0[i]);
    } else {
      const double disc = acc0[i] * acc0[i] - 2 * jj * yd;
      if (disc >= 0) {
        roots.push_back((-acc0[i] + std::sqrt(disc)) / jj);
        roots.push_back((-acc0[i] - std::sqrt(disc)) / jj);
      }
    }
    for (double t : roots)
      if (t > 0 && t < d[i]) {
        y_min = std::min(y_min, y_at(y, yd, acc0[i], jj, t));
        y_max = std::max(y_max, y_at(y, yd, acc0[i], jj, t));
      }
    const double t = d[i];
    const double y_next = y_at(y, yd, acc0[i], jj, t);
    area += y_next - y;
    yd += acc0[i] * t + jj * t * t / 2;
    y = y_next;
    T += t;
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  }
  return {y, yd, y_min, y_max, area / T};
}

// The profile with velocity swing D written out from eqs. (J2), (J3) of the docs, built and
// normalised by the generic PiecewisePolynomialProfile (which computes its own stroke).
double generic_stroke(const Params& p, double D) {
  const double a = p.a2, b = p.a3, j = p.jerk;
  const double d[6] = {p.period - D / a - D / b - (a + b) / j,
                       a / j,
                       D / a - a / j,
                       (a + b) / j,
                       D / b - b / j,
                       b / j};
  const double acc0[6] = {0, 0, -a, -a, b, b}, acc1[6] = {0, -a, -a, b, b, 0};
  double dd[6];
  for (int i = 0; i < 6; ++i) dd[i] = std::max(0.0, d[i]);
  return PiecewisePolynomialProfile::from_linear_accelerations(dd, acc0, acc1).stroke();
}

double sum(const std::array<double, 6>& d) {
  double t = 0;
  for (double x : d) t += x;
  return t;
}
}  // namespace

// The constraints hold on a grid of (a2, a3, jerk, stroke), checked by hand integration and by
// the generic profile; case 0 is confirmed by an independent criterion: a profile exists iff
// the ramps fit (the D_min and D_max profiles exist) and the stroke lies between the strokes
// of those two extreme profiles (monotone in D, docs eq. J12), computed by the generic builder.
TEST(JerkLimitedThreePhase, MeetsAllConstraintsOnTheGridAndReportsCaseZero) {
  const double dt = 1.0;
  int physical = 0, case0 = 0, closed = 0, bisected = 0;
  for (double dy : {0.084, 0.01, 0.001}) {
    for (double jerk : {3.0, 8.0, 30.0, 100.0, 1e3, 1e5}) {
      for (int i = 0; i <= 18; ++i) {
        for (int k = 0; k <= 18; ++k) {
          const Params p{dt, dy, 0.2 * std::pow(50.0, i / 18.0), 0.2 * std::pow(50.0, k / 18.0),
                         jerk};
          SCOPED_TRACE(::testing::Message()
                       << "dy " << dy << " j " << jerk << " a2 " << p.a2 << " a3 " << p.a3);
          const Solution r = solve_jerk_limited_three_phase(p);
          // Independent criterion.
          const double a = p.a2, b = p.a3, m = std::max(a, b), s = 1 / a + 1 / b;
          const double D_min = m * m / jerk, D_max = (dt - (a + b) / jerk) / s;
          bool expected = false, near_boundary = false;
          if (D_min <= D_max * (1 - 1e-9)) {
            const double lo = generic_stroke(p, D_min), hi = generic_stroke(p, D_max);
            expected = lo <= dy && dy <= hi;
            near_boundary = std::abs(lo - dy) < 1e-9 * dy || std::abs(hi - dy) < 1e-9 * dy;
          } else {
            near_boundary = D_min <= D_max * (1 + 1e-9);
          }
          if (!near_boundary) {
            EXPECT_EQ(r.physical, expected);
            // min_jerk agrees: physical iff jerk >= min_jerk.
            EXPECT_EQ(r.physical, jerk >= r.min_jerk);
          }
          if (!r.physical) {
            ++case0;
            EXPECT_NE(r.reason, JerkLimitedCase0::none);
            EXPECT_THROW(JerkLimitedThreePhaseProfile{p}, InvalidParameter);
            continue;
          }
          ++physical;
          (r.closed_form ? closed : bisected)++;
          EXPECT_EQ(r.reason, JerkLimitedCase0::none);
          for (double x : r.durations()) EXPECT_GE(x, 0.0);
          EXPECT_NEAR(sum(r.durations()), dt, 1e-14);
          EXPECT_EQ(r.ramp_down, a / jerk);
          EXPECT_NEAR(r.ramp_up, (a + b) / jerk, 1e-15 * (a + b) / jerk);
          EXPECT_EQ(r.ramp_end, b / jerk);
          const Integrated g = integrate(p, r);
          const double D = r.velocity_swing;
          EXPECT_NEAR(g.yd_end, r.yd_ini, 1e-13 * D);    // velocity returns
          EXPECT_NEAR(g.mean_velocity, 0.0, 1e-13 * D);  // position returns
          EXPECT_NEAR(g.y_end, 0.0, 1e-13 * D);
          EXPECT_NEAR(g.y_max - g.y_min, dy, 1e-12 * dy);  // stroke, by hand
          // The built profile: its own stroke, initial velocity and plateau accelerations.
          const JerkLimitedThreePhaseProfile profile(p);
          EXPECT_NEAR(profile.stroke(), dy, 1e-12 * dy);
          EXPECT_NEAR(profile.state(0).yd, r.yd_ini, 1e-13 * D);
          EXPECT_NEAR(profile.state(0).y, -g.y_min, 1e-12 * dy);  // min y = 0
          EXPECT_EQ(profile.state(0.5 * r.hold0).ydd, 0.0);       // y'' = 0 phase kept
          // Velocity swing: both plateau branches lose / regain D (eq. J1).
          EXPECT_NEAR(a * (r.hold2 + a / jerk), D, 1e-13 * D);
          EXPECT_NEAR(b * (r.hold3 + b / jerk), D, 1e-13 * D);
        }
      }
    }
  }
  EXPECT_GT(physical, 1000);
  EXPECT_GT(case0, 1000);
  EXPECT_GT(closed, 500);
  EXPECT_GT(bisected, 50);
}

// Every ramp lasts Δa/j with jerk ∓j, the plateaus have jerk 0, and y'' = 0 on [0, T1].
TEST(JerkLimitedThreePhase, RampsLastDeltaAOverJerk) {
  const Params p{1.05, 0.084, 2.2, 0.9, 40.0};  // the paper's Fig. 18 setting, jerk 40
  const JerkLimitedThreePhaseProfile profile(p);
  const auto segs = profile.piecewise_polynomial()->segments();
  ASSERT_EQ(segs.size(), 6u);
  const double j = p.jerk, a = p.a2, b = p.a3;
  const double expect_accel[6] = {0, 0, -a, -a, b, b}, expect_end[6] = {0, -a, -a, b, b, 0};
  const double expect_jerk[6] = {0, -j, 0, j, 0, -j};
  for (int i = 0; i < 6; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(segs[i].accel, expect_accel[i]);
    EXPECT_NEAR(segs[i].end_accel(), expect_end[i], 1e-14);
    EXPECT_NEAR(segs[i].jerk, expect_jerk[i], 1e-13 * j);
  }
  EXPECT_EQ(segs[1].duration, a / j);
  EXPECT_NEAR(segs[3].duration, (a + b) / j, 1e-16);
  EXPECT_EQ(segs[5].duration, b / j);
  EXPECT_NEAR(profile.piecewise_polynomial()->peak_jerk(), j, 1e-13 * j);
  EXPECT_EQ(profile.peak_acceleration(), std::max(a, b));
  EXPECT_FALSE(profile.piecewise_polynomial()->piecewise_constant());
  for (double t : {0.0, 0.25 * segs[1].begin, 0.999 * segs[1].begin})
    EXPECT_EQ(profile.state(t).ydd, 0.0);
  // Inside the ramps y'' is the straight line between the plateaus.
  const double mid = segs[3].begin + 0.5 * segs[3].duration;
  EXPECT_NEAR(profile.state(mid).ydd, 0.5 * (b - a), 1e-13);
}

TEST(JerkLimitedThreePhase, InfiniteJerkIsTheJumpProfileBitForBit) {
  for (const ThreePhaseParameters& q :
       {ThreePhaseParameters{1.05, 0.084, 2.2, 0.9}, ThreePhaseParameters{1.0, 0.084, 3.0, 3.0},
        ThreePhaseParameters{1e5, 0.084, 1e-6, 2e-6},
        ThreePhaseParameters{0.3975711110065985, 5.5655136158781754e-05, 0.01, 7.0}}) {
    const ThreePhaseProfile jump(q);
    const JerkLimitedThreePhaseProfile limited({q.period, q.stroke, q.a2, q.a3, kInf});
    EXPECT_TRUE(limited.solution().closed_form);
    const auto s1 = jump.piecewise_polynomial()->segments();
    const auto s2 = limited.piecewise_polynomial()->segments();
    ASSERT_EQ(s1.size(), s2.size());  // zero-length ramps dropped
    for (std::size_t i = 0; i < s1.size(); ++i) {
      EXPECT_EQ(s1[i].begin, s2[i].begin);
      EXPECT_EQ(s1[i].duration, s2[i].duration);
      EXPECT_EQ(s1[i].accel, s2[i].accel);
      EXPECT_EQ(s1[i].y, s2[i].y);
      EXPECT_EQ(s1[i].yd, s2[i].yd);
      EXPECT_EQ(s1[i].jerk, s2[i].jerk);
    }
    EXPECT_EQ(limited.stroke(), jump.stroke());
    EXPECT_EQ(limited.solution().hold0, jump.solution().t1);
    EXPECT_EQ(limited.solution().yd_ini, jump.solution().yd_ini);
  }
}

// docs eq. (J17): T1 = t1 - (a2+a3)/(2j) + O(1/j^2), start of the up-ramp = t2 - (a2+2a3)/(2j),
// D = D0 - a2 a3/(2j), with (t1, t2, D0) of ThreePhaseProfile. Observed over 3 decades.
TEST(JerkLimitedThreePhase, ApproachesThreePhaseAsOneOverJerk) {
  for (const ThreePhaseParameters& q :
       {ThreePhaseParameters{1.05, 0.084, 2.2, 0.9}, ThreePhaseParameters{1.0, 0.05, 1.0, 1.0},
        ThreePhaseParameters{2.0, 0.1, 0.7, 4.0}}) {
    SCOPED_TRACE(::testing::Message() << "a2 " << q.a2 << " a3 " << q.a3);
    const ThreePhaseSolution r0 = solve_three_phase(q);
    ASSERT_TRUE(r0.physical);
    const double a = q.a2, b = q.a3;
    const double c1 = -(a + b) / 2, c2 = -(a + 2 * b) / 2, cD = -a * b / 2;  // first order
    double prev_err1 = 0, prev_res1 = 0;
    for (double j : {1e3, 1e4, 1e5, 1e6}) {
      const Solution r = solve_jerk_limited_three_phase({q.period, q.stroke, a, b, j});
      ASSERT_TRUE(r.physical);
      EXPECT_TRUE(r.closed_form);
      const double t1 = r.hold0, t2 = r.hold0 + r.ramp_down + r.hold2;
      const double err1 = t1 - r0.t1, err2 = t2 - r0.t2,
                   errD = r.velocity_swing - r0.velocity_swing;
      // first-order coefficient, to O(1/j)
      EXPECT_NEAR(err1 * j, c1, 200 / j);
      EXPECT_NEAR(err2 * j, c2, 200 / j);
      EXPECT_NEAR(errD * j, cD, 200 / j);
      if (prev_err1 != 0) {
        // O(1/j): the error falls tenfold per decade; the remainder a hundredfold (to rounding).
        EXPECT_NEAR(prev_err1 / err1, 10.0, 0.2);
        const double res1 = err1 - c1 / j;
        if (std::abs(res1) > 1e-13) {
          EXPECT_NEAR(prev_res1 / res1, 100.0, 10.0);
        }
      }
      prev_err1 = err1;
      prev_res1 = err1 - c1 / j;
    }
  }
}

// The hand-computed cases of docs Sect. "Hand-computed cases" (exact rationals).
TEST(JerkLimitedThreePhase, HandComputedCases) {
  {  // (H1) a2 = a3 = 1, j = 4, Δt = 2, Δy = 131/768: plateau crossings, closed form.
    const Solution r = solve_jerk_limited_three_phase({2.0, 131.0 / 768, 1, 1, 4});
    ASSERT_TRUE(r.physical);
    EXPECT_TRUE(r.closed_form);
    EXPECT_NEAR(r.velocity_swing, 0.5, 1e-15);
    EXPECT_NEAR(r.hold0, 0.5, 1e-15);
    EXPECT_NEAR(r.hold2, 0.25, 1e-15);
    EXPECT_NEAR(r.hold3, 0.25, 1e-15);
    EXPECT_EQ(r.ramp_down, 0.25);
    EXPECT_EQ(r.ramp_up, 0.5);
    EXPECT_EQ(r.ramp_end, 0.25);
    EXPECT_NEAR(r.yd_ini, 3.0 / 16, 1e-15);
  }
  {  // (H2) same, Δt = 6, Δy = 9/32 + sqrt(2)/96: crossings on the ramps, bisection.
    const Solution r =
        solve_jerk_limited_three_phase({6.0, 9.0 / 32 + std::sqrt(2.0) / 96, 1, 1, 4});
    ASSERT_TRUE(r.physical);
    EXPECT_FALSE(r.closed_form);
    EXPECT_NEAR(r.velocity_swing, 0.5, 1e-14);
    EXPECT_NEAR(r.hold0, 4.5, 1e-14);
    EXPECT_NEAR(r.hold2, 0.25, 1e-14);
    EXPECT_NEAR(r.yd_ini, 1.0 / 16, 1e-15);
  }
  {  // (H3) a2 = 2, a3 = 1, j = 4, Δt = 5, Δy = 207/128: asymmetric, closed form.
    const Solution r = solve_jerk_limited_three_phase({5.0, 207.0 / 128, 2, 1, 4});
    ASSERT_TRUE(r.physical);
    EXPECT_TRUE(r.closed_form);
    EXPECT_NEAR(r.velocity_swing, 2.0, 1e-14);
    EXPECT_NEAR(r.hold0, 1.25, 1e-14);
    EXPECT_NEAR(r.hold2, 0.5, 1e-14);
    EXPECT_NEAR(r.hold3, 1.75, 1e-14);
    EXPECT_EQ(r.ramp_down, 0.5);
    EXPECT_EQ(r.ramp_up, 0.75);
    EXPECT_EQ(r.ramp_end, 0.25);
    EXPECT_NEAR(r.yd_ini, 0.75, 1e-15);
    const JerkLimitedThreePhaseProfile profile({5.0, 207.0 / 128, 2, 1, 4});
    EXPECT_NEAR(profile.stroke(), 207.0 / 128, 1e-14);
    EXPECT_NEAR(profile.state(0).yd, 0.75, 1e-15);
  }
}

// docs (H4)-(H6): the three kinds of boundary, each with a hand-computed smallest jerk.
TEST(JerkLimitedThreePhase, CaseZeroBoundariesAtTheSmallestJerk) {
  struct Edge {
    double stroke, j_min;
    JerkLimitedCase0 below;
  };
  // Δt = 1, a2 = a3 = 1 (S_max(∞) = 1/16, j_p = 4):
  const Edge edges[] = {
      {37.0 / 600, 20.0, JerkLimitedCase0::stroke_too_large},   // (H4) S_max(20) = Δy
      {19.0 / 3072, 16.0, JerkLimitedCase0::stroke_too_small},  // (H5) S_min(16) = Δy
      {1.0 / 24, 4.0, JerkLimitedCase0::ramps_exceed_period},   // (H6) all holds vanish at 4
  };
  for (const Edge& e : edges) {
    SCOPED_TRACE(::testing::Message() << "stroke " << e.stroke);
    const Solution at = solve_jerk_limited_three_phase({1.0, e.stroke, 1, 1, 2.0});
    EXPECT_FALSE(at.physical);
    EXPECT_NEAR(at.min_jerk, e.j_min, 1e-12 * e.j_min);
    const Solution above =
        solve_jerk_limited_three_phase({1.0, e.stroke, 1, 1, e.j_min * (1 + 1e-9)});
    ASSERT_TRUE(above.physical);
    const Solution below =
        solve_jerk_limited_three_phase({1.0, e.stroke, 1, 1, e.j_min * (1 - 1e-9)});
    EXPECT_FALSE(below.physical);
    EXPECT_EQ(below.reason, e.below);
    const JerkLimitedThreePhaseProfile profile({1.0, e.stroke, 1, 1, e.j_min * (1 + 1e-9)});
    EXPECT_NEAR(profile.stroke(), e.stroke, 1e-12 * e.stroke);
    // What vanishes at the boundary: T1 (stroke too large), the plateaus (stroke too small),
    // everything but the ramps (ramps exceed the period).
    if (e.below != JerkLimitedCase0::stroke_too_small) {
      EXPECT_NEAR(above.hold0, 0.0, 1e-7);
    }
    if (e.below != JerkLimitedCase0::stroke_too_large) {
      EXPECT_NEAR(above.hold2, 0.0, 1e-7);
      EXPECT_NEAR(above.hold3, 0.0, 1e-7);
    }
  }
  // Accelerations too low for any jerk (Δy > 1/16), and jumps only (Δy = 1/16 exactly).
  for (double j : {10.0, 1e6, kInf}) {
    const Solution r = solve_jerk_limited_three_phase({1.0, 0.07, 1, 1, j});
    EXPECT_FALSE(r.physical);
    EXPECT_EQ(r.reason, JerkLimitedCase0::accelerations_too_low);
    EXPECT_EQ(r.min_jerk, kInf);
  }
  EXPECT_TRUE(solve_jerk_limited_three_phase({1.0, 1.0 / 16, 1, 1, kInf}).physical);
  const Solution jumps_only = solve_jerk_limited_three_phase({1.0, 1.0 / 16, 1, 1, 1e12});
  EXPECT_FALSE(jumps_only.physical);
  EXPECT_EQ(jumps_only.reason, JerkLimitedCase0::stroke_too_large);
  EXPECT_EQ(jumps_only.min_jerk, kInf);
}

TEST(JerkLimitedThreePhase, ConstructorNamesJerkAndItsSmallestValueOnOneLine) {
  try {
    JerkLimitedThreePhaseProfile({1.0, 37.0 / 600, 1, 1, 10});
    FAIL();
  } catch (const InvalidParameter& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.name(), "jerk");
    EXPECT_EQ(what.find('\n'), std::string::npos);
    const auto at = what.find("need jerk >= ");
    ASSERT_NE(at, std::string::npos) << what;
    EXPECT_NEAR(std::stod(what.substr(at + 13)), 20.0, 1e-12);
    EXPECT_EQ(what.rfind("invalid jerk = 10: ", 0), 0u) << what;
  }
  try {
    JerkLimitedThreePhaseProfile({1.0, 0.07, 1, 1, 10});
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "a2, a3");
    EXPECT_NE(std::string(e.what()).find("period^2/(8 stroke)"), std::string::npos);
  }
}

TEST(JerkLimitedThreePhase, RejectsMisuse) {
  try {
    solve_jerk_limited_three_phase({1.0, 0.084, 1, 1, -1});
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_STREQ(e.what(), "invalid jerk = -1: must be > 0 (+inf: jump accelerations)");
  }
  for (double j : {0.0, -0.0, std::nan(""), -kInf})
    EXPECT_THROW(solve_jerk_limited_three_phase({1.0, 0.084, 1, 1, j}), InvalidParameter) << j;
  EXPECT_THROW(JerkLimitedThreePhaseProfile({1.0, 0.084, 1, 1, std::nan("")}), InvalidParameter);
  // The same bounds as the three-phase profile.
  EXPECT_THROW(solve_jerk_limited_three_phase({0.0, 0.084, 1, 1, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1e51, 0.084, 1, 1, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1.0, -0.084, 1, 1, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1.0, 1e-51, 1, 1, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1.0, 0.084, std::nan(""), 1, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1.0, 0.084, 1, 0, 10}), InvalidParameter);
  EXPECT_THROW(solve_jerk_limited_three_phase({1.0, 0.084, kInf, 1, 10}), InvalidParameter);
}

TEST(JerkLimitedThreePhase, ImplementsTheTableProfileInterface) {
  const JerkLimitedThreePhaseProfile profile({1.05, 0.084, 2.2, 0.9, 40.0});
  const TableProfile& base = profile;
  EXPECT_EQ(base.kind(), "jerk-limited-three-phase");
  EXPECT_EQ(base.piecewise_polynomial(), profile.piecewise_polynomial());
  EXPECT_NE(base.piecewise_polynomial(), nullptr);
  EXPECT_EQ(base.period(), 1.05);
  EXPECT_NEAR(base.piecewise_polynomial()->period(), 1.05, 1e-15);
  for (double t : {0.1, 0.5, 0.93}) {
    EXPECT_NEAR(base.state(t + 1.05).y, base.state(t).y, 1e-14);
    EXPECT_EQ(base.velocity(t), base.state(t).yd);
  }
  EXPECT_EQ(profile.parameters().jerk, 40.0);
  EXPECT_TRUE(profile.solution().physical);
}

// Far from the paper's scales: every physical setting builds, returns its velocity and meets
// the stroke; min_jerk separates physical from case 0.
TEST(JerkLimitedThreePhase, BuildsOverExtremeScales) {
  struct Scale {
    double period, stroke;
  };
  const Scale scales[] = {{1.0, 0.084},  {0.3975711110065985, 5.5655136158781754e-05},
                          {1.0, 1e-10},  {1e5, 0.084},
                          {1e-4, 0.084}, {1.0, 1e-5}};
  int built = 0, bisected = 0;
  for (const Scale& sc : scales) {
    const double a_c = 16 * sc.stroke / (sc.period * sc.period);
    for (int i = 0; i <= 12; ++i) {
      for (int k = 0; k <= 12; ++k) {
        const double a2 = a_c * std::pow(10.0, -1 + 0.5 * i),
                     a3 = a_c * std::pow(10.0, -1 + 0.5 * k);
        const Solution probe = solve_jerk_limited_three_phase({sc.period, sc.stroke, a2, a3, kInf});
        if (!probe.physical) continue;
        for (double f : {1.001, 3.0, 1e3}) {
          const Params p{sc.period, sc.stroke, a2, a3, probe.min_jerk * f};
          SCOPED_TRACE(::testing::Message() << "period " << p.period << " stroke " << p.stroke
                                          << " a2 " << a2 << " a3 " << a3 << " j " << p.jerk);
          if (!std::isfinite(p.jerk)) continue;
          std::optional<JerkLimitedThreePhaseProfile> profile;
          ASSERT_NO_THROW(profile.emplace(p));
          ++built;
          if (!profile->solution().closed_form) ++bisected;
          EXPECT_NEAR(profile->stroke(), p.stroke, 1e-11 * p.stroke);
          double dv = 0, dv_scale = 0, T = 0;
          for (const AccelerationSegment& s : profile->piecewise_polynomial()->segments()) {
            dv += 0.5 * (s.accel + s.end_accel()) * s.duration;
            dv_scale += 0.5 * (std::abs(s.accel) + std::abs(s.end_accel())) * s.duration;
            T += s.duration;
          }
          EXPECT_LE(std::abs(dv), 1e-14 * dv_scale);
          EXPECT_NEAR(T, p.period, 1e-14 * p.period);
          EXPECT_FALSE(
              solve_jerk_limited_three_phase({sc.period, sc.stroke, a2, a3, probe.min_jerk * 0.999})
                  .physical);
        }
      }
    }
  }
  EXPECT_GT(built, 500);
  EXPECT_GT(bisected, 20);
}
