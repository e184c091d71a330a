// Rows of 1-D parts (issue 24, docs/rows.md): the contact core's row stage (Moreau) and the
// exact row solver, against the single-part solvers, the cluster closed forms of docs/rows.md
// and each other.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "planar_profiles.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/row_exact.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {
namespace rows_test {

using testing_support::kPaper;  // the paper's Sect. 7.2 three-phase profile, period 1

core::SliderBody part(double length, FrictionLaw law = {}, double mass = 1) {
  core::SliderBody b;
  b.law = law;
  b.mass = mass;
  b.length = length;
  return b;
}

core::Model row_model(std::vector<core::SliderBody> parts, double h, double e = 0,
                      PlanarField field = UniformPlanarField{}) {
  PlanarTableMotion motion;
  motion.first = &kPaper;
  core::Model m{motion, std::move(field), {}, {h, 0.5}};
  for (auto& p : parts) m.bodies.push_back(p);
  for (int i = 0; i + 1 < static_cast<int>(parts.size()); ++i)
    m.part_contacts.push_back({i, i + 1, e});
  return m;
}

core::State start(const core::Model& m, const std::vector<double>& x,
                  const std::vector<double>& v) {
  std::vector<PlanarPose> poses;
  std::vector<PlanarTwist> twists;
  for (std::size_t i = 0; i < x.size(); ++i) {
    poses.push_back({x[i], 0, 0});
    twists.push_back({v[i], 0, 0});
  }
  return core::make_state(m, 0.0, poses, twists);
}

// The 1-D exact solver's position and velocity at t_end for one part (uniform level 1 or a
// field of steps under a point footprint).
ObjectState one_part_exact(const FrictionLaw& law, const FrictionMap& friction, double x0,
                           double v0, double t_end) {
  const ExactSetup setup{*kPaper.piecewise_polynomial(), *friction.piecewise_affine(), law};
  ExactState s = make_exact_state(setup, {0.0, x0, v0});
  advance_exact(setup, s, t_end);
  return s.object;
}

// --- Moreau: the core's row stage ----------------------------------------------------------

TEST(RowsMoreau, PartsThatNeverTouchMoveBitForBitAsAlone) {
  // Three parts with different laws, far apart: the row's contacts never become active, so
  // each part takes the 1-D Moreau step itself; equality is exact (bit for bit).
  const std::vector<FrictionLaw> laws{FrictionLaw(1.3, 1.0), FrictionLaw(1.0, 1.0),
                                      FrictionLaw(1.1, 0.9, 1.05)};
  const std::vector<double> x{0.0, 5.0, 10.0}, v{0.0, 0.1, -0.2};
  std::vector<core::SliderBody> parts;
  for (const auto& l : laws) parts.push_back(part(0.5, l));
  const double h = 1.0 / 2000;
  const core::Model row = row_model(parts, h);
  core::State s = start(row, x, v);
  core::step(row, s, 20000);
  for (std::size_t i = 0; i < 3; ++i) {
    core::Model alone = row_model({parts[i]}, h);
    core::State a = start(alone, {x[i]}, {v[i]});
    core::step(alone, a, 20000);
    EXPECT_EQ(s.bodies[i].pose.x, a.bodies[0].pose.x) << i;
    EXPECT_EQ(s.bodies[i].twist.ux, a.bodies[0].twist.ux) << i;
  }
}

TEST(RowsMoreau, TwoIdenticalTouchingPartsMoveAsOnePart) {
  // docs/rows.md: identical parts in contact never separate and move as one part of mass
  // m1 + m2; the paper's part moves independently of its mass. The pooled block's value is
  // (sum m u - sum m f)/sum m, equal to u - f up to rounding (1e-15 per step).
  const double h = 1.0 / 2000;
  const FrictionLaw law(1.2, 1.0);
  const core::Model pair = row_model({part(0.5, law), part(0.5, law)}, h);
  core::State s = start(pair, {0.0, 0.5}, {0.0, 0.0});
  const core::Model one = row_model({part(0.5, law, 2.0)}, h);
  core::State o = start(one, {0.0}, {0.0});
  for (int period = 0; period < 50; ++period) {
    core::step(pair, s, 2000);
    core::step(one, o, 2000);
  }
  EXPECT_GT(o.bodies[0].pose.x, 0.1);  // it moved
  EXPECT_NEAR(s.bodies[0].pose.x, o.bodies[0].pose.x, 1e-13);
  EXPECT_NEAR(s.bodies[1].pose.x - 0.5, o.bodies[0].pose.x, 1e-13);
}

// --- the exact row solver ------------------------------------------------------------------

TEST(RowsExact, OnePartIsTheOneDimensionalExactSolver) {
  // Uniform level and a friction step (point footprint): the row of one part against
  // advance_exact over 30 periods. Tolerance 1e-12: the two solvers form event times by
  // different arithmetic (the 1-D solver in phase-local time), rounding-level apart.
  const FrictionLaw law(1.25, 1.0);
  const UniformFriction uniform(1.0);
  const FrictionField steps = FrictionField::steps({0.3}, {1.0, 2.5});
  const FieldFriction step_map(steps, PointFootprint{});
  for (const bool with_step : {false, true}) {
    PlanarField field = UniformPlanarField{};
    if (with_step) field = AxisField{steps};
    const core::Model m = row_model({part(0.5, law)}, 1e-3, 0, field);
    RowExactState s = make_row_exact_state(m, 0.0, std::vector<double>{0.0},
                                           std::vector<double>{0.0});
    advance_row_exact(m, s, 30.0);
    const ObjectState ref =
        with_step ? one_part_exact(law, step_map, 0.0, 0.0, 30.0) : one_part_exact(law, uniform, 0.0, 0.0, 30.0);
    EXPECT_NEAR(s.x[0], ref.x, 1e-12 * std::max(1.0, std::abs(ref.x))) << with_step;
    EXPECT_NEAR(s.v[0], ref.xd, 1e-12) << with_step;
    if (with_step) EXPECT_GT(s.statistics.boundaries, 0);
  }
}

TEST(RowsExact, PartsThatNeverTouchEqualSingleRuns) {
  // Far-apart parts: each equals its own single-part row run bit for bit (each part's parabola
  // runs from its own anchor, which only its own events move: row_exact.hpp), sampled at
  // every whole period.
  const std::vector<FrictionLaw> laws{FrictionLaw(1.3, 1.0), FrictionLaw(1.0, 1.0),
                                      FrictionLaw(1.1, 0.9, 1.05)};
  const std::vector<double> x{0.0, 5.0, 10.0}, v{0.0, 0.1, -0.2};
  std::vector<core::SliderBody> parts;
  for (const auto& l : laws) parts.push_back(part(0.5, l));
  const core::Model m = row_model(parts, 1e-3);
  RowExactState s = make_row_exact_state(m, 0.0, x, v);
  std::vector<RowExactState> alone;
  std::vector<core::Model> models;
  for (std::size_t i = 0; i < 3; ++i) models.push_back(row_model({parts[i]}, 1e-3));
  for (std::size_t i = 0; i < 3; ++i)
    alone.push_back(make_row_exact_state(models[i], 0.0, std::vector<double>{x[i]},
                                         std::vector<double>{v[i]}));
  for (int p = 1; p <= 20; ++p) {
    advance_row_exact(m, s, p);
    for (std::size_t i = 0; i < 3; ++i) {
      advance_row_exact(models[i], alone[i], p);
      EXPECT_EQ(s.x[i], alone[i].x[0]) << i << " at period " << p;
      EXPECT_EQ(s.v[i], alone[i].v[0]) << i << " at period " << p;
    }
  }
  EXPECT_EQ(s.statistics.collisions, 0);
}

TEST(RowsExact, TwoIdenticalTouchingPartsMoveAsOnePartOfTwiceTheMass) {
  // docs/rows.md: to <= 1e-13 over 50 periods (the bound).
  const FrictionLaw law(1.2, 1.0);
  const core::Model pair = row_model({part(0.5, law), part(0.5, law)}, 1e-3);
  RowExactState s = make_row_exact_state(pair, 0.0, std::vector<double>{0.0, 0.5},
                                         std::vector<double>{0.0, 0.0});
  const core::Model one = row_model({part(0.5, law, 2.0)}, 1e-3);
  RowExactState o = make_row_exact_state(one, 0.0, std::vector<double>{0.0},
                                         std::vector<double>{0.0});
  advance_row_exact(pair, s, 50.0);
  advance_row_exact(one, o, 50.0);
  EXPECT_GT(o.x[0], 0.1);
  EXPECT_EQ(s.statistics.separations, 0);
  EXPECT_TRUE(s.touching[0]);
  EXPECT_NEAR(s.x[0], o.x[0], 1e-13);
  EXPECT_NEAR(s.x[1] - 0.5, o.x[0], 1e-13);
  EXPECT_NEAR(s.v[1], o.v[0], 1e-13);
}

// The largest |x_exact - x_moreau| over the parts at whole periods 1 .. periods.
double row_distance(const core::Model& m, const std::vector<double>& x,
                    const std::vector<double>& v, long long steps_per_period, int periods,
                    RowExactStatistics* stats = nullptr) {
  core::Model mm = m;
  mm.options.step = 1.0 / static_cast<double>(steps_per_period);
  core::State s = start(mm, x, v);
  RowExactState e = make_row_exact_state(m, 0.0, x, v);
  double worst = 0;
  for (int p = 1; p <= periods; ++p) {
    core::step(mm, s, steps_per_period);
    advance_row_exact(m, e, static_cast<double>(p));
    for (std::size_t i = 0; i < x.size(); ++i)
      worst = std::max(worst, std::abs(s.bodies[i].pose.x - e.x[i]));
  }
  if (stats) *stats = e.statistics;
  return worst;
}

TEST(RowsExact, TouchingPartsWithDifferentFrictionStayTogetherOrSplitAsDerived) {
  // docs/rows.md, two touching parts: sliding forward they stay together iff the front part's
  // kinetic level k2+ >= k1+, sliding backward iff k2- <= k1-. Together: rear kf 0.8 kb 1.2,
  // front 1.0 both ways; split: the front part slides easier forward (kf 0.8) than the rear
  // (1.0). Each against Moreau at 20 000 steps per period (distance <= 1e-3, Moreau's O(h)).
  const double L = 0.5;
  {
    const core::Model m = row_model({part(L, FrictionLaw(1.3, 0.8, 1.2)), part(L, FrictionLaw(1.3, 1.0))}, 1e-3);
    RowExactStatistics st;
    EXPECT_LT(row_distance(m, {0.0, L}, {0.0, 0.0}, 20000, 10, &st), 1e-3);
    EXPECT_EQ(st.separations, 0);
    EXPECT_EQ(st.collisions, 0);
  }
  {
    const core::Model m = row_model({part(L, FrictionLaw(1.3, 1.0)), part(L, FrictionLaw(1.3, 0.8))}, 1e-3);
    RowExactStatistics st;
    EXPECT_LT(row_distance(m, {0.0, L}, {0.0, 0.0}, 20000, 10, &st), 1e-3);
    EXPECT_GT(st.separations, 0);
  }
}

TEST(RowsExact, MoreauConvergesWithOrderOneOnAThreePartQueueWithCollisions) {
  // Three parts with gaps: the rear one slides furthest forward and backward (static 0.7 <
  // the table's 0.9 of phase 3), the front one never backward: every period the rear part
  // catches the queue, pushes it, and falls back (about two collisions and two separations a
  // period). Plastic and e = 0.4. Moreau's distance to the exact row at 1e3, 1e4, 1e5 steps
  // per period over 5 periods: order 1 (each tenfold step cut gains >= 0.8 decades).
  const double L = 0.3;
  for (const double e : {0.0, 0.4}) {
    const core::Model m = row_model({part(L, FrictionLaw(0.7, 0.4, 0.6)),
                                     part(L, FrictionLaw(0.85, 0.75)),
                                     part(L, FrictionLaw(1.1, 1.0))},
                                    1e-3, e);
    const std::vector<double> x{0.0, 0.35, 0.7}, v{0.0, 0.0, 0.0};
    RowExactStatistics st;
    std::vector<double> err;
    for (const long long n : {1000LL, 10000LL, 100000LL})
      err.push_back(row_distance(m, x, v, n, 5, &st));
    EXPECT_GE(st.collisions, 8) << e;
    EXPECT_GE(st.separations, 8) << e;
    for (std::size_t k = 0; k + 1 < err.size(); ++k)
      EXPECT_GT(std::log10(err[k] / err[k + 1]), 0.8) << e << ": " << err[k] << " " << err[k + 1];
    std::cout << "e = " << e << ": row Moreau distances " << err[0] << " " << err[1] << " "
              << err[2] << ", collisions " << st.collisions << ", separations "
              << st.separations << "\n";
  }
}

TEST(RowsExact, BadInputNamesThePart) {
  const core::Model m = row_model({part(0.5), part(0.5)}, 1e-3);
  try {
    make_row_exact_state(m, 0.0, std::vector<double>{0.0, 0.4}, std::vector<double>{0.0, 0.0});
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "x[1]");
  }
  core::Model bad = m;
  std::get<core::SliderBody>(bad.bodies[1]).length = 0;
  EXPECT_THROW(core::validate(bad), InvalidParameter);
  bad = m;
  bad.part_contacts[0].restitution = 1.5;
  try {
    core::validate(bad);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "part_contacts[0].restitution");
  }
  bad = m;
  std::get<core::SliderBody>(bad.bodies[0]).mass = 0;
  try {
    core::validate(bad);
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "bodies[0].mass");
  }
}

}  // namespace rows_test
}  // namespace selfalign

