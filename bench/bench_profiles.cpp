// Cost of evaluating table profiles (issue 9, D20: a Fourier profile of order 1000 took minutes
// in a steady-state search). FourierProfile::state sums the series with the rotation recurrence
// (two trigonometric calls per 16 harmonics); the bare loop beside it is the same sum with
// cos/sin of every harmonic, the former method. Report the ratio of the two from one run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "selfalign/profiles/fourier.hpp"

namespace {
using namespace selfalign;

std::vector<double> coefficients(int order) {
  std::vector<double> c(static_cast<std::size_t>(order));
  for (int k = 0; k < order; ++k) c[static_cast<std::size_t>(k)] = 0.01 / (k + 1);
  return c;
}

// The profile's own evaluation at 1000 times across a period.
void fourier_state(benchmark::State& st) {
  const int order = static_cast<int>(st.range(0));
  const FourierProfile profile(1.0, coefficients(order), coefficients(order));
  for (auto _ : st)
    for (int i = 0; i < 1000; ++i) benchmark::DoNotOptimize(profile.state(i * 1e-3).ydd);
  st.SetItemsProcessed(st.iterations() * 1000);
}

// The same sum, one cos and one sin per harmonic (the evaluation before issue 9).
void fourier_direct_trig(benchmark::State& st) {
  const int order = static_cast<int>(st.range(0));
  const std::vector<double> a = coefficients(order), b = coefficients(order);
  const double w = 2 * std::numbers::pi;
  for (auto _ : st)
    for (int i = 0; i < 1000; ++i) {
      const double t = i * 1e-3;
      double y = 0, yd = 0, ydd = 0;
      for (int k = 0; k < order; ++k) {
        const double kw = (k + 1) * w, c = std::cos(kw * t), s = std::sin(kw * t);
        y += a[static_cast<std::size_t>(k)] * c + b[static_cast<std::size_t>(k)] * s;
        yd += kw * (-a[static_cast<std::size_t>(k)] * s + b[static_cast<std::size_t>(k)] * c);
        ydd -= kw * kw * (a[static_cast<std::size_t>(k)] * c + b[static_cast<std::size_t>(k)] * s);
      }
      benchmark::DoNotOptimize(y + yd + ydd);
    }
  st.SetItemsProcessed(st.iterations() * 1000);
}

BENCHMARK(fourier_state)->Arg(12)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(fourier_direct_trig)->Arg(12)->Arg(1000)->Unit(benchmark::kMicrosecond);
}  // namespace
