// Cost of the two solvers (issue 2): the exact solver per table period and Moreau
// time-stepping per step, uniform friction, three-phase profile of Sect. 7.2, and the exact
// solver under finite jerk (jerk-limited three-phase, Sect. 8 item 2).
//
// Each library benchmark has a bare, single-purpose loop of the same computation beside it
// (bare_*), so the library's overhead is a ratio measured in one run of this binary:
//   exact_per_period/X         vs  bare_exact_per_period/X
//   time_stepping_per_step/X   vs  bare_time_stepping_per_step/X_inlined     (profile velocity
//                                  inlined) and .../X_ppvelocity (PiecewisePolynomialProfile::
//                                  velocity called directly, no virtual dispatch)
// Before timing, every benchmark checks once that the library and its bare loop end in the
// same state (|dx|, |dx'|, |dt| <= 1e-12 (1 + |.|)) and the same arc count, else it is skipped
// with an error. Reproduce the ratios with
//   selfalign_bench_simulate --benchmark_repetitions=9 --benchmark_min_time=0.2
//     --benchmark_enable_random_interleaving=true --benchmark_out=sim.json
//     --benchmark_out_format=json
// and divide the per-repetition CPU times of each pair (repetition i by repetition i; real time
// is noisy when other processes share the cores).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "../tests/opaque_profile.hpp"  // the tests' closed-form-hiding wrapper
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/time_stepping.hpp"
#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/planar/planar_point.hpp"
#include "selfalign/planar/planar_patch_integrator.hpp"
#include "selfalign/planar/planar_rigid.hpp"

namespace {
using namespace selfalign;

// Settings of each motion case at (Δt, Δy) (see tests/test_time_stepping.cpp for their cases).
const ThreePhaseParameters kCase1{1.0, 0.084, 3.0, 0.9};
const ThreePhaseParameters kCase3{1.0, 0.084, 2.3, 1.3};
// Jerk 50: the slip arcs on the ramps all run to the ramp's end (no stop found by the certified
// scan); jerk 12 (min 10.04): one slip per period stops inside a ramp (a bracketed root).
const JerkLimitedThreePhaseParameters kCase3Jerk50{1.0, 0.084, 2.3, 1.3, 50.0};
const JerkLimitedThreePhaseParameters kCase3Jerk12{1.0, 0.084, 2.3, 1.3, 12.0};

constexpr long long kPeriods = 1000;   // exact solver: periods per iteration, from rest
constexpr long long kSteps = 100000;   // time-stepping: steps per iteration, from rest
const TimeSteppingOptions kStepOptions{1e-4, 0.5};
constexpr double kInf = std::numeric_limits<double>::infinity();

void per_item_counters(benchmark::State& st, long long per_iteration, const char* name) {
  st.SetItemsProcessed(st.iterations() * per_iteration);
  st.counters[name] = benchmark::Counter(static_cast<double>(st.iterations() * per_iteration),
                                         benchmark::Counter::kIsRate |
                                             benchmark::Counter::kInvert);
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(a)); }

// ---- Bare loops -------------------------------------------------------------------------------

// A copy of the profile's segments, the only data the bare loops read.
struct BareSegment {
  double begin, accel, jerk, yd;
};
struct BareProfile {
  std::vector<BareSegment> segs;
  double period;
};
BareProfile bare_profile(const PiecewisePolynomialProfile& p) {
  BareProfile b{{}, p.period()};
  for (const AccelerationSegment& s : p.segments()) b.segs.push_back({s.begin, s.accel, s.jerk, s.yd});
  return b;
}

struct BareState {
  double t = 0, x = 0, v = 0;
  std::size_t si = 0;
  long long n = 0;
};

