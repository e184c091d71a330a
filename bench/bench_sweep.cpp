// Issue 3: f and the motion case on an n x n (y2'', y3'') grid at Δt = 1, Δy = 0.084 over
// (0, 3]^2 (target then: 1000 x 1000 under 2 s wall on 2 cores, by the search).
// Issue 22 item 3: the same grids with closed-form cells (three_phase_steady_state): 10^6
// cells <= 100 ms in-process on 2 threads, the cost per cell flat (+-10 %) from 10^4 to 10^6.
// Args: {n, threads, closed_form}. Counters: ns of thread time per cell.
// sweep_grid returns the vector of AccelerationCell (88 bytes a cell, first touched by the
// calling thread); sweep_grid_columns hands each cell to a sink writing five columns allocated
// uninitialised, as the Python binding and the CLI's table do (first touched by the workers).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/analysis/sweep.hpp"

namespace bench_sweep {
using namespace selfalign;

// Thread time per cell [ns]: wall time x threads / cells, per iteration.
void thread_ns_per_cell(benchmark::State& st, double cells, int threads) {
  st.counters["thread_ns_per_cell"] =
      benchmark::Counter(cells / 1e9 / static_cast<double>(threads),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void sweep_grid(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::vector<double> g = linear_grid(3.0 / n, 3.0, n);
  SweepOptions o;
  o.threads = static_cast<int>(st.range(1));
  o.closed_form = st.range(2) != 0;
  std::size_t physical = 0;
  for (auto _ : st) {
    const auto cells = sweep_accelerations(1.0, 0.084, g, g, o);
    physical = 0;
    for (const auto& c : cells) physical += c.predicted != StickSlipCase::non_physical;
    benchmark::DoNotOptimize(cells.data());
  }
  st.counters["cells"] = static_cast<double>(n) * n;
  st.counters["physical_cells"] = static_cast<double>(physical);
  thread_ns_per_cell(st, static_cast<double>(n) * n, o.threads);
}
BENCHMARK(sweep_grid)
    ->ArgNames({"n", "threads", "closed_form"})
    ->Args({1000, 2, 0})
    ->Args({1000, 1, 0})
    ->Args({100, 2, 1})
    ->Args({316, 2, 1})
    ->Args({1000, 2, 1})
    ->Args({1000, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void sweep_grid_columns(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::vector<double> g = linear_grid(3.0 / n, 3.0, n);
  SweepOptions o;
  o.threads = static_cast<int>(st.range(1));
  if (st.range(2) != 0) o.progress = [](std::size_t, std::size_t) {};  // as the front ends
  const std::size_t cells = static_cast<std::size_t>(n) * n;
  for (auto _ : st) {
    std::unique_ptr<double[]> v_bar(new double[cells]), f(new double[cells]),
        x0(new double[cells]);
    std::unique_ptr<std::int32_t[]> prior(new std::int32_t[cells]),
        observed(new std::int32_t[cells]);
    sweep_accelerations(1.0, 0.084, g, g, o, [&](std::size_t k, const AccelerationCell& c) {
      v_bar[k] = c.v_bar, f[k] = c.f, x0[k] = c.x_dot_0s;
      prior[k] = static_cast<std::int32_t>(c.predicted);
      observed[k] = static_cast<std::int32_t>(c.observed);
    });
    benchmark::DoNotOptimize(v_bar.get());
  }
  st.counters["cells"] = static_cast<double>(cells);
  thread_ns_per_cell(st, static_cast<double>(cells), o.threads);
}
BENCHMARK(sweep_grid_columns)
    ->ArgNames({"n", "threads", "progress"})
    ->Args({100, 2, 0})
    ->Args({316, 2, 0})
    ->Args({1000, 2, 0})
    ->Args({1000, 1, 0})
    ->Args({100, 2, 1})
    ->Args({1000, 2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// Issue 23: a feeder regime chart over (vibration angle, machine number), n x n cells, each
// the closed-form regime and a run of 10 periods from rest: by the exact feeder solver
// (moreau 0, the chart's default) or the contact core with Moreau-Jean flight (moreau 1, 200
// steps per period); target: 200 x 200 on 2 cores <= 2 s. Args: {n, threads, moreau}.
void feeder_chart(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  std::vector<double> angles, ks;
  for (int i = 0; i < n; ++i) angles.push_back(-1.2 + 2.4 * (i + 0.5) / n);
  for (int i = 0; i < n; ++i) ks.push_back(0.1 * std::pow(100.0, (i + 0.5) / n));  // 0.1 .. 10
  FeederChartOptions o;
  o.threads = static_cast<int>(st.range(1));
  o.method = st.range(2) == 0 ? Method::exact : Method::time_stepping;
  long long hopping = 0;
  for (auto _ : st) {
    const auto cells = feeder_regime_chart(angles, ks, o);
    hopping = 0;
    for (const auto& c : cells) hopping += c.regime == FeederRegime::hopping;
    benchmark::DoNotOptimize(cells.data());
  }
  st.counters["cells"] = static_cast<double>(n) * n;
  st.counters["hopping_cells"] = static_cast<double>(hopping);
  thread_ns_per_cell(st, static_cast<double>(n) * n, o.threads);
}
BENCHMARK(feeder_chart)
    ->ArgNames({"n", "threads", "moreau"})
    ->Args({200, 2, 0})
    ->Args({200, 1, 0})
    ->Args({200, 2, 1})
    ->Args({200, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace bench_sweep
