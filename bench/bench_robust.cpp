// Monte Carlo of the task (a 20 g part, mu 0.2 +-5%, c_mu 2.5 +-5% (1 sd), 3 mm
// transition, 40 mm to go, +-0.1 mm): 1e5 stopping runs on the worker threads, and the same
// runs' periods advanced by the bare exact solver (advance_exact on the two-region table, no
// stopping machinery) to set the cost per run beside the solver's own.
//
//   build/release/bench/selfalign_bench_robust --benchmark_repetitions=5
//
// Two processes: the nominal design of `selfalign design` (y2'' = c_mu mu g: half the runs
// never stop, proven at entry) and the best profile `design --robust` finds (P = 0.62: nearly
// every run stops).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "selfalign/friction/friction_field.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

constexpr int kRuns = 100'000;

DesignRequest task() {
  DesignRequest q;
  q.mass = 0.02, q.width = 0.003, q.mu = 0.2, q.c_mu = 2.5, q.distance = 0.04;
  q.stroke_max = 0.002, q.acceleration_max = 50, q.frequency_max = 30, q.tolerance = 1e-4;
  return q;
}

ProcessUncertainty uncertainty() {
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  return u;
}

constexpr double kInf = std::numeric_limits<double>::infinity();
// `selfalign design` for the task (nominal), and `design --robust`'s best profile.
const Process kNominal{0.09767186838611738, 0.002, 4.905, 2.6568750000000003, kInf, 0.037};
const Process kRobust{0.13976542375431586, 0.002, 2.20725, 1.430625, kInf, 0.03978243633555542};

void monte_carlo_runs(benchmark::State& st, const Process& p) {
  MonteCarloOptions o;
  o.runs = static_cast<int>(st.range(0));
  o.threads = static_cast<int>(st.range(1));
  MonteCarloResult r;
  for (auto _ : st) {
    r = monte_carlo(task(), p, uncertainty(), o);
    benchmark::DoNotOptimize(r);
  }
  st.counters["p_stop"] = r.p_stop;
  st.counters["us_per_run"] = benchmark::Counter(
      static_cast<double>(st.iterations()) * o.runs * 1e-6,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The same runs (draws), each advanced by advance_exact for the periods its stopping run
// covered: to the stop (T_p, or 0.999 of the way for accumulation) or, for a run that never
// stops, to its entry; on one thread.
void bare_exact_same_periods(benchmark::State& st, const Process& p) {
  const DesignRequest q = task();
  const ProcessUncertainty u = uncertainty();
  const int runs = static_cast<int>(st.range(0));
  MonteCarloOptions o;
  o.runs = runs;
  const MonteCarloResult mc = monte_carlo(q, p, u, o);
  struct Run {
    std::unique_ptr<ThreePhaseProfile> profile;
    FieldFriction friction;
    double t_end;
  };
  std::vector<Run> prepared;
  double periods = 0;
  for (int i = 0; i < runs; ++i) {
    const InputValues v = draw_inputs(q, u, 1, static_cast<std::uint64_t>(i));
    const Scales sc(v[3], v[0], q.gravity);
    auto profile = std::make_unique<ThreePhaseProfile>(ThreePhaseParameters{
        sc.time_from_si(p.period), sc.length_from_si(p.stroke), sc.acceleration_from_si(p.a2),
        sc.acceleration_from_si(p.a3)});
    const double t_si = std::isnan(mc.process_time[static_cast<std::size_t>(i)])
                            ? mc.entry_time[static_cast<std::size_t>(i)]
                            : mc.process_time[static_cast<std::size_t>(i)];
    const double P = profile->period();
    // A run that never entered stopped at a repeated state: at least one period.
    const double t_end = std::isnan(t_si) ? P : std::max(1.0, std::ceil(sc.time_from_si(t_si) / P)) * P;
    periods += t_end / P;
    prepared.push_back({std::move(profile), two_region_friction(sc.length_from_si(p.x_mu), 1.0, v[1]),
                        t_end});
  }
  for (auto _ : st)
    for (const Run& r : prepared) {
      const ExactSetup setup{*r.profile->piecewise_polynomial(), *r.friction.piecewise_affine()};
      ExactState s = make_exact_state(setup, {0, 0, 0});
      advance_exact(setup, s, r.t_end);
      benchmark::DoNotOptimize(s);
    }
  st.counters["periods_per_run"] = periods / runs;
  st.counters["us_per_run"] = benchmark::Counter(
      static_cast<double>(st.iterations()) * runs * 1e-6,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(monte_carlo_runs, robust_1e5_2threads, kRobust)
    ->Args({kRuns, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(monte_carlo_runs, robust_1e4_1thread, kRobust)
    ->Args({kRuns / 10, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(bare_exact_same_periods, robust_1e4, kRobust)
    ->Args({kRuns / 10})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(monte_carlo_runs, nominal_1e5_2threads, kNominal)
    ->Args({kRuns, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(monte_carlo_runs, nominal_1e4_1thread, kNominal)
    ->Args({kRuns / 10, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(bare_exact_same_periods, nominal_1e4, kNominal)
    ->Args({kRuns / 10})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace selfalign