// Exact solution, piecewise-constant table acceleration, constant friction bound m, paper's
// law (static = kinetic): per segment, stick while |A| <= m, else parabolic arcs
// x'' = -sigma m - A ending at the segment end or at the stop time v/|x''|.
[[gnu::noinline]] std::size_t bare_parabolic(const BareProfile& p, double m, BareState& s,
                                             double t_end) {
  const BareSegment* segs = p.segs.data();
  const std::size_t nseg = p.segs.size();
  const double P = p.period;
  double t = s.t, x = s.x, v = s.v;
  std::size_t si = s.si, count = 0;
  long long n = s.n;
  while (t < t_end) {
    const double period_start = static_cast<double>(n) * P;
    const double seg_end = si + 1 < nseg ? period_start + segs[si + 1].begin : period_start + P;
    const double A = segs[si].accel;
    const bool to_switch = seg_end <= t_end;
    const double t_stop = to_switch ? seg_end : t_end;
    while (t < t_stop) {
      ++count;
      int sigma;
      if (v == 0) {
        if (std::abs(A) <= m) {  // stick for the rest of the segment
          t = t_stop;
          break;
        }
        sigma = A > 0 ? -1 : 1;
      } else {
        sigma = v > 0 ? 1 : -1;
      }
      const double a = -sigma * m - A;
      const double sv = sigma * v, sa = sigma * a;
      double tau = t_stop - t;
      bool stop = false;
      if (sa < 0 && sv / -sa <= tau) {
        tau = sv / -sa;
        stop = true;
      }
      x = x + tau * (v + 0.5 * a * tau);
      v = stop ? 0.0 : v + a * tau;
      if ((v > 0 && sigma < 0) || (v < 0 && sigma > 0)) v = 0;
      t = stop ? t + tau : t_stop;
    }
    if (to_switch && ++si == nseg) {
      si = 0;
      ++n;
    }
  }
  s = {t, x, v, si, n};
  return count;
}

// Smallest tau > 0 where c + b tau + a tau^2 (c >= 0) reaches 0; inf if none.
inline double first_zero(double a, double b, double c) {
  if (a == 0) return b < 0 ? c / -b : kInf;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return kInf;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0) return kInf;  // double root at 0
  const double r1 = q / a, r2 = c / q;
  double r = kInf;
  if (r1 > 0) r = r1;
  if (r2 > 0 && r2 < r) r = r2;
  return r;
}

// Exact solution, piecewise-affine table acceleration A0 + J tau (finite jerk), constant
// friction bound m, paper's law: cubic arcs x'' = q0 - J tau, the stop as the root of the
// velocity's quadratic, the stick break where the linear |A| reaches m.
[[gnu::noinline]] std::size_t bare_cubic(const BareProfile& p, double m, BareState& s,
                                         double t_end) {
  const BareSegment* segs = p.segs.data();
  const std::size_t nseg = p.segs.size();
  const double P = p.period;
  double t = s.t, x = s.x, v = s.v;
  std::size_t si = s.si, count = 0;
  long long n = s.n;
  int breaking = 0;
  while (t < t_end) {
    const double period_start = static_cast<double>(n) * P;
    const double seg_begin = period_start + segs[si].begin;
    const double seg_end = si + 1 < nseg ? period_start + segs[si + 1].begin : period_start + P;
    const double J = segs[si].jerk;
    const bool to_switch = seg_end <= t_end;
    const double t_stop = to_switch ? seg_end : t_end;
    while (t < t_stop) {
      ++count;
      const double A = J == 0 ? segs[si].accel : segs[si].accel + J * (t - seg_begin);
      int sigma = 0;
      if (v == 0) {
        if (breaking != 0) sigma = breaking;
        else if (!(std::abs(A) <= m)) sigma = A > 0 ? -1 : 1;
        breaking = 0;
        if (sigma == 0) {
          const double tau_break = J > 0 ? (m - A) / J : J < 0 ? (-m - A) / J : kInf;
          if (t + tau_break < t_stop) {  // held until |A| reaches m, then slips
            t = t + std::max(tau_break, 0.0);
            breaking = J > 0 ? -1 : 1;
          } else {
            t = t_stop;
          }
          continue;
        }
      } else {
        sigma = v > 0 ? 1 : -1;
      }
      double q0 = -sigma * m - A;
      if (v == 0 && sigma * q0 < 0) q0 = 0;
      const double T = t_stop - t;
      // sigma x'(tau) = sigma v + sigma q0 tau - sigma J tau^2 / 2
      const double tau_v = first_zero(-0.5 * sigma * J, sigma * q0, sigma * v + 0.0);
      const bool stop = tau_v <= T;
      const double tau = stop ? tau_v : T;
      if (J == 0) {
        x = x + tau * (v + 0.5 * q0 * tau);
        v = v + q0 * tau;
      } else {
        const double jx = -J;
        x = x + tau * (v + tau * (0.5 * q0 + tau * jx / 6.0));
        v = v + tau * (q0 + 0.5 * jx * tau);
      }
      if (stop) v = 0;
      if ((v > 0 && sigma < 0) || (v < 0 && sigma > 0)) v = 0;
      t = stop ? t + tau : t_stop;
    }
    if (to_switch && ++si == nseg) {
      si = 0;
      ++n;
    }
  }
  s = {t, x, v, si, n};
  return count;
}

