// Tests for profiles/three_phase.hpp: the appendix's constraints (61)-(67) and Sect. 4.4.3's
// seven constraints, checked by integrating the returned profile by hand, on a grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "selfalign/error.hpp"
#include "selfalign/profiles/three_phase.hpp"

using namespace selfalign;

namespace {
// The constraints hold to rounding: every quantity is O(1) and formed from a handful of
// operations, so 1e-12 absolute leaves three orders of magnitude of headroom.
constexpr double kConstraintTol = 1e-12;

struct Integrated {
  double y_end, yd_end, y_min, y_max;
};

// Integrates the three constant-acceleration intervals of Fig. 7 from (y_ini, y'_ini),
// independently of the library's PiecewisePolynomialProfile.
Integrated integrate(const ThreePhaseParameters& p, const ThreePhaseSolution& r) {
  const double acc[3] = {0.0, -p.a2, p.a3};
  const double t[4] = {0.0, r.t1, r.t2, r.t3};
  double y = r.y_ini, yd = r.yd_ini, y_min = y, y_max = y;
  for (int i = 0; i < 3; ++i) {
    const double d = t[i + 1] - t[i];
    if (acc[i] != 0) {  // an extremum inside the interval where y' = 0
      const double tau = -yd / acc[i];
      if (tau > 0 && tau < d) {
        const double ye = y + yd * tau + 0.5 * acc[i] * tau * tau;
        y_min = std::min(y_min, ye);
        y_max = std::max(y_max, ye);
      }
    }
    y += yd * d + 0.5 * acc[i] * d * d;
    yd += acc[i] * d;
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  }
  return {y, yd, y_min, y_max};
}
}  // namespace

