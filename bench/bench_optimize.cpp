// Profile design at the paper's Fig. 6 setting (Δt = 0.072, Δy = 0.021, y'_max = 3.2,
// y''_max = 1275): wall time of each family's optimiser and the f it reaches (counters).
#include <benchmark/benchmark.h>

#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"

namespace {
using namespace selfalign;

void report(benchmark::State& st, const OptimizationResult& r) {
  st.counters["f"] = r.f;
  st.counters["v_bar"] = r.v_bar;
  st.counters["feasible"] = r.feasible ? 1 : 0;
  st.counters["evaluations"] = r.evaluations;
}

void optimize_three_phase_fig6(benchmark::State& st) {
  OptimizationResult r;
  for (auto _ : st) r = optimize_three_phase(ActuatorLimits{});
  report(st, r);
}

void optimize_piecewise_fig6(benchmark::State& st) {
  OptimizeOptions o;
  o.segments = static_cast<int>(st.range(0));
  const OptimizationResult three = optimize_three_phase(ActuatorLimits{}, o);
  OptimizationResult r;
  for (auto _ : st) r = optimize_piecewise_constant(ActuatorLimits{}, o, &three);
  report(st, r);
}

void optimize_fourier_fig6(benchmark::State& st) {
  OptimizeOptions o;
  o.order = static_cast<int>(st.range(0));
  const OptimizationResult three = optimize_three_phase(ActuatorLimits{}, o);
  OptimizationResult r;
  for (auto _ : st) r = optimize_fourier(ActuatorLimits{}, o, &three);
  report(st, r);
}

BENCHMARK(optimize_three_phase_fig6)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(optimize_piecewise_fig6)->Arg(3)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(optimize_fourier_fig6)->Arg(12)->Unit(benchmark::kMillisecond)->Iterations(1);
}  // namespace
