// Monte Carlo of a queue stopping at the friction step (robust/row_monte_carlo.hpp,
// docs/rows.md section 11): against row_stop (no uncertainty), the 1-D exact solver on the
// single-part study's own draws (one part), the draw convention written out again, and
// itself over thread counts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "queue_example.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/robust/process_uncertainty.hpp"
#include "selfalign/robust/row_monte_carlo.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {
namespace row_monte_carlo_test {

using testing_support::example_queue;  // examples/queue.toml

ProcessUncertainty some_uncertainty() {
  ProcessUncertainty u;
  set_input(u, "mu", "normal:0.3,5%");
  set_input(u, "c_mu", "uniform:3.5,4.5");
  set_input(u, "static_ratio", "uniform:1,1.3");
  set_input(u, "x_mu_offset", "uniform:-0.05,0.05");
  set_input(u, "amplitude", "normal:1,3%");
  set_input(u, "period_factor", "uniform:0.95,1.05");
  return u;
}

// Bitwise equality of two columns (NaN equal to NaN of the same bits).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(RowMonteCarlo, WithoutUncertaintyEveryRunIsRowStop) {
  // Every input known: each run's process is the nominal one, bit for bit, so each run's end
  // positions and process times are row_stop's exactly, and the errors are row_stop's (the
  // nominal step is the drawn one).
  const RowProcess p = example_queue();
  const ThreePhaseProfile profile(p.table);
  const FrictionField field = FrictionField::steps({p.step_position}, {1.0, p.c_mu});
  // The study samples each run once a period; where the exact solver stops between events
  // moves the rounding of the rear part's end (1e-16 with 20 samples a period).
  const RowStop ref = row_stop(profile, p.queue, field, 400, {Method::exact, 0}, 1);
  const RowStop sampled = row_stop(profile, p.queue, field, 400, {Method::exact, 0}, 20);
  ASSERT_TRUE(ref.stopped);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(ref.x[i], sampled.x[i], 1e-14);
  RowMonteCarloOptions o;
  o.runs = 4;
  o.max_periods = 400;
  o.tolerance = 0.3;
  const RowMonteCarloResult r = row_monte_carlo(p, ProcessUncertainty{}, o);
  ASSERT_EQ(r.parts, 3);
  EXPECT_EQ(r.queue_stops, 4);
  EXPECT_EQ(r.p_stop, 1.0);
  for (int run = 0; run < 4; ++run) {
    EXPECT_EQ(r.accumulated[static_cast<std::size_t>(run)], ref.accumulated);
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t at = static_cast<std::size_t>(run) * 3 + i;
      EXPECT_EQ(r.stopped[at], 1);
      EXPECT_EQ(r.end_position[at], ref.x[i]) << run << " " << i;
      EXPECT_EQ(r.error[at], ref.error[i]) << run << " " << i;
      EXPECT_EQ(r.process_time[at], ref.process_time[i]) << run << " " << i;
    }
  }
  // Every part 0.2613 past its packed target (docs/rows.md section 8): within 0.3.
  for (const RowPartSummary& s : r.summary) {
    EXPECT_EQ(s.within, 4);
    EXPECT_EQ(s.p_within, 1.0);
    EXPECT_EQ(s.end_sd, 0.0);
  }
  EXPECT_EQ(r.summary[2].end_mean, ref.x[2]);
  EXPECT_EQ(r.all_within, 4);
  EXPECT_EQ(row_end_position_quantile(r, 1, 0.5), ref.x[1]);
  EXPECT_EQ(row_process_time_quantile(r, 0, 0.99), ref.process_time[0]);
}