TEST(ThreePhaseProfile, MeetsAllConstraintsOnTheGridAndReportsCaseZero) {
  const double dt = 1.0, dy = 0.084;
  int physical = 0, case0 = 0;
  for (int i = 1; i <= 60; ++i) {
    for (int j = 1; j <= 60; ++j) {
      const ThreePhaseParameters p{dt, dy, 3.0 * i / 60, 3.0 * j / 60};
      const ThreePhaseSolution r = solve_three_phase(p);
      // Independent case-0 criterion: the largest stroke of this shape is reached with t1 = 0
      // (the whole period accelerating); build that profile with the generic normaliser.
      const double s = 1 / p.a2 + 1 / p.a3, D = dt / s;
      const double durations[3] = {0.0, D / p.a2, D / p.a3}, accels[3] = {0.0, -p.a2, p.a3};
      const double max_stroke =
          PiecewisePolynomialProfile::from_accelerations(durations, accels).stroke();
      if (!r.physical) {
        ++case0;
        EXPECT_LT(max_stroke, dy * (1 + 1e-12)) << p.a2 << ", " << p.a3;
        EXPECT_THROW(ThreePhaseProfile{p}, InvalidParameter);
        continue;
      }
      ++physical;
      EXPECT_GE(max_stroke, dy * (1 - 1e-12));
      const Integrated g = integrate(p, r);
      SCOPED_TRACE(::testing::Message() << "a2 = " << p.a2 << ", a3 = " << p.a3);
      EXPECT_NEAR(g.y_end, r.y_ini, kConstraintTol);        // periodic position (constraint 5)
      EXPECT_NEAR(g.yd_end, r.yd_ini, kConstraintTol);      // periodic velocity (constraint 6)
      EXPECT_NEAR(g.y_max - g.y_min, dy, kConstraintTol);   // stroke (constraint 4)
      EXPECT_NEAR(g.y_min, 0.0, kConstraintTol);            // min y = 0 (constraint 1)
      EXPECT_NEAR(r.t3, dt, 0.0);                           // eq. (62)
      EXPECT_GE(r.t1, 0.0);                                 // y'' = 0 on [t0, t1] (constraint 7)
      EXPECT_LE(r.t1, r.t2);
      EXPECT_LE(r.t2, r.t3);
      EXPECT_GE(r.yd_ini, 0.0);  // the y'_ini < 0 branch is empty (docs/three-phase-profile.md)
      // The appendix's equations verbatim.
      EXPECT_NEAR(r.y_ini, 0.5 * p.a3 * std::pow(r.t3 - r.t_yd0_2, 2), kConstraintTol);  // (61)
      EXPECT_NEAR(0.5 * p.a2 * std::pow(r.t2 - r.t_yd0_1, 2) +
                      0.5 * p.a3 * std::pow(r.t_yd0_2 - r.t2, 2),
                  dy, kConstraintTol);  // (63)
      EXPECT_NEAR(r.yd_ini * r.t1 + 0.5 * p.a2 * std::pow(r.t_yd0_1 - r.t1, 2) +
                      0.5 * p.a3 * std::pow(r.t3 - r.t_yd0_2, 2),
                  dy, kConstraintTol);  // (64), with its right-hand side equal to Δy by (63)
      EXPECT_NEAR(p.a3 * (r.t3 - r.t2), p.a2 * (r.t2 - r.t1), kConstraintTol);  // (65)
      EXPECT_NEAR(r.yd_ini - p.a2 * (r.t_yd0_1 - r.t1), 0.0, kConstraintTol);    // (66)
      EXPECT_NEAR(r.yd_ini - p.a3 * (r.t3 - r.t_yd0_2), 0.0, kConstraintTol);    // (67)
      // The profile object agrees with the closed form (a second normalisation route).
      const ThreePhaseProfile profile(p);
      const TableState s0 = profile.state(0.0);
      EXPECT_NEAR(s0.y, r.y_ini, kConstraintTol);
      EXPECT_NEAR(s0.yd, r.yd_ini, kConstraintTol);
      EXPECT_EQ(s0.ydd, 0.0);
      EXPECT_NEAR(profile.stroke(), dy, kConstraintTol);
      EXPECT_EQ(profile.state(0.5 * (r.t1 + r.t2)).ydd, -p.a2);
      EXPECT_EQ(profile.state(0.5 * (r.t2 + r.t3)).ydd, p.a3);
    }
  }
  // The grid straddles the boundary 1/a2 + 1/a3 = Δt^2/(8Δy) = 1.488...: both kinds occur.
  EXPECT_GT(physical, 1000);
  EXPECT_GT(case0, 100);
}

TEST(ThreePhaseProfile, CaseZeroBoundaryIsTheClosedFormLimit) {
  // 1/a + 1/a = Δt^2/(8Δy) at a = 16 Δy / Δt^2: just inside is physical, just outside is not.
  const double dt = 1.0, dy = 0.084, a = 16 * dy / (dt * dt);
  EXPECT_TRUE(solve_three_phase({dt, dy, a * (1 + 1e-9), a * (1 + 1e-9)}).physical);
  EXPECT_FALSE(solve_three_phase({dt, dy, a * (1 - 1e-9), a * (1 - 1e-9)}).physical);
  const ThreePhaseSolution edge = solve_three_phase({dt, dy, a * (1 + 1e-12), a * (1 + 1e-12)});
  EXPECT_NEAR(edge.t1, 0.0, 1e-5);  // at the limit the zero-acceleration interval vanishes
}

TEST(ThreePhaseProfile, OtherRootOfTheQuadraticHasNegativeFirstInterval) {
  // u^2 - 2u + 2G = 0 has roots 1 -+ sqrt(1 - 2G); the '+' root gives t1 = (1 - u) Δt < 0.
  const ThreePhaseParameters p{1.0, 0.084, 2.3, 1.3};
  const double s = 1 / p.a2 + 1 / p.a3, G = std::sqrt(2 * s * p.stroke) / p.period;
  const double u_other = 1 + std::sqrt(1 - 2 * G);
  EXPECT_LT((1 - u_other) * p.period, 0.0);
  const double u = 1 - std::sqrt(1 - 2 * G);
  EXPECT_NEAR(solve_three_phase(p).t1, (1 - u) * p.period, 1e-14);
}