// The profile velocity of PiecewisePolynomialProfile::velocity, inlined (jerk 0 segments).
inline double bare_velocity(const BareProfile& p, double t) {
  const double P = p.period;
  double ph = t - P * std::floor(t / P);
  if (ph >= P) ph -= P;
  if (ph < 0) ph = 0;
  std::size_t i = 0;
  const std::size_t nseg = p.segs.size();
  while (i + 1 < nseg && ph >= p.segs[i + 1].begin) ++i;
  const BareSegment& s = p.segs[i];
  return s.yd + s.accel * (ph - s.begin);
}

// Moreau step of time_stepping.hpp, constant bound m, static s and kinetic kf / kb.
// Velocity: the inlined copy above, or (Velocity = const PiecewisePolynomialProfile&) the
// profile's own function called directly.
template <class VelocityFn>
[[gnu::noinline]] void bare_moreau(const VelocityFn& velocity, double m, const FrictionLaw& law,
                                   double h, double theta, double t0, double& x_io, double& v_io,
                                   double& yd_io, long long steps) {
  const double hs = h * (law.static_coefficient() * m), hkf = h * (law.kinetic_forward() * m),
               hkb = h * (law.kinetic_backward() * m);
  double x = x_io, v = v_io, yd = yd_io;
  for (long long k = 1; k <= steps; ++k) {
    const double yd1 = velocity(t0 + static_cast<double>(k) * h);
    const double v_free = v - (yd1 - yd);
    const bool sliding_on = (v > 0 && v_free > 0) || (v < 0 && v_free < 0);
    const double hold = sliding_on ? (v_free > 0 ? hkf : hkb) : hs;
    double v1 = 0;
    if (v_free > hold) v1 = v_free - hkf;
    else if (v_free < -hold) v1 = v_free + hkb;
    x += h * ((1 - theta) * v + theta * v1);
    v = v1;
    yd = yd1;
  }
  x_io = x;
  v_io = v;
  yd_io = yd;
}

// ---- Exact solver -----------------------------------------------------------------------------

// The library from rest over `periods` periods: final state and arc count. Every horizon is a
// multiple of the PiecewisePolynomialProfile's period (the sum of its segment durations, which
// for the jerk-limited profile can differ from the requested period by an ulp).
BareState library_exact(const ExactSetup& setup, long long periods, std::size_t& arcs) {
  ExactState s = make_exact_state(setup, {0, 0, 0});
  arcs = advance_exact(setup, s, static_cast<double>(periods) * setup.profile.period());
  return {s.object.t, s.object.x, s.object.xd, s.segment, s.period_index};
}

std::size_t bare_exact(const BareProfile& b, double m, BareState& s, double t_end) {
  bool constant = true;
  for (const BareSegment& g : b.segs) constant = constant && g.jerk == 0;
  return constant ? bare_parabolic(b, m, s, t_end) : bare_cubic(b, m, s, t_end);
}

// One-off fairness check: the library and the bare loop agree on the final state and arcs.
bool check_exact(benchmark::State& st, const ExactSetup& setup, double m) {
  std::size_t arcs_lib = 0;
  const BareState lib = library_exact(setup, kPeriods, arcs_lib);
  const BareProfile b = bare_profile(setup.profile);
  BareState bare;
  const std::size_t arcs_bare =
      bare_exact(b, m, bare, static_cast<double>(kPeriods) * setup.profile.period());
  st.counters["check_dx"] = std::abs(lib.x - bare.x);
  if (close(lib.t, bare.t) && close(lib.x, bare.x) && close(lib.v, bare.v) &&
      arcs_lib == arcs_bare)
    return true;
  st.SkipWithError(("library and bare loop differ: x " + std::to_string(lib.x) + " vs " +
                    std::to_string(bare.x) + ", x' " + std::to_string(lib.v) + " vs " +
                    std::to_string(bare.v) + ", arcs " + std::to_string(arcs_lib) + " vs " +
                    std::to_string(arcs_bare))
                       .c_str());
  return false;
}

