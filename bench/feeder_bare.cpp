// The exact feeder solver per period on the classic sinusoidal drive (issue 23), against a
// bare loop of the same computation in the same binary:
//   feeder_exact_per_period/{sliding,hopping}       advance_feeder_exact over kFeederPeriods
//                                                   periods of the drive (FeederTable: two
//                                                   FourierProfile's, one along the track and
//                                                   one along its normal)
//   bare_feeder_exact_per_period/{sliding,hopping}  the same arcs and safe-step certificates
//                                                   written for this one drive: one sincos per
//                                                   evaluation for both directions (they share
//                                                   the phase), no virtual calls, the bounds in
//                                                   closed form (a w^k per derivative)
// Sliding: psi = 0.35, theta = 0.02, K = 1.5 (Gamma = 0.51); hopping: Gamma = 1.6, psi = 0.5,
// theta = 0 (plastic landing); mu_s = 0.5, mu_k = 0.4 at level 1 = g. Before timing the bare
// loop is checked once against the library (position after the periods within 1e-12
// (1 + |x|)); a bare loop that disagrees is skipped with an error. The ratio: bench/
// bare_loop_ratios.py.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/analysis/feeder_exact.hpp"

// In a namespace of their own: the benchmark sources are compiled as one unity file.
namespace selfalign_feeder_bare {
namespace {
using namespace selfalign;

constexpr long long kFeederPeriods = 200;
constexpr double kPi = std::numbers::pi;

struct Case {
  double psi, theta, K;
};
const Case kSliding{0.35, 0.02, 1.5};
const Case kHopping{0.5, 0.0, 1.6 / std::sin(0.5)};
constexpr double kMuS = 0.5, kMuK = 0.4;

FeederDrive drive_of(const Case& c) {
  const double w = 2 * kPi;
  return FeederDrive{c.K / (w * w), 1.0, c.psi, c.theta, 1.0};
}

// ---- the bare loop --------------------------------------------------------------------------

double resolution(double t) {
  return 16 * std::numeric_limits<double>::epsilon() * (std::abs(t) + 1e-300);
}
double safe(double f, double f1, double b) {
  if (f < 0 || (f == 0 && f1 <= 0)) return 0.0;
  const double r = std::sqrt(f1 * f1 + 2 * b * f);
  return f1 >= 0 ? (f1 + r) / b : 2 * f / (r - f1);
}

// The largest d with f + f1 d - c2 d^2 - c3 d^3 >= 0, Newton from above (c2, c3 >= 0).
double local_step(double f, double f1, double c2, double c3, double from) {
  const auto poly = [&](double e) { return f + e * (f1 - e * (c2 + c3 * e)); };
  double d = from;
  for (int k = 0; k < 8 && poly(d) < 0; ++k) {
    const double slope = f1 - d * (2 * c2 + 3 * c3 * d);
    if (!(slope < 0)) break;
    d -= poly(d) / slope;
  }
  for (int k = 0; k < 4 && poly(d) < 0; ++k) d *= 0.5;
  return poly(d) >= 0 ? d : 0.0;
}

struct Bare {
  double w, ax, az, gc, gs;  // a0 cos psi, a0 sin psi
  double t = 0, x = 0, u = 0, h = 0, v = 0;  // v: the height's rate
  int mode = 0, breaking = 0;                 // 0 contact, 1 flight
  bool from_lift = false;
  struct P {
    double s, c;
  };
  P phase(double tt) const { return {std::sin(w * tt), std::cos(w * tt)}; }