TEST(ThreePhaseProfile, RejectsMisuse) {
  EXPECT_THROW(solve_three_phase({0.0, 0.084, 1, 1}), InvalidParameter);
  EXPECT_THROW(solve_three_phase({1.0, -0.084, 1, 1}), InvalidParameter);
  EXPECT_THROW(solve_three_phase({1.0, 0.084, std::nan(""), 1}), InvalidParameter);
  EXPECT_THROW(solve_three_phase({1.0, 0.084, 1, 0}), InvalidParameter);
  try {
    ThreePhaseProfile({1.0, 0.084, 0.5, 0.5});
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "a2, a3");
    EXPECT_NE(std::string(e.what()).find("period^2/(8 stroke)"), std::string::npos);
  }
}

// Issue 9, F01: physical profiles far from the paper's scales were rejected ("net velocity
// change 2.1e-14 must be 0") because the segment durations were differences of absolute times.
// Every setting that the closed-form criterion (docs/three-phase-profile.md: physical iff
// 1/a2 + 1/a3 <= Δt^2/(8Δy)) calls physical must build, over six decades of a2/a3 and extreme
// periods and strokes, and the built profile must return to its initial velocity.
TEST(ThreePhaseProfile, EveryPhysicalSettingBuildsOverExtremeScales) {
  struct Scale {
    double period, stroke;
  };
  const Scale scales[] = {{1.0, 0.084},   {0.3975711110065985, 5.5655136158781754e-05},
                          {1.0, 1e-10},   {1e5, 0.084},
                          {1e-4, 0.084},  {1.0, 1e-5}};
  int built = 0;
  for (const Scale& sc : scales) {
    for (int i = 0; i <= 24; ++i) {
      for (int j = 0; j <= 24; ++j) {
        // a2, a3 log-spaced over [1e-6, 1e6] relative to the scale's critical acceleration
        // a_c = 16 Δy/Δt^2 (where the equal-acceleration profile becomes physical).
        const double a_c = 16 * sc.stroke / (sc.period * sc.period);
        const ThreePhaseParameters p{sc.period, sc.stroke, a_c * std::pow(10.0, -6 + 0.5 * i),
                                     a_c * std::pow(10.0, -6 + 0.5 * j)};
        const double s = 1 / p.a2 + 1 / p.a3;
        if (!(s <= p.period * p.period / (8 * p.stroke))) continue;  // case 0 (closed form)
        SCOPED_TRACE(::testing::Message() << "period " << p.period << " stroke " << p.stroke
                                        << " a2 " << p.a2 << " a3 " << p.a3);
        std::optional<ThreePhaseProfile> profile;
        ASSERT_NO_THROW(profile.emplace(p));
        ++built;
        // The velocity swing D = u Δt / s, written out from the docs (not from the library):
        // the table loses D at -a2 and regains it at +a3, so its velocity returns.
        const double G = std::sqrt(2 * s * p.stroke) / p.period;
        const double u = 2 * G / (1 + std::sqrt(1 - 2 * G));
        const double D = u * p.period / s;
        const auto segs = profile->piecewise_polynomial()->segments();
        double dv = 0, dt = 0;
        for (const AccelerationSegment& seg : segs) {
          dv += seg.accel * seg.duration;
          dt += seg.duration;
        }
        // Rounding of three products of size D: a few ulps of D.
        constexpr double kVelocityReturnTol = 1e-14;
        EXPECT_LE(std::abs(dv), kVelocityReturnTol * D);
        EXPECT_NEAR(dt, p.period, 1e-14 * p.period);  // the durations fill the period
        EXPECT_NEAR(segs.back().duration * p.a3, D, 1e-14 * D);
      }
    }
  }
  EXPECT_GT(built, 1000);
}