void exact_run(benchmark::State& st, const TableProfile& profile) {
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_polynomial(), *friction.piecewise_affine()};
  if (!check_exact(st, setup, friction.level())) return;
  std::size_t arcs = 0;
  for (auto _ : st) {
    ExactState s = make_exact_state(setup, {0, 0, 0});
    arcs += advance_exact(setup, s, static_cast<double>(kPeriods) * setup.profile.period());
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  per_item_counters(st, kPeriods, "ns_per_period");
  st.counters["arcs_per_period"] =
      static_cast<double>(arcs) / static_cast<double>(st.iterations() * kPeriods);
}

void bare_exact_run(benchmark::State& st, const TableProfile& profile) {
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_polynomial(), *friction.piecewise_affine()};
  if (!check_exact(st, setup, friction.level())) return;
  const BareProfile b = bare_profile(*profile.piecewise_polynomial());
  double m = friction.level();
  std::size_t arcs = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    BareState s;
    arcs += bare_exact(b, m, s, static_cast<double>(kPeriods) * b.period);
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  per_item_counters(st, kPeriods, "ns_per_period");
  st.counters["arcs_per_period"] =
      static_cast<double>(arcs) / static_cast<double>(st.iterations() * kPeriods);
}

void exact_per_period(benchmark::State& st, ThreePhaseParameters params) {
  exact_run(st, ThreePhaseProfile(params));
}
void exact_per_period(benchmark::State& st, JerkLimitedThreePhaseParameters params) {
  exact_run(st, JerkLimitedThreePhaseProfile(params));
}
void bare_exact_per_period(benchmark::State& st, ThreePhaseParameters params) {
  bare_exact_run(st, ThreePhaseProfile(params));
}
void bare_exact_per_period(benchmark::State& st, JerkLimitedThreePhaseParameters params) {
  bare_exact_run(st, JerkLimitedThreePhaseProfile(params));
}

// ---- Time-stepping ----------------------------------------------------------------------------

enum class BareVelocity { inlined, ppvelocity };

// Runs the bare Moreau loop from rest; returns the final (x, x', y').
template <class Fn>
void bare_moreau_from_rest(const Fn& velocity, double y0, double m, long long steps, double& x,
                           double& v, double& yd) {
  x = 0;
  v = 0;
  yd = y0;
  bare_moreau(velocity, m, FrictionLaw{}, kStepOptions.step, kStepOptions.theta, 0.0, x, v,
              yd, steps);
}

void run_bare_moreau(BareVelocity which, const PiecewisePolynomialProfile& pp,
                     const BareProfile& b, double m, long long steps, double& x, double& v,
                     double& yd) {
  if (which == BareVelocity::inlined)
    bare_moreau_from_rest([&b](double t) { return bare_velocity(b, t); }, pp.velocity(0.0), m,
                          steps, x, v, yd);
  else
    bare_moreau_from_rest([&pp](double t) { return pp.velocity(t); }, pp.velocity(0.0), m,
                          steps, x, v, yd);
}

bool check_time_stepping(benchmark::State& st, const ThreePhaseProfile& profile, double m) {
  const UniformFriction friction(m);
  TimeSteppingState s = make_time_stepping_state(profile, {0, 0, 0});
  advance_time_stepping(profile, friction, FrictionLaw{}, kStepOptions, s, kSteps);
  const PiecewisePolynomialProfile& pp = *profile.piecewise_polynomial();
  const BareProfile b = bare_profile(pp);
  for (BareVelocity which : {BareVelocity::inlined, BareVelocity::ppvelocity}) {
    double x, v, yd;
    run_bare_moreau(which, pp, b, m, kSteps, x, v, yd);
    if (!(close(s.object.x, x) && close(s.object.xd, v) && close(s.table_velocity, yd))) {
      st.SkipWithError(("time-stepping: library and bare loop differ: x " +
                        std::to_string(s.object.x) + " vs " + std::to_string(x))
                           .c_str());
      return false;
    }
    st.counters["check_dx"] = std::abs(s.object.x - x);
  }
  return true;
}