TEST(RowMonteCarlo, DrawsFollowTheSingleStudysConvention) {
  // Part i's input k is the quantile of uniform_draw(seed, run, 7 i + k), written out here
  // again; part 0 draws what draw_inputs draws for the single-part study; the per-run inputs
  // are part 0's for every part; mu is the factor on the nominal 0.3.
  const RowProcess p = example_queue();
  const ProcessUncertainty u = some_uncertainty();
  DesignRequest q;
  q.mu = 0.3;
  q.c_mu = 4.0;
  for (std::uint64_t run : {0u, 5u, 77u}) {
    const RowDraw d = draw_row_process(p, u, 9, run);
    const InputValues single = draw_inputs(q, u, 9, run);
    ASSERT_EQ(d.inputs.size(), 3u);
    EXPECT_EQ(d.inputs[0][0], single[0] / 0.3);
    for (std::size_t k : {1u, 2u, 4u, 5u, 6u}) EXPECT_EQ(d.inputs[0][k], single[k]) << k;
    EXPECT_TRUE(std::isnan(d.inputs[0][3]));  // width: not drawn
    for (std::size_t i = 1; i < 3; ++i) {
      const double mu = quantile(u.mu, uniform_draw(9, run, 7 * i + 0), 0.0);
      const double ratio = quantile(u.static_ratio, uniform_draw(9, run, 7 * i + 2), 0.0);
      EXPECT_EQ(d.inputs[i][0], mu / 0.3) << i;
      EXPECT_EQ(d.inputs[i][2], ratio) << i;
      for (std::size_t k : {1u, 4u, 5u, 6u}) EXPECT_EQ(d.inputs[i][k], single[k]) << i << k;
      // the law: static = ratio x forward kinetic, backward capped by it
      const double f = mu / 0.3, kf = p.queue.parts[i].law.kinetic_forward() * f;
      EXPECT_EQ(d.process.queue.parts[i].law.kinetic_forward(), kf);
      EXPECT_EQ(d.process.queue.parts[i].law.static_coefficient(), ratio * kf);
      EXPECT_EQ(d.process.queue.parts[i].law.kinetic_backward(), std::min(kf, ratio * kf));
    }
    const double a = single[5], per = single[6];
    EXPECT_EQ(d.process.table.period, 1.0 * per);
    EXPECT_EQ(d.process.table.stroke, 0.084 * a);
    EXPECT_EQ(d.process.table.a2, 3.0 * a / (per * per));
    EXPECT_EQ(d.process.table.a3, 0.9 * a / (per * per));
    EXPECT_EQ(d.process.step_position, 1.5 + single[4]);
    EXPECT_EQ(d.process.c_mu, single[1]);
  }
  // The draws' distribution: c_mu uniform on [3.5, 4.5], so P(c_mu < 3.75) = 1/4; over 4000
  // runs the count lies in its 95% Wilson interval's reach (binomial sd 27: +-4 sd = 110).
  int below = 0;
  for (std::uint64_t run = 0; run < 4000; ++run)
    below += draw_row_process(p, u, 3, run).process.c_mu < 3.75;
  EXPECT_NEAR(below, 1000, 110);
}

TEST(RowMonteCarlo, OnePartEqualsTheOneDimensionalExactSolverOnTheSingleStudysDraws) {
  // A queue of one part on the single-part study's draws (draw_inputs), converted by hand
  // (docs/rows.md section 11): the 1-D exact solver on a step with a point footprint ends
  // where the row's Monte Carlo says, run by run (1e-12: the two solvers' event arithmetic,
  // OnePartIsTheOneDimensionalExactSolver). (The single-part monte_carlo itself averages the
  // step over the part's width, eqs. 7-9: another model, so it is not compared.)
  RowProcess p;
  p.table = {1.0, 0.084, 3.0, 0.9};
  p.step_position = 0.6;
  p.c_mu = 2.5;
  p.queue.parts = {{0.3, 1.0, FrictionLaw(1.2, 1.0), 0.0, 0.0}};
  const ProcessUncertainty u = some_uncertainty();
  RowMonteCarloOptions o;
  o.runs = 24;
  o.seed = 5;
  o.max_periods = 400;
  o.tolerance = 0.05;
  const RowMonteCarloResult r = row_monte_carlo(p, u, o);
  DesignRequest q;
  q.mu = 0.3;
  q.c_mu = 2.5;
  int stopped = 0;
  for (std::size_t run = 0; run < 24; ++run) {
    const InputValues v = draw_inputs(q, u, 5, run);
    const double f = v[0] / 0.3, a = v[5], per = v[6];
    const FrictionLaw law(v[2] * f, f, std::min(f, v[2] * f));
    const ThreePhaseProfile profile({per, 0.084 * a, 3.0 * a / (per * per), 0.9 * a / (per * per)});
    const FrictionField field = FrictionField::steps({0.6 + v[4]}, {1.0, v[1]});
    const FieldFriction map(field, PointFootprint{});
    const ExactSetup setup{*profile.piecewise_polynomial(), *map.piecewise_affine(), law};
    ExactState s = make_exact_state(setup, {0.0, 0.0, 0.0});
    advance_exact(setup, s, 405 * per);
    ASSERT_TRUE(r.queue_stopped[run]) << run;
    ++stopped;
    EXPECT_NEAR(r.end_position[run], s.object.x, 1e-12) << run;
    EXPECT_EQ(r.error[run], r.end_position[run] - 0.6) << run;  // the nominal step
    EXPECT_EQ(s.object.xd, 0.0) << run;
  }
  // The summary from the columns, by hand.
  double sum = 0;
  int within = 0;
  for (std::size_t run = 0; run < 24; ++run) {
    sum += r.end_position[run];
    within += std::abs(r.end_position[run] - 0.6) <= 0.05;
  }
  EXPECT_NEAR(r.summary[0].end_mean, sum / 24, 1e-15);
  EXPECT_EQ(r.summary[0].within, within);
  EXPECT_EQ(r.all_within, within);
  const auto [lo, hi] = wilson_interval(within, 24);
  EXPECT_EQ(r.summary[0].p_within_low, lo);
  EXPECT_EQ(r.summary[0].p_within_high, hi);
  EXPECT_GT(r.summary[0].end_sd, 0.0);
  EXPECT_EQ(stopped, 24);
}