// --- analyses: conveying and stopping queues (analysis/row.hpp) -----------------------------

namespace selfalign::rows_analysis_test {

using testing_support::kPaper;

RowQueue identical_queue(int n, double length, double pitch, const FrictionLaw& law) {
  RowQueue q;
  for (int i = 0; i < n; ++i) q.parts.push_back({length, 1.0, law, i * pitch, 0.0});
  return q;
}

TEST(RowAnalysis, ATouchingQueueOfIdenticalPartsConveysAsOnePart) {
  // docs/rows.md section 4: identical touching parts never separate; the queue moves as the
  // lone part, whose mean velocity over period 10 the 1-D exact solver gives. Throughput at
  // pitch L: v T / L parts per period.
  const FrictionLaw law(1.2, 1.0);
  const RowQueue q = identical_queue(4, 0.25, 0.25, law);
  const RowRun run = row_run(kPaper, q, nullptr, 10, {Method::exact, 0}, 4);
  const UniformFriction uniform(1.0);
  const ExactSetup setup{*kPaper.piecewise_polynomial(), *uniform.piecewise_affine(), law};
  ExactState s = make_exact_state(setup, {0.0, 0.0, 0.0});
  advance_exact(setup, s, 9.0);
  const double x9 = s.object.x;
  advance_exact(setup, s, 10.0);
  const double v_bar = s.object.x - x9;
  EXPECT_GT(v_bar, 0.01);
  EXPECT_NEAR(run.queue_velocity, v_bar, 1e-12);
  ASSERT_EQ(run.clusters, std::vector<int>({4}));
  EXPECT_EQ(run.pitch, 0.25);
  EXPECT_NEAR(run.throughput_per_period, v_bar / 0.25, 1e-11);
  EXPECT_EQ(run.positions.size(), 41u);
  // Moreau at 20 000 steps per period: the same velocity to O(h)
  const RowRun moreau = row_run(kPaper, q, nullptr, 10, {Method::time_stepping, 20000}, 4);
  EXPECT_NEAR(moreau.queue_velocity, v_bar, 2e-4);
  EXPECT_EQ(moreau.clusters, std::vector<int>({4}));
}

TEST(RowAnalysis, OnePartStopsWhereTheOneDimensionalExactSolverStops) {
  const FrictionLaw law(1.2, 1.0);
  const FrictionField field = FrictionField::steps({0.5}, {1.0, 2.5});
  const RowQueue q = identical_queue(1, 0.3, 0.3, law);
  const RowStop stop = row_stop(kPaper, q, field, 200, {Method::exact, 0}, 2);
  ASSERT_TRUE(stop.stopped);
  const FieldFriction map(field, PointFootprint{});
  const ExactSetup setup{*kPaper.piecewise_polynomial(), *map.piecewise_affine(), law};
  ExactState s = make_exact_state(setup, {0.0, 0.0, 0.0});
  advance_exact(setup, s, static_cast<double>(stop.periods) + 5);
  EXPECT_NEAR(stop.x[0], s.object.x, 1e-12);
  EXPECT_NEAR(stop.error[0], s.object.x - 0.5, 1e-12);
  EXPECT_GT(stop.process_time[0], 0);
  EXPECT_LE(stop.stop_time, static_cast<double>(stop.periods));
}

TEST(RowAnalysis, AQueueStopsAtTheStepAndTheMethodsAgree) {
  // Three parts with gaps reach a step to level 4: the rear one (static 1.1, kinetic 0.8)
  // conveys faster and catches up; a cluster with only its front part on the rough side has
  // the pooled static bound (1.1 + 1.2 + 4.8)/3 = 2.37 < 3 = the table's push (docs/rows.md
  // section 4), so the queue pushes the front part on until two parts are on the rough side
  // ((1.1 + 4.8 + 4.8)/3 = 3.57 > 3): it stops packed, the middle part's leading edge just
  // past the step. The exact row and Moreau (20 000 steps per period: O(h) = 5e-5 per
  // collision and stop) agree to 2e-3.
  const FrictionLaw law(1.2, 1.0);
  const FrictionField field = FrictionField::steps({1.5}, {1.0, 4.0});
  RowQueue q = identical_queue(3, 0.25, 0.375, law);
  q.parts[0].law = FrictionLaw(1.1, 0.8);  // the rear part conveys faster: it catches up
  const RowStop exact = row_stop(kPaper, q, field, 400, {Method::exact, 0}, 2);
  const RowStop moreau = row_stop(kPaper, q, field, 400, {Method::time_stepping, 20000}, 2);
  ASSERT_TRUE(exact.stopped);
  ASSERT_TRUE(moreau.stopped);
  EXPECT_GT(exact.collisions, 0);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(exact.x[i], moreau.x[i], 2e-3) << i;
  ASSERT_EQ(exact.gaps.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(exact.gaps[i], moreau.gaps[i], 2e-3) << i;
  EXPECT_TRUE(exact.accumulated);
  EXPECT_GT(exact.x[1], 1.5);  // two parts on the rough side
  EXPECT_LT(exact.x[0], 1.5);
  EXPECT_NEAR(exact.error[2], exact.x[2] - 1.5, 1e-15);
  EXPECT_NEAR(exact.error[1], exact.x[1] - 1.25, 1e-15);
  std::cout << "queue end x " << exact.x[0] << " " << exact.x[1] << " " << exact.x[2]
            << " gaps " << exact.gaps[0] << " " << exact.gaps[1] << " accumulated "
            << exact.accumulated << " periods " << exact.periods << "\n";
}

}  // namespace selfalign::rows_analysis_test