  void run(double t_end) {
    while (t < t_end) {
      if (mode == 1) {
        flight(t_end);
        continue;
      }
      const P p = phase(t);
      const double n = gc - az * w * w * p.s, n1 = -az * w * w * w * p.c;
      if (n < 0 || (n == 0 && n1 < 0)) {
        mode = 1, h = 0, v = 0, from_lift = true;
        continue;
      }
      int sigma;
      if (u != 0) {
        sigma = u > 0 ? 1 : -1;
      } else if (breaking != 0) {
        sigma = breaking, breaking = 0;
      } else {
        const double f = -ax * w * w * p.s + gs;
        if (std::abs(f) <= kMuS * n) {
          stick(t_end);
          continue;
        }
        sigma = f > 0 ? -1 : 1;
      }
      slip(sigma, t_end);
    }
  }
  void stick(double t_end) {
    const double w2 = w * w, w3 = w2 * w, B = (kMuS * az + ax) * w2 * w2;
    for (;;) {
      const P p = phase(t);
      const double n = gc - az * w2 * p.s, f = -ax * w2 * p.s + gs;
      const double n1 = -az * w3 * p.c, f1 = -ax * w3 * p.c;
      const double up = safe(kMuS * n - f, kMuS * n1 - f1, B);
      const double down = safe(kMuS * n + f, kMuS * n1 + f1, B);
      const double step = std::min(up, down);
      if (t + step >= t_end) {
        t = t_end;
        return;
      }
      if (step <= resolution(t)) {
        if ((up <= down ? kMuS * n1 - f1 : kMuS * n1 + f1) >= 0) {
          t += 1024 * resolution(t);
          continue;
        }
        t += step;
        breaking = up <= down ? -1 : 1;
        return;
      }
      t += step;
    }
  }
  void slip(int sigma, double t_end) {
    const double w2 = w * w, w3 = w2 * w, cc = sigma * kMuK;
    const double Bg = (ax + kMuK * az) * w3, Bg1 = (ax + kMuK * az) * w3 * w, Bn = az * w3 * w;
    const double t0 = t, x0 = x, u0 = u;
    const P p0 = phase(t0);
    const bool from_rest = u0 == 0;
    // u = u0 - (X'(t) - X'0) - gs tau - cc (gc tau + Z'(t) - Z'0), X' = ax w cos, Z' = az w cos
    const auto rate = [&](double tau, const P& p) {
      return u0 - ax * w * (p.c - p0.c) - gs * tau - cc * (gc * tau + az * w * (p.c - p0.c));
    };
    double tau = 0, g = sigma * u0;
    P p = p0;
    int end = 0;  // 0 horizon, 1 velocity zero, 2 lift-off
    for (int i = 0;; ++i) {
      const double n = gc - az * w2 * p.s;
      double g1 = sigma * (ax * w2 * p.s - gs - cc * n);
      if (from_rest && i == 0) g1 = std::max(g1, 0.0);
      const double g2 = sigma * (ax * w3 * p.c + cc * az * w3 * p.c);
      const double quad = safe(g, g1, Bg);
      const double local = local_step(g, g1, 0.5 * std::abs(g2), Bg1 / 6, std::max(2 * quad, 1e-300));
      const double dg = std::max({quad, local, g1 >= 0 ? safe(g1, g2, Bg1) : 0.0});
      const double dn = az != 0 ? safe(n, -az * w3 * p.c, Bn) : HUGE_VAL;
      const double step = std::min(dg, dn), now = t0 + tau;
      if (now + step >= t_end) {
        tau = t_end - t0;
        p = phase(t_end);
        break;
      }
      tau += step;
      p = phase(t0 + tau);
      g = sigma * rate(tau, p);
      if (!(g > 0)) {
        end = 1;
        break;
      }
      if (step <= resolution(now)) {
        if (dg <= dn && g1 < 0) {
          end = 1;
          break;
        }
        if (dn < dg && -az * w3 * p.c < 0) {
          end = 2;
          break;
        }
        tau += 1024 * resolution(now);
        p = phase(t0 + tau);
        g = sigma * rate(tau, p);
      }
    }
    t = t0 + tau;
    // x = x0 + u0 tau - D_x - gs tau^2/2 - cc (gc tau^2/2 + D_z), D = y - y0 - y0' tau
    const double dx = ax * (p.s - p0.s - w * p0.c * tau), dz = az * (p.s - p0.s - w * p0.c * tau);
    x = x0 + u0 * tau - dx - 0.5 * gs * tau * tau - cc * (0.5 * gc * tau * tau + dz);
    u = end == 1 ? 0.0 : rate(tau, p);
    if (end == 2) mode = 1, h = 0, v = 0, from_lift = true;
  }
  void flight(double t_end) {
    const double w2 = w * w, w3 = w2 * w;
    const double t0 = t, x0 = x, u0 = u, h0 = h, v0 = v;
    const P p0 = phase(t0);
    const double Bh = gc + az * w2, Z3 = az * w3, Z4 = az * w3 * w;
    const auto height = [&](double s, const P& p) {
      return h0 + v0 * s - 0.5 * gc * s * s - az * (p.s - p0.s - w * p0.c * s);
    };
    const auto hrate = [&](double s, const P& p) { return v0 - gc * s - az * w * (p.c - p0.c); };
    double tau = 0, hh = h0, ww = v0;
    P p = p0;
    bool lands = false;
    for (int i = 0;; ++i) {
      const double n = gc - az * w2 * p.s, n1 = -az * w3 * p.c;
      const double away = from_lift && i == 0 ? std::max(-n, 0.0) : -n;
      const double quad = safe(hh, ww, Bh);
      // the local cubic h + w d - max(n, 0) d^2/2 - Z3 d^3/6
      const double local =
          local_step(hh, ww, 0.5 * std::max(n, 0.0), Z3 / 6, std::max(2 * quad, 1e-300));
      const double convex = ww >= 0 && hh >= 0 ? safe(away, -n1, Z4) : 0.0;
      const double step = std::max({quad, local, convex}), now = t0 + tau;
      if (now + step >= t_end) {
        tau = t_end - t0;
        p = phase(t_end);
        break;
      }
      if (step <= resolution(now) && ww < 0) {
        tau += std::max(0.0, hh) / -ww;
        p = phase(t0 + tau);
        lands = true;
        break;
      }
      tau += std::max(step, step <= resolution(now) ? 1024 * resolution(now) : 0.0);
      p = phase(t0 + tau);
      hh = height(tau, p);
      ww = hrate(tau, p);
      if (hh <= 0 && ww <= 0) {
        lands = true;
        break;
      }
    }
    from_lift = false;
    t = t0 + tau;
    x = x0 + u0 * tau - 0.5 * gs * tau * tau - ax * (p.s - p0.s - w * p0.c * tau);
    u = u0 - gs * tau - ax * w * (p.c - p0.c);
    v = hrate(tau, p);
    h = lands ? 0.0 : std::max(0.0, height(tau, p));
    if (lands) {  // plastic; the tangential impulse within the kinetic cone
      const double P = std::max(0.0, -v);
      const int sigma = u > 0 ? 1 : -1;
      u = std::abs(u) <= kMuK * P ? 0.0 : u - sigma * kMuK * P;
      v = 0, mode = 0;
    }
  }
};

Bare bare_of(const Case& c) {
  const FeederDrive d = drive_of(c);
  Bare b{2 * kPi / d.period, d.amplitude * std::cos(c.psi), d.amplitude * std::sin(c.psi),
         d.g * std::cos(c.theta), d.g * std::sin(c.theta)};
  return b;
}

// ---- the library ------------------------------------------------------------------------------

double library_x(const FeederTable& table, long long periods) {
  const FeederDrive& d = table.drive();
  const FeederTrack track{table.motion().first, table.motion().normal, d.g, d.incline, d.g,
                          FrictionLaw(kMuS, kMuK)};
  FeederExactState s;
  advance_feeder_exact(track, s, static_cast<double>(periods) * d.period);
  return s.x;
}

void feeder_exact_per_period(benchmark::State& st, Case c) {
  const FeederTable table(drive_of(c));
  for (auto _ : st) benchmark::DoNotOptimize(library_x(table, kFeederPeriods));
  st.SetItemsProcessed(st.iterations() * kFeederPeriods);
  st.counters["us_per_period"] = benchmark::Counter(
      static_cast<double>(kFeederPeriods), benchmark::Counter::kIsIterationInvariantRate |
                                               benchmark::Counter::kInvert);
}

void bare_feeder_exact_per_period(benchmark::State& st, Case c) {
  {
    const FeederTable table(drive_of(c));
    const double lib = library_x(table, kFeederPeriods);
    Bare b = bare_of(c);
    b.run(static_cast<double>(kFeederPeriods));
    if (!(std::abs(lib - b.x) <= 1e-12 * (1 + std::abs(lib)))) {
      st.SkipWithError(("bare feeder loop differs: x " + std::to_string(lib) + " vs " +
                        std::to_string(b.x))
                           .c_str());
      return;
    }
    st.counters["check_dx"] = std::abs(lib - b.x);
  }
  for (auto _ : st) {
    Bare b = bare_of(c);
    b.run(static_cast<double>(kFeederPeriods));
    benchmark::DoNotOptimize(b.x);
  }
  st.SetItemsProcessed(st.iterations() * kFeederPeriods);
}

BENCHMARK_CAPTURE(feeder_exact_per_period, sliding, kSliding)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(feeder_exact_per_period, hopping, kHopping)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_feeder_exact_per_period, sliding, kSliding)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_feeder_exact_per_period, hopping, kHopping)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace selfalign_feeder_bare