TEST(RowMonteCarlo, TheSameForAnyThreadCountAndChunks) {
  const RowProcess p = example_queue();
  const ProcessUncertainty u = some_uncertainty();
  RowMonteCarloOptions o;
  o.runs = 16;
  o.max_periods = 400;
  o.threads = 1;
  const RowMonteCarloResult one = row_monte_carlo(p, u, o);
  o.threads = 2;
  const RowMonteCarloResult two = row_monte_carlo(p, u, o);
  EXPECT_TRUE(same_bits(one.end_position, two.end_position));
  EXPECT_TRUE(same_bits(one.error, two.error));
  EXPECT_TRUE(same_bits(one.process_time, two.process_time));
  EXPECT_TRUE(same_bits(one.inputs, two.inputs));
  EXPECT_TRUE(same_bits(one.queue_stopped, two.queue_stopped));
  // a chunk (first_run 10, 6 runs) is the tail of the study
  o.first_run = 10;
  o.runs = 6;
  const RowMonteCarloResult tail = row_monte_carlo(p, u, o);
  EXPECT_TRUE(same_bits(tail.end_position,
                        std::vector<double>(one.end_position.begin() + 30, one.end_position.end())));
  // the uncertainty shows: the runs differ
  EXPECT_NE(one.end_position[2], one.end_position[5]);
}

TEST(RowMonteCarlo, BadInputNamesTheParameter) {
  const RowProcess p = example_queue();
  RowMonteCarloOptions o;
  o.runs = 0;
  const auto name_of = [&](const ProcessUncertainty& u, const RowMonteCarloOptions& opt,
                           const RowProcess& proc) {
    try {
      (void)row_monte_carlo(proc, u, opt);
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("none");
  };
  EXPECT_EQ(name_of({}, o, p), "runs");
  o.runs = 2;
  o.tolerance = 0;
  EXPECT_EQ(name_of({}, o, p), "tolerance");
  o.tolerance = 0.1;
  o.max_periods = 0;
  EXPECT_EQ(name_of({}, o, p), "max_periods");
  o.max_periods = 10;
  ProcessUncertainty u;
  set_input(u, "width", "uniform:0.9,1.1");
  EXPECT_EQ(name_of(u, o, p), "width.uncertain");
  ProcessUncertainty tiny;
  set_input(tiny, "mu", "uniform:1e-55,1");  // factor 2e-55 on the coefficients: refused
  EXPECT_EQ(name_of(tiny, o, p), "mu.lower");
  ProcessUncertainty huge;
  set_input(huge, "period_factor", "uniform:1e-30,1");  // a2 x 1e60: beyond the model's range
  EXPECT_EQ(name_of(huge, o, p), "period_factor.lower");
  RowProcess overlap = p;
  overlap.queue.parts[1].x = 0.1;
  EXPECT_EQ(name_of({}, o, overlap), "parts[1].x");
  const RowMonteCarloResult r = row_monte_carlo(p, {}, o);
  EXPECT_THROW((void)row_end_position_quantile(r, 3, 0.5), InvalidParameter);
  EXPECT_THROW((void)row_end_position_quantile(r, 0, 0.0), InvalidParameter);
}

}  // namespace row_monte_carlo_test
}  // namespace selfalign