void time_stepping_per_step(benchmark::State& st, ThreePhaseParameters params) {
  const ThreePhaseProfile profile(params);
  const UniformFriction friction;
  const FrictionLaw law;
  if (!check_time_stepping(st, profile, friction.level())) return;
  for (auto _ : st) {
    TimeSteppingState s = make_time_stepping_state(profile, {0, 0, 0});
    advance_time_stepping(profile, friction, law, kStepOptions, s, kSteps);
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  per_item_counters(st, kSteps, "ns_per_step");
}

void bare_time_stepping_per_step(benchmark::State& st, ThreePhaseParameters params,
                                 BareVelocity which) {
  const ThreePhaseProfile profile(params);
  const UniformFriction friction;
  if (!check_time_stepping(st, profile, friction.level())) return;
  const PiecewisePolynomialProfile& pp = *profile.piecewise_polynomial();
  const BareProfile b = bare_profile(pp);
  double m = friction.level();
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    double x, v, yd;
    run_bare_moreau(which, pp, b, m, kSteps, x, v, yd);
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(yd);
  }
  per_item_counters(st, kSteps, "ns_per_step");
}

BENCHMARK_CAPTURE(exact_per_period, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(exact_per_period, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(exact_per_period, case3_jerk50_uniform, kCase3Jerk50)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(exact_per_period, case3_jerk12_uniform, kCase3Jerk12)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_exact_per_period, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_exact_per_period, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_exact_per_period, case3_jerk50_uniform, kCase3Jerk50)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_exact_per_period, case3_jerk12_uniform, kCase3Jerk12)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(time_stepping_per_step, case1_uniform, kCase1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(time_stepping_per_step, case3_uniform, kCase3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_time_stepping_per_step, case1_uniform_inlined, kCase1,
                  BareVelocity::inlined)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_time_stepping_per_step, case3_uniform_inlined, kCase3,
                  BareVelocity::inlined)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_time_stepping_per_step, case3_uniform_ppvelocity, kCase3,
                  BareVelocity::ppvelocity)
    ->Unit(benchmark::kMicrosecond);

// ---- Planar point contact (planar/planar_point.hpp) -------------------------------------------
// The table moves along x (case 3) and y (case 1) at once; a uniform field, s = 1.3 > k = 1.
// The bare loop is the same scheme inlined: both table velocities from the closed form, the
// disc projection, no field lookup, no validation.

const FrictionLaw kPlanarLaw(1.3, 1.0);

