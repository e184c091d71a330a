// Rows of 1-D parts (issue 24, docs/rows.md): the cost of the contact core's row stage
// (core::step, Moreau) per part and step, and the exact row solver against Moreau on the
// 3-part queue of tests/test_rows.cpp.
//
//   BM_row_moreau_step/N        N parts of length 0.3 at pitch 0.3: all touching, one chain of
//                               N parts; laws FrictionLaw(1.2, 1.0 + 0.01 (i % 3)) (identical
//                               but not quite: the chain splits and closes again); the paper's
//                               three-phase profile (Sect. 7.2), h = 1/2000; one period
//                               (2000 steps) per iteration
//   BM_row_moreau_step_apart/N  the same parts at pitch 0.6: no contact ever active, every
//                               part takes the lone 1-D step (checked before timing)
//   Counters: ns_per_part_step (CPU time / (2000 N)), chained (the mean fraction of the parts
//   in an active chain over the timed period), items = part-steps.
//   Each iteration restarts the row from the same state (s = s0: copy-assignment into the
//   sized workspace, no allocation), taken after kWarmPeriods periods from rest, so every
//   iteration runs the same period.
//
//   BM_row_exact_period         tests/test_rows.cpp's MoreauConvergesWithOrderOneOnAThreePart-
//                               QueueWithCollisions (e = 0): advance_row_exact over 5 periods
//                               (from make_row_exact_state) per iteration
//   BM_row_moreau_same_accuracy/n  core::step on the same queue over 5 periods at n steps per
//                               period (5 n steps per iteration); n = 1e3 and 1e5. Counter
//                               distance: the largest |x_moreau - x_exact| over the parts at the
//                               ends of periods 1..5 (as the test). The exact solver is accurate
//                               to about 1e-12; Moreau is order 1 (about 1e-3 at 1e3, 1e-5 at
//                               1e5), so even at 1e5 it is some 1e7 times less accurate.
// Summaries (medians, min-max over repetitions, time ratios): bench/rows_summary.py.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../tests/planar_profiles.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/simulate/row_exact.hpp"

