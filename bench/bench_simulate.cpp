// Cost of the two solvers (issue 2): the exact solver per table period and Moreau
// time-stepping per step, uniform friction, three-phase profile of Sect. 7.2.
#include <benchmark/benchmark.h>

#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace {
using namespace selfalign;

// Settings of each motion case at (Δt, Δy) (see tests/test_time_stepping.cpp for their cases).
const ThreePhaseParameters kCase1{1.0, 0.084, 3.0, 0.9};
const ThreePhaseParameters kCase3{1.0, 0.084, 2.3, 1.3};

void exact_per_period(benchmark::State& st, ThreePhaseParameters params) {
  const ThreePhaseProfile profile(params);
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_polynomial(), *friction.piecewise_affine()};
  const long long periods = 1000;
  std::size_t arcs = 0;
  for (auto _ : st) {
    ExactState s = make_exact_state(setup, {0, 0, 0});
    arcs += advance_exact(setup, s, static_cast<double>(periods) * params.period);
    benchmark::DoNotOptimize(s.object.x);
  }
  st.SetItemsProcessed(st.iterations() * periods);
  st.counters["ns_per_period"] = benchmark::Counter(
      static_cast<double>(st.iterations() * periods),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["arcs_per_period"] =
      static_cast<double>(arcs) / static_cast<double>(st.iterations() * periods);
}

void time_stepping_per_step(benchmark::State& st, ThreePhaseParameters params) {
  const ThreePhaseProfile profile(params);
  const UniformFriction friction;
  const TimeSteppingOptions options{1e-4, 0.5};
  const long long steps = 100000;
  for (auto _ : st) {
    TimeSteppingState s = make_time_stepping_state(profile, {0, 0, 0});
    advance_time_stepping(profile, friction, options, s, steps);
    benchmark::DoNotOptimize(s.object.x);
  }
  st.SetItemsProcessed(st.iterations() * steps);
  st.counters["ns_per_step"] = benchmark::Counter(
      static_cast<double>(st.iterations() * steps),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(exact_per_period, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(exact_per_period, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(time_stepping_per_step, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(time_stepping_per_step, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
}  // namespace