void planar_point_per_step(benchmark::State& st) {
  const ThreePhaseProfile px(kCase3), py(kCase1);
  PlanarTableMotion motion;
  motion.first = &px;
  motion.second = &py;
  const PlanarField field = UniformPlanarField{1.0};
  for (auto _ : st) {
    PlanarPointState s = make_planar_point_state(motion, 0, 0, 0, 0, 0);
    advance_planar_point(motion, field, kPlanarLaw, kStepOptions, s, kSteps);
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  per_item_counters(st, kSteps, "ns_per_step");
}

// Returns the final (x, y, ux, uy).
std::array<double, 4> bare_planar(const BareProfile& bx, const BareProfile& by, double m) {
  const double h = kStepOptions.step, theta = kStepOptions.theta;
  const double s = kPlanarLaw.static_coefficient(), k = kPlanarLaw.kinetic_forward();
  double x = 0, y = 0, ux = 0, uy = 0;
  double tvx = bare_velocity(bx, 0.0), tvy = bare_velocity(by, 0.0);
  for (long long i = 1; i <= kSteps; ++i) {
    const double t = static_cast<double>(i) * h;
    const double tvx1 = bare_velocity(bx, t), tvy1 = bare_velocity(by, t);
    const double vx = ux - (tvx1 - tvx), vy = uy - (tvy1 - tvy);
    const double speed = std::hypot(vx, vy);
    const double hold = h * ((vx * ux + vy * uy > 0 ? k : s) * m);
    double ux1 = 0, uy1 = 0;
    if (speed > hold) {
      const double impulse = h * (k * m);
      ux1 = vx - impulse * (vx / speed);
      uy1 = vy - impulse * (vy / speed);
    }
    x += h * ((1 - theta) * ux + theta * ux1);
    y += h * ((1 - theta) * uy + theta * uy1);
    ux = ux1, uy = uy1, tvx = tvx1, tvy = tvy1;
  }
  return {x, y, ux, uy};
}

void bare_planar_point_per_step(benchmark::State& st) {
  const ThreePhaseProfile px(kCase3), py(kCase1);
  const BareProfile bx = bare_profile(*px.piecewise_polynomial());
  const BareProfile by = bare_profile(*py.piecewise_polynomial());
  // The check: the library's run and the bare loop end in the same state.
  PlanarTableMotion motion;
  motion.first = &px;
  motion.second = &py;
  PlanarPointState lib = make_planar_point_state(motion, 0, 0, 0, 0, 0);
  advance_planar_point(motion, UniformPlanarField{1.0}, kPlanarLaw, kStepOptions, lib, kSteps);
  const std::array<double, 4> ref = bare_planar(bx, by, 1.0);
  if (!(close(lib.x, ref[0]) && close(lib.y, ref[1]))) {
    st.SkipWithError("planar: library and bare loop differ");
    return;
  }
  st.counters["check_dx"] = std::abs(lib.x - ref[0]) + std::abs(lib.y - ref[1]);
  double m = 1.0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(m);
    const std::array<double, 4> r = bare_planar(bx, by, m);
    benchmark::DoNotOptimize(r);
  }
  per_item_counters(st, kSteps, "ns_per_step");
}

// The exact planar solver per period (planar/planar_exact_point.hpp), the same motion.
void planar_exact_point_per_period(benchmark::State& st) {
  const ThreePhaseProfile px(kCase3), py(kCase1);
  PlanarTableMotion motion;
  motion.first = &px;
  motion.second = &py;
  long long arcs = 0;
  for (auto _ : st) {
    PlanarExactState s;
    arcs += advance_planar_exact_point(motion, UniformPlanarField{1.0}, kPlanarLaw, s,
                                       static_cast<double>(kPeriods) * px.period());
    benchmark::DoNotOptimize(s);
  }
  per_item_counters(st, kPeriods, "ns_per_period");
  st.counters["arcs_per_period"] =
      static_cast<double>(arcs) / static_cast<double>(st.iterations() * kPeriods);
}

// ---- Rigid part on a contact patch (planar/planar_rigid.hpp) ----------------------------------
// The same table motion; the patch stepper with 1 point at the centre of mass (the closed-form
// path: the cost of the general stepper's bookkeeping) and with a 16-point 4 x 4 rectangle
// (the convex impulse problem: dual sweeps and Newton steps), on a half-plane field so that
// the run has stick, pivot and slip steps. Ratios against planar_point_per_step.
void planar_patch_per_step(benchmark::State& st) {
  const ThreePhaseProfile px(kCase3), py(kCase1);
  PlanarTableMotion motion;
  motion.first = &px;
  motion.second = &py;
  const int side = static_cast<int>(st.range(0));
  const RigidPart part{0.002, side == 1 ? point_patch() : rectangle_patch(0.1, 0.06, side, side)};
  const PlanarField field = HalfPlaneStepField{0.02, 0, 0.3, 0.05, 2.5};
  long long sweeps = 0, newton = 0, stick = 0;
  for (auto _ : st) {
    PlanarRigidState s = make_planar_rigid_state(motion, 0, {0, 0, 0.2}, {});
    advance_planar_rigid(motion, field, kPlanarLaw, part, kStepOptions, s, kSteps);
    sweeps += s.sweeps, newton += s.newton_steps, stick += s.mode == PatchMode::stick;
    benchmark::DoNotOptimize(s.pose);
    benchmark::ClobberMemory();
  }
  per_item_counters(st, kSteps, "ns_per_step");
  const double steps = static_cast<double>(st.iterations() * kSteps);
  st.counters["sweeps_per_step"] = static_cast<double>(sweeps) / steps;
  st.counters["newton_per_step"] = static_cast<double>(newton) / steps;
}

