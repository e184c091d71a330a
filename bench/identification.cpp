// Identification (issue 25): the fit of 10 s of 2 kHz data (20 000 samples, 200 shooting
// windows of one period) with three free parameters (mu, mu_static, time_offset), local stage
// only (starts 0, no profile), two threads; against one pass of the model over the same 10 s
// at the same samples (one simulate() run), in the same binary, so that "fit / pass" is a
// ratio from one run. docs/identification.md quotes the figures.

#include <benchmark/benchmark.h>

#include <random>

#include "selfalign/identify/identification.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::bench_identification {
namespace {

SimulateConfig model_config(double mu, double mu_static) {
  SimulateConfig c;
  c.units = "si";
  c.profile = "three-phase";
  c.period = 0.05;
  c.stroke = 6.2e-4, c.a2 = 6.77, c.a3 = 3.83, c.jerk = 800;
  c.friction = "uniform";
  c.mu = mu, c.mu_static = mu_static, c.g = 9.81, c.length_scale = 1e-3;
  c.x0 = 0, c.v0 = 0;
  return c;
}

// 10 s at 2 kHz of the truth (mu 0.3, mu_static 0.36), noise 2 um, clock 3 ms behind.
const MeasuredMotion& data() {
  static const MeasuredMotion d = [] {
    SimulateConfig c = model_config(0.3, 0.36);
    c.periods = 200;
    c.output_step = 5e-4;
    const SimulateModel m = build_simulate_model(c);
    const SimulationResult r = simulate(*m.profile, *m.friction, m.law, m.initial, m.options);
    const OutputUnits out = m.output_units();
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0, 2e-6);
    MeasuredMotion d;
    d.source = "bench";
    for (std::size_t i = 0; i + 1 < r.trajectory.size(); ++i) {
      d.t.push_back(out.time(r.trajectory.t[i]) - 3e-3);
      d.x.push_back(out.length(r.trajectory.x[i]) + noise(rng));
      d.line.push_back(i);
    }
    return d;
  }();
  return d;
}

void BM_IdentifyTenSecondsAtTwoKilohertzThreeParameters(benchmark::State& state) {
  IdentificationOptions o;
  o.free = {"mu", "mu_static", kTimeOffset};
  o.starts = 0;
  o.threads = 2;
  const std::vector<IdentificationRun> runs{{data(), model_config(0.31, 0.34)}};
  for (auto _ : state) {
    const Identification r = identify(runs, o);
    benchmark::DoNotOptimize(r.sigma);
  }
  state.counters["samples"] = static_cast<double>(data().t.size());
}
BENCHMARK(BM_IdentifyTenSecondsAtTwoKilohertzThreeParameters)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The floor: one pass of the model over the same 10 s at the same 20 000 samples.
void BM_OnePassOfTheModelOverTheData(benchmark::State& state) {
  SimulateConfig c = model_config(0.3, 0.36);
  c.periods = 200;
  c.output_step = 5e-4;
  const SimulateModel m = build_simulate_model(c);
  for (auto _ : state) {
    const SimulationResult r = simulate(*m.profile, *m.friction, m.law, m.initial, m.options);
    benchmark::DoNotOptimize(r.final_state.x);
  }
}
BENCHMARK(BM_OnePassOfTheModelOverTheData)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace selfalign::bench_identification
