// Issue 3: f and the motion case on a 1000 x 1000 (y2'', y3'') grid at Δt = 1, Δy = 0.084 over
// (0, 3]^2, with the exact solver, on all cores (target: under 2 s wall on 2 cores).
#include <benchmark/benchmark.h>

#include "selfalign/analysis/sweep.hpp"

namespace {
using namespace selfalign;

void sweep_grid(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::vector<double> g = linear_grid(3.0 / n, 3.0, n);
  SweepOptions o;
  o.threads = static_cast<int>(st.range(1));
  std::size_t physical = 0;
  for (auto _ : st) {
    const auto cells = sweep_accelerations(1.0, 0.084, g, g, o);
    physical = 0;
    for (const auto& c : cells) physical += c.predicted != StickSlipCase::non_physical;
    benchmark::DoNotOptimize(cells.data());
  }
  st.counters["cells"] = static_cast<double>(n) * n;
  st.counters["physical_cells"] = static_cast<double>(physical);
  st.counters["thread_time_per_cell"] =
      benchmark::Counter(static_cast<double>(n) * n * static_cast<double>(o.threads),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert,
                         benchmark::Counter::kIs1000);
}
BENCHMARK(sweep_grid)
    ->Args({1000, 2})
    ->Args({1000, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
}  // namespace