// ---- A 16-point patch to a given accuracy: Moreau against the patch integrator --------------
// The problem of planar_patch_per_step over 2 periods. The error of a run is the distance of its
// end pose from the integrator's at tolerance 1e-13 (position plus patch radius times angle);
// bench/planar_patch_accuracy.py picks, per method, the cheapest run within 1e-6 and reports the
// ratio of their times (issue 22: the integrator at least 10x faster than Moreau at 1e-6).
struct SixteenPointRun {
  ThreePhaseProfile px{kCase3}, py{kCase1};
  PlanarTableMotion motion;
  RigidPart part{0.002, rectangle_patch(0.1, 0.06, 4, 4)};
  PlanarField field = HalfPlaneStepField{0.02, 0, 0.3, 0.05, 2.5};
  static constexpr double kT = 2.0;
  SixteenPointRun() { motion.first = &px, motion.second = &py; }
  PlanarPose integrated(double rtol, IntegratorStatistics* stats = nullptr) const {
    IntegratorOptions o;
    o.relative_tolerance = rtol, o.absolute_tolerance = 1e-2 * rtol;
    PlanarPatchState s = make_planar_patch_state(0, {0, 0, 0.2}, {});
    advance_planar_integrated(motion, field, kPlanarLaw, part, o, s, kT, stats);
    return s.pose;
  }
  PlanarPose moreau(double h) const {
    PlanarRigidState s = make_planar_rigid_state(motion, 0, {0, 0, 0.2}, {});
    advance_planar_rigid(motion, field, kPlanarLaw, part, {h, 0.5}, s, std::llround(kT / h));
    return s.pose;
  }
  double error(const PlanarPose& a) const {
    static const PlanarPose ref = integrated(1e-13);
    return std::hypot(a.x - ref.x, a.y - ref.y) +
           patch_radius(part.patch) * std::abs(a.angle - ref.angle);
  }
};

