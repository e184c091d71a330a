// Issue 4: the four Fig. 17 surfaces (f, case, accumulation, Δx_d) on a 200 x 200 (y2'', y3'')
// grid over (0, 2.5]^2 with 100 steady-state entries per cell, at Δt = 1, Δy = 0.084,
// w = 0.05, c_mu = 2.5 (target: under 10 s wall on 2 cores).
#include <benchmark/benchmark.h>

#include "selfalign/analysis/positioning.hpp"

namespace {
using namespace selfalign;

void fig17_surfaces(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::vector<double> g = linear_grid(2.5 / n, 2.5, n);
  PositioningOptions o;
  o.entries = 100;
  o.stopping.max_periods = 300;
  SweepOptions sweep;
  sweep.threads = static_cast<int>(st.range(1));
  std::size_t accumulating = 0, arrived = 0;
  for (auto _ : st) {
    const auto cells = positioning_surfaces(1.0, 0.084, 0.05, 2.5, g, g, o, sweep);
    accumulating = arrived = 0;
    for (const auto& c : cells) {
      accumulating += c.accumulates;
      arrived += c.dx_d == c.dx_d;  // not NaN
    }
    benchmark::DoNotOptimize(cells.data());
  }
  st.counters["cells"] = static_cast<double>(n) * n;
  st.counters["cells_arriving"] = static_cast<double>(arrived);
  st.counters["cells_accumulating"] = static_cast<double>(accumulating);
}
BENCHMARK(fig17_surfaces)->Args({200, 2})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
}  // namespace