// In a namespace of their own: the benchmark sources are compiled as one unity file.
namespace selfalign_rows_bench {
namespace {
using namespace selfalign;
using testing_support::kPaper;  // the paper's Sect. 7.2 three-phase profile, period 1

// ---- the queue's model: the library's row_model (analysis/row.hpp) ------------------------

constexpr double kLength = 0.3;

// A queue of parts of length kLength with these laws at leading edges x.
core::Model queue_of(const std::vector<FrictionLaw>& laws, const std::vector<double>& x,
                     long long steps_per_period) {
  RowQueue q;
  for (std::size_t i = 0; i < laws.size(); ++i) q.parts.push_back({kLength, 1.0, laws[i], x[i], 0.0});
  return row_model(kPaper, q, nullptr, steps_per_period);
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

// ---- BM_row_moreau_step(_apart) -------------------------------------------------------------

constexpr long long kStepsPerPeriod = 2000;
constexpr int kWarmPeriods = 3;

// N parts at `pitch`; at pitch == length the leading edges are placed so that each gap
// (x_front - length) - x_rear is >= 0 in floating point (0 or one ulp: x = i * 0.3 may round
// to an overlap of 1e-17, which make_state rejects).
std::vector<double> positions(int n, double pitch) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double xi = i * pitch;
    if (i > 0)
      while ((xi - kLength) - x[static_cast<std::size_t>(i - 1)] < 0) xi = std::nextafter(xi, 1e300);
    x[static_cast<std::size_t>(i)] = xi;
  }
  return x;
}

core::Model queue_model(int n, double pitch) {
  std::vector<FrictionLaw> laws;
  for (int i = 0; i < n; ++i) laws.push_back(FrictionLaw(1.2, 1.0 + 0.01 * (i % 3)));
  return queue_of(laws, positions(n, pitch), kStepsPerPeriod);
}

double min_gap(const core::Model& m, const core::State& s) {
  double g = 1e300;
  for (const auto& pc : m.part_contacts)
    g = std::min(g, (s.bodies[static_cast<std::size_t>(pc.front)].pose.x - kLength) -
                        s.bodies[static_cast<std::size_t>(pc.rear)].pose.x);
  return g;
}

void row_moreau_step(benchmark::State& st, double pitch) {
  const int n = static_cast<int>(st.range(0));
  const core::Model m = queue_model(n, pitch);
  core::State s0 = start(m, positions(n, pitch), std::vector<double>(static_cast<std::size_t>(n), 0.0));
  core::step(m, s0, kWarmPeriods * kStepsPerPeriod);
  // One untimed period step by step: the mean fraction of chained parts, and for the spaced
  // row that no contact became active (every part took the lone step).
  core::State s = s0;
  double chained = 0;
  for (long long k = 0; k < kStepsPerPeriod; ++k) {
    core::step(m, s, 1);
    long long c = 0;
    for (const signed char b : s.row.chained) c += b;
    chained += static_cast<double>(c) / n;
  }
  chained /= static_cast<double>(kStepsPerPeriod);
  if (s.status != core::StepStatus::ok) {
    st.SkipWithError("the row's step failed");
    return;
  }
  if (pitch > kLength && (chained != 0 || !(min_gap(m, s) > 0))) {
    st.SkipWithError("a contact of the spaced row became active");
    return;
  }
  for (auto _ : st) {
    s = s0;
    benchmark::DoNotOptimize(core::step(m, s, kStepsPerPeriod));
    benchmark::DoNotOptimize(s.bodies.back().pose.x);
  }
  const double per_iteration = static_cast<double>(kStepsPerPeriod) * n;
  st.SetItemsProcessed(st.iterations() * static_cast<long long>(per_iteration));
  // kIsIterationInvariantRate | kInvert: time / (value * iterations); value in 1e-9 units gives ns
  st.counters["ns_per_part_step"] = benchmark::Counter(
      per_iteration * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.counters["chained"] = chained;
}

void BM_row_moreau_step(benchmark::State& st) { row_moreau_step(st, kLength); }
void BM_row_moreau_step_apart(benchmark::State& st) { row_moreau_step(st, 2 * kLength); }

// ---- BM_row_exact_period vs BM_row_moreau_same_accuracy -------------------------------------

constexpr int kQueuePeriods = 5;
const std::vector<double> kQueueX{0.0, 0.35, 0.7}, kQueueV{0.0, 0.0, 0.0};

core::Model three_part_queue() {
  return queue_of({FrictionLaw(0.7, 0.4, 0.6), FrictionLaw(0.85, 0.75), FrictionLaw(1.1, 1.0)},
                  kQueueX, 1000);
}

void BM_row_exact_period(benchmark::State& st) {
  const core::Model m = three_part_queue();
  RowExactStatistics stats;
  for (auto _ : st) {
    RowExactState e = make_row_exact_state(m, 0.0, kQueueX, kQueueV);
    benchmark::DoNotOptimize(advance_row_exact(m, e, static_cast<double>(kQueuePeriods)));
    benchmark::DoNotOptimize(e.x.back());
    stats = e.statistics;
  }
  st.counters["periods"] = kQueuePeriods;
  st.counters["arcs"] = static_cast<double>(stats.arcs);
  st.counters["collisions"] = static_cast<double>(stats.collisions);
  st.counters["separations"] = static_cast<double>(stats.separations);
}

void BM_row_moreau_same_accuracy(benchmark::State& st) {
  const long long per_period = st.range(0);
  core::Model m = three_part_queue();
  m.options.step = 1.0 / static_cast<double>(per_period);
  // The distance to the exact row at the ends of periods 1..5 (tests/test_rows.cpp's
  // row_distance), untimed.
  double distance = 0;
  {
    core::State s = start(m, kQueueX, kQueueV);
    RowExactState e = make_row_exact_state(m, 0.0, kQueueX, kQueueV);
    for (int p = 1; p <= kQueuePeriods; ++p) {
      core::step(m, s, per_period);
      advance_row_exact(m, e, static_cast<double>(p));
      for (std::size_t i = 0; i < kQueueX.size(); ++i)
        distance = std::max(distance, std::abs(s.bodies[i].pose.x - e.x[i]));
    }
  }
  const core::State s0 = start(m, kQueueX, kQueueV);
  core::State s = s0;
  for (auto _ : st) {
    s = s0;
    benchmark::DoNotOptimize(core::step(m, s, kQueuePeriods * per_period));
    benchmark::DoNotOptimize(s.bodies.back().pose.x);
  }
  st.counters["periods"] = kQueuePeriods;
  st.counters["distance"] = distance;
  st.counters["ns_per_step"] = benchmark::Counter(
      static_cast<double>(kQueuePeriods * per_period) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_row_moreau_step)
    ->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_row_moreau_step_apart)
    ->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_row_exact_period)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_row_moreau_same_accuracy)
    ->Arg(1000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace selfalign_rows_bench
