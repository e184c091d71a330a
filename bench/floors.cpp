// Floors (issue 22, item 1): for each solver, a minimal loop written from the equations, not
// from the library's code path, in the same binary as the library's benchmarks
// (bench_simulate.cpp), so that "library / floor" is the distance to what the computation
// costs at least. The existing bare_* partners transliterate the library's loops and measure
// its dispatch overhead; these measure the distance to the floor.
//   floor_exact_per_period/X        the three-phase walk: per period three constant table
//                                   accelerations (0, -a2, +a3 over the appendix's t1, t2 - t1,
//                                   t3 - t2), per arc one closed-form parabola, local time only
//   floor_time_stepping_per_step/X  Moreau (time_stepping.hpp) with the table velocity from
//                                   the segment the step lands in, tracked as t advances (no
//                                   division, no search), the projection inlined
//   floor_planar_point_per_step     the planar point step, the same tracking, |v| by sqrt
// Before timing, each floor is checked once against the library's run (final state within
// 1e-12 (1 + |.|)); a floor that disagrees is skipped with an error.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "selfalign/friction/friction_map.hpp"
#include "selfalign/planar/planar_point.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/time_stepping.hpp"

// In a namespace of their own: the benchmark sources are compiled as one unity file.
namespace selfalign_floors {
namespace {
using namespace selfalign;

const ThreePhaseParameters kCase1{1.0, 0.084, 3.0, 0.9};
const ThreePhaseParameters kCase3{1.0, 0.084, 2.3, 1.3};
constexpr long long kPeriods = 1000;  // as bench_simulate.cpp
constexpr long long kSteps = 100000;
constexpr double kH = 1e-4, kTheta = 0.5;

bool close(double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(a)); }

// The one-off check of a floor: the library's final (x, x') and the floor's agree, else the
// benchmark is skipped with an error; the position difference is reported as check_dx.
bool agrees(benchmark::State& st, const std::string& what, double lib_x, double lib_v, double x,
            double v) {
  if (!(close(lib_x, x) && close(lib_v, v))) {
    st.SkipWithError((what + " floor differs: x " + std::to_string(lib_x) + " vs " +
                      std::to_string(x))
                         .c_str());
    return false;
  }
  st.counters["check_dx"] = std::abs(lib_x - x);
  return true;
}

// The three segments of a three-phase profile from its closed form (appendix): accelerations,
// start phases, durations, and the table velocity at each start.
struct Phases {
  std::array<double, 3> accel, begin, duration, yd;
  double period;
};
Phases phases(const ThreePhaseProfile& p) {
  const ThreePhaseSolution& s = p.solution();
  const ThreePhaseParameters& q = p.parameters();
  Phases f{{0.0, -q.a2, q.a3}, {0.0, s.t1, s.t2}, {s.t1, s.t2 - s.t1, s.t3 - s.t2}, {}, s.t3};
  f.yd = {s.yd_ini, s.yd_ini, s.yd_ini - q.a2 * (s.t2 - s.t1)};
  return f;
}

// ---- Exact: parabolic arcs ------------------------------------------------------------------
// Relative motion x under the paper's law with level m: slipping (sigma = sign x'),
// x'' = -A - sigma m; at rest, held while |A| <= m, else slipping with sigma = -sign A.
[[gnu::noinline]] long long floor_exact(const Phases& f, double m, long long periods, double& x,
                                        double& v) {
  long long arcs = 0;
  for (long long n = 0; n < periods; ++n)
    for (int j = 0; j < 3; ++j) {
      const double A = f.accel[j];
      double left = f.duration[j];
      while (left > 0) {
        ++arcs;
        double sigma;
        if (v == 0) {
          if (std::abs(A) <= m) break;  // held to the segment's end
          sigma = A > 0 ? -1.0 : 1.0;
        } else {
          sigma = v > 0 ? 1.0 : -1.0;
        }
        const double a = -A - sigma * m;
        const double tau = sigma * a < 0 ? -v / a : left + 1;  // when x' = 0, if it decelerates
        if (tau <= left) {
          x += tau * (v + 0.5 * a * tau);
          v = 0;
          left -= tau;
        } else {
          x += left * (v + 0.5 * a * left);
          v += a * left;
          left = 0;
        }
      }
    }
  return arcs;
}

void floor_exact_per_period(benchmark::State& st, ThreePhaseParameters params) {
  const ThreePhaseProfile profile(params);
  const Phases f = phases(profile);
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_polynomial(), *friction.piecewise_affine()};
  ExactState lib = make_exact_state(setup, {0, 0, 0});
  advance_exact(setup, lib, static_cast<double>(kPeriods) * setup.profile.period());
  double x = 0, v = 0;
  floor_exact(f, 1.0, kPeriods, x, v);
  if (!agrees(st, "exact", lib.object.x, lib.object.xd, x, v)) return;
  double m = 1.0;
  long long arcs = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    double xi = 0, vi = 0;
    arcs += floor_exact(f, m, kPeriods, xi, vi);
    benchmark::DoNotOptimize(xi);
    benchmark::DoNotOptimize(vi);
  }
  st.SetItemsProcessed(st.iterations() * kPeriods);
  st.counters["arcs_per_period"] =
      static_cast<double>(arcs) / static_cast<double>(st.iterations() * kPeriods);
}