// Arg k: the step 10^-k (Moreau) or the relative tolerance 10^-k (integrator).
void planar_patch_accuracy_moreau(benchmark::State& st) {
  const SixteenPointRun run;
  const double h = std::pow(10.0, -static_cast<double>(st.range(0)));
  PlanarPose pose;
  for (auto _ : st) {
    pose = run.moreau(h);
    benchmark::DoNotOptimize(pose);
  }
  st.counters["error"] = run.error(pose);
  st.counters["step"] = h;
}
void planar_patch_accuracy_integrator(benchmark::State& st) {
  const SixteenPointRun run;
  const double rtol = std::pow(10.0, -static_cast<double>(st.range(0)));
  PlanarPose pose;
  IntegratorStatistics stats;
  for (auto _ : st) {
    stats = {};
    pose = run.integrated(rtol, &stats);
    benchmark::DoNotOptimize(pose);
  }
  st.counters["error"] = run.error(pose);
  st.counters["relative_tolerance"] = rtol;
  st.counters["rk_steps"] = static_cast<double>(stats.steps + stats.rejected);
  st.counters["events"] = static_cast<double>(stats.events);
}
BENCHMARK(planar_patch_accuracy_moreau)->DenseRange(3, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(planar_patch_accuracy_integrator)->DenseRange(5, 10)->Unit(benchmark::kMillisecond);

BENCHMARK(planar_point_per_step)->Unit(benchmark::kMicrosecond);
BENCHMARK(planar_patch_per_step)->Arg(1)->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(planar_exact_point_per_period)->Unit(benchmark::kMicrosecond);
BENCHMARK(bare_planar_point_per_step)->Unit(benchmark::kMicrosecond);

// ---- Fourier profiles: the exact smooth-profile solver beside Moreau (issue 11) ------------
// The order-12 Fourier series of a Fig. 6-like three-phase profile (Δt = 0.072, Δy = 0.021,
// y2'' = 1000, y3'' = 80, Lanczos-smoothed), on the uniform table: the exact steady state
// (converged to ~1e-14 in x'_0s) and Moreau steady states at two step sizes, whose v̄ error
// against the exact one is reported as a counter (the accuracy each buys).
const FourierProfile& fig6_like_order12() {
  static const FourierProfile profile = [] {
    std::vector<double> a, b;
    const ThreePhaseProfile three({0.072, 0.021, 1000, 80});
    fourier_series_of(*three.piecewise_polynomial(), 12, a, b);
    return FourierProfile(0.072, a, b);
  }();
  return profile;
}

void fourier_steady_state_exact(benchmark::State& st) {
  const FourierProfile& p = fig6_like_order12();
  SteadyState r;
  for (auto _ : st) {
    r = steady_state(p);
    benchmark::DoNotOptimize(r);
  }
  st.counters["periods"] = r.periods;
  st.counters["x_dot_0s_error"] = r.x_dot_0s_error;
}

void fourier_steady_state_moreau(benchmark::State& st) {
  const FourierProfile& p = fig6_like_order12();
  const double v_exact = steady_state(p).v_bar;
  const testing_support::Opaque hidden(p);  // the same motion, without its closed form
  SteadyStateOptions o;
  o.steps_per_period = static_cast<int>(st.range(0));
  SteadyState r;
  for (auto _ : st) {
    r = steady_state(hidden, o);
    benchmark::DoNotOptimize(r);
  }
  st.counters["periods"] = r.periods;
  st.counters["v_bar_error"] = std::abs(r.v_bar - v_exact);
}

BENCHMARK(fourier_steady_state_exact)->Unit(benchmark::kMicrosecond);
BENCHMARK(fourier_steady_state_moreau)->Arg(2000)->Arg(20000)->Unit(benchmark::kMicrosecond);
// ---- Stribeck + viscous friction: the slip integrator beside Moreau (issue 11) ------------
// The paper's Sect. 7.2 three-phase profile on the uniform table under s = 1.3, k = 1,
// v_s = 0.01, delta = 2, c = 0.1: one period from the steady state's phase-0 velocity, by the
// integrator at two tolerances and by Moreau at three step sizes. Counter x_error: |x| after
// the period against the integrator at rtol 1e-13 (the accuracy each run buys).
struct StribeckCase {
  ThreePhaseProfile profile{ThreePhaseParameters{1.0, 0.084, 2.3, 1.3}};
  FrictionLaw law = FrictionLaw(1.3, 1.0).with_stribeck(0.01, 2.0).with_viscous(0.1);
  UniformFriction uniform;
  double v0 = 0, x_reference = 0;
  StribeckCase() {
    v0 = steady_state(profile, law).x_dot_0s;
    ObjectState s{0, 0, v0};
    advance_integrated({profile, *uniform.piecewise_affine(), law, {1e-13, 1e-15}}, s,
                       profile.period());
    x_reference = s.x;
  }
};
const StribeckCase& stribeck_case() {
  static const StribeckCase c;
  return c;
}

void stribeck_integrator_per_period(benchmark::State& st) {
  const StribeckCase& c = stribeck_case();
  const double rtol = std::pow(10.0, -static_cast<double>(st.range(0)));
  const IntegratorSetup setup{c.profile, *c.uniform.piecewise_affine(), c.law, {rtol, rtol / 100}};
  ObjectState s;
  IntegratorStatistics stats;
  for (auto _ : st) {
    s = {0, 0, c.v0};
    stats = {};
    advance_integrated(setup, s, c.profile.period(), nullptr, &stats);
    benchmark::DoNotOptimize(s);
  }
  st.counters["x_error"] = std::abs(s.x - c.x_reference);
  st.counters["steps"] = static_cast<double>(stats.steps);
  st.counters["rejected"] = static_cast<double>(stats.rejected);
}

void stribeck_moreau_per_period(benchmark::State& st) {
  const StribeckCase& c = stribeck_case();
  const long long n = st.range(0);
  TimeSteppingState s;
  for (auto _ : st) {
    s = make_time_stepping_state(c.profile, {0, 0, c.v0});
    advance_time_stepping(c.profile, c.uniform, c.law, {c.profile.period() / n, 0.5}, s, n);
    benchmark::DoNotOptimize(s);
  }
  st.counters["x_error"] = std::abs(s.object.x - c.x_reference);
}

BENCHMARK(stribeck_integrator_per_period)->Arg(10)->Arg(6)->Unit(benchmark::kMicrosecond);
BENCHMARK(stribeck_moreau_per_period)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);
}  // namespace