// ---- Moreau: the table velocity tracked ----------------------------------------------------
// The table velocity at t = k h: the phase t - n P and the segment it lies in advance with t.
struct Tracker {
  const Phases& f;
  long long n = 0;
  int i = 0;
  double velocity(double t) {
    double ph = t - static_cast<double>(n) * f.period;
    while (ph >= f.period) {
      ++n;
      i = 0;
      ph = t - static_cast<double>(n) * f.period;
    }
    while (i < 2 && ph >= f.begin[i + 1]) ++i;
    return f.yd[i] + f.accel[i] * (ph - f.begin[i]);
  }
};

[[gnu::noinline]] void floor_moreau(const Phases& f, double m, long long steps, double& x,
                                    double& v) {
  Tracker track{f};
  double yd = track.velocity(0.0);
  const double hold = kH * m;  // the paper's law: static = kinetic = 1
  for (long long k = 1; k <= steps; ++k) {
    const double yd1 = track.velocity(static_cast<double>(k) * kH);
    const double w = v - (yd1 - yd);
    const double v1 = w > hold ? w - hold : w < -hold ? w + hold : 0.0;
    x += kH * ((1 - kTheta) * v + kTheta * v1);
    v = v1;
    yd = yd1;
  }
}

void floor_time_stepping_per_step(benchmark::State& st, ThreePhaseParameters params) {
  const ThreePhaseProfile profile(params);
  const Phases f = phases(profile);
  TimeSteppingState lib = make_time_stepping_state(profile, {0, 0, 0});
  advance_time_stepping(profile, UniformFriction(), FrictionLaw{}, {kH, kTheta}, lib, kSteps);
  double x = 0, v = 0;
  floor_moreau(f, 1.0, kSteps, x, v);
  if (!agrees(st, "Moreau", lib.object.x, lib.object.xd, x, v)) return;
  double m = 1.0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    double xi = 0, vi = 0;
    floor_moreau(f, m, kSteps, xi, vi);
    benchmark::DoNotOptimize(xi);
    benchmark::DoNotOptimize(vi);
  }
  st.SetItemsProcessed(st.iterations() * kSteps);
}

// ---- Planar point: the disc projection with sqrt -------------------------------------------
const FrictionLaw kPlanarLaw(1.3, 1.0);  // as bench_simulate.cpp

[[gnu::noinline]] std::array<double, 4> floor_planar(const Phases& fx, const Phases& fy,
                                                     double m) {
  const double s = kPlanarLaw.static_coefficient(), k = kPlanarLaw.kinetic_forward();
  const double hold_stick = kH * (s * m), hold_slip = kH * (k * m);
  Tracker tx{fx}, ty{fy};
  double x = 0, y = 0, ux = 0, uy = 0;
  double tvx = tx.velocity(0.0), tvy = ty.velocity(0.0);
  for (long long i = 1; i <= kSteps; ++i) {
    const double t = static_cast<double>(i) * kH;
    const double tvx1 = tx.velocity(t), tvy1 = ty.velocity(t);
    const double vx = ux - (tvx1 - tvx), vy = uy - (tvy1 - tvy);
    const double speed = std::sqrt(vx * vx + vy * vy);
    const double hold = vx * ux + vy * uy > 0 ? hold_slip : hold_stick;
    double ux1 = 0, uy1 = 0;
    if (speed > hold) {
      const double keep = 1 - hold_slip / speed;
      ux1 = vx * keep;
      uy1 = vy * keep;
    }
    x += kH * ((1 - kTheta) * ux + kTheta * ux1);
    y += kH * ((1 - kTheta) * uy + kTheta * uy1);
    ux = ux1, uy = uy1, tvx = tvx1, tvy = tvy1;
  }
  return {x, y, ux, uy};
}

void floor_planar_point_per_step(benchmark::State& st) {
  const ThreePhaseProfile px(kCase3), py(kCase1);
  const Phases fx = phases(px), fy = phases(py);
  PlanarTableMotion motion;
  motion.first = &px;
  motion.second = &py;
  PlanarPointState lib = make_planar_point_state(motion, 0, 0, 0, 0, 0);
  advance_planar_point(motion, UniformPlanarField{1.0}, kPlanarLaw, {kH, kTheta}, lib, kSteps);
  const std::array<double, 4> r = floor_planar(fx, fy, 1.0);
  if (!(close(lib.x, r[0]) && close(lib.y, r[1]))) {
    st.SkipWithError(("planar floor differs: x " + std::to_string(lib.x) + " vs " +
                      std::to_string(r[0]))
                         .c_str());
    return;
  }
  st.counters["check_dx"] = std::abs(lib.x - r[0]) + std::abs(lib.y - r[1]);
  double m = 1.0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    const std::array<double, 4> out = floor_planar(fx, fy, m);
    benchmark::DoNotOptimize(out);
  }
  st.SetItemsProcessed(st.iterations() * kSteps);
}

BENCHMARK_CAPTURE(floor_exact_per_period, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(floor_exact_per_period, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(floor_time_stepping_per_step, case1_uniform, kCase1)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(floor_time_stepping_per_step, case3_uniform, kCase3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(floor_planar_point_per_step)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace selfalign_floors
