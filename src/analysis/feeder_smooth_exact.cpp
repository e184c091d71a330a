// The exact feeder solver on smooth drives (feeder_exact.hpp; docs/feeder.md, "The exact
// solver on smooth drives"): the classic sinusoidal drive, Fourier sums of it, any SmoothMotion
// along the track (x_T) and along its normal (z_T). Every arc is closed-form in the motion;
// every event is isolated by safe steps (safe_step.hpp), the certified scan of the smooth 1-D
// solver: the scan never steps over a root and converges onto each one.
//
// Per unit mass, from an arc's start t0 (tau = t - t0, D = the track's value at t minus its
// Taylor line at t0, e.g. D_x(t) = x_T(t) - x_T(t0) - x_T'(t0) tau):
//   slip in direction sigma, c = sigma k_sigma m / g:
//     u = u0 - (x_T'(t) - x_T'(t0)) - g_s tau - c (g_c tau + z_T'(t) - z_T'(t0)),
//     x = x0 + u0 tau - D_x - g_s tau^2 / 2 - c (g_c tau^2 / 2 + D_z);
//   flight:
//     u = u0 - g_s tau - (x_T'(t) - x_T'(t0)),     x = x0 + u0 tau - g_s tau^2 / 2 - D_x,
//     w = w0 - g_c tau - (z_T'(t) - z_T'(t0)),     h = h0 + w0 tau - g_c tau^2 / 2 - D_z.
// Events and their certificates (a function F >= 0 on the open arc; bounds of the profiles'
// derivatives X3, X4 = sup |x_T'''|, |x_T''''|, Z2, Z3, Z4 likewise for z_T):
//   stick break: the margins s m n / g -+ f >= 0 (f = x_T'' + g_s, n = g_c + z_T''), their
//     curvature within s m Z4 / g + X4;
//   velocity zero: sigma u >= 0, curvature within X3 + |c| Z3 (and, while it rises, its slope
//     sigma u' >= 0 with curvature within X4 + |c| Z4: a slip that starts with u' = 0);
//   lift-off: n >= 0 in contact, curvature within Z4;
//   landing: h >= 0 in flight, by the largest of three certificates: h + w d - (g_c + Z2) d^2/2
//     (|h''| = |n|), the local cubic h + w d - max(n, 0) d^2 / 2 - Z3 d^3 / 6 (h'' = -n >= -n(t)
//     - Z3 d), and, while w >= 0, -n >= 0 (then h is convex and rising: it cannot return to 0;
//     this one carries the flight away from a lift-off, where h = w = n = 0).
// A root is declared when the safe step falls below 16 roundings of t (time_resolution); a
// landing is then placed by one Newton step on h.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../simulate/safe_step.hpp"
#include "feeder_exact_detail.hpp"
#include "selfalign/error.hpp"

namespace selfalign::detail {
namespace {

using D4 = std::array<double, 4>;

// The work budget of one arc, as in smooth_exact.cpp: a motion whose bounds make every safe
// step tiny ends in an error, not in a wrong arc.
constexpr long long kMaxFeederSteps = 100'000'000;

[[noreturn]] void exceed_feeder_budget(double t) {
  throw InvalidParameter("profile", "smooth motion",
                         "the exact feeder solver needs more than 1e8 safe steps for one arc at "
                         "t = " + format_number(t) +
                             " (derivative bounds too large for the time scale: use "
                             "time-stepping)");
}

// The two directions of the track's motion, null ones as zero.
struct SmoothTrack {
  const SmoothMotion* along;
  const SmoothMotion* normal;
  double X2 = 0, X3 = 0, X4 = 0, Z2 = 0, Z3 = 0, Z4 = 0;
  explicit SmoothTrack(const FeederTrack& k)
      : along(k.along ? k.along->smooth() : nullptr),
        normal(k.normal ? k.normal->smooth() : nullptr) {
    if (along) X2 = k.along->peak_acceleration(), X3 = along->jerk_bound(),
               X4 = along->snap_bound();
    if (normal) Z2 = k.normal->peak_acceleration(), Z3 = normal->jerk_bound(),
                Z4 = normal->snap_bound();
  }
  D4 x(double t) const { return along ? along->derivatives(t) : D4{}; }
  D4 z(double t) const { return normal ? normal->derivatives(t) : D4{}; }
};

// The motion's value at t minus its Taylor line from t0 (D in the header).
double taylor_gap(const D4& at, const D4& from, double tau) {
  return at[0] - from[0] - from[1] * tau;
}

struct Solver {
  const SmoothTrack& T;
  const FeederConstants& c;
  FeederExactStatistics& stats;
  double t, x, u, h, w;
  FeederMode mode;
  int breaking = 0;  // after a stick break: the slip's direction
  bool from_lift_off = false;

  // Held until a margin closes (a break: breaking = the slip's direction) or t_end.
  void stick(double t_end) {
    const double sm = c.static_bound(1.0, c.level_at(x));
    const double B = sm * T.Z4 + T.X4;
    const double t0 = t;
    D4 dx = T.x(t), dz = T.z(t);
    for (long long i = 0;; ++i) {
      if (i == kMaxFeederSteps) exceed_feeder_budget(t);
      const double n = c.gc + dz[2], f = dx[2] + c.gs;
      const double up = safe_step(sm * n - f, sm * dz[3] - dx[3], B);    // f reaches +s m n/g
      const double down = safe_step(sm * n + f, sm * dz[3] + dx[3], B);  // f reaches -s m n/g
      const double step = std::min(up, down);
      if (t + step >= t_end) {
        t = t_end;
        break;
      }
      if (step <= time_resolution(t)) {
        const double rate = up <= down ? sm * dz[3] - dx[3] : sm * dz[3] + dx[3];
        if (rate >= 0) {  // a touch of the bound, not a crossing: step past it
          t += 1024 * time_resolution(t);
        } else {
          t += step;
          breaking = up <= down ? -1 : 1;  // f beyond +s m n / g: it slides backward
          break;
        }
      } else {
        t += step;
      }
      dx = T.x(t), dz = T.z(t);
    }
    record_census(stats, FeederMode::stick, t - t0, t);
    mode = FeederMode::stick;
  }

  // One slip in direction sigma until u = 0, a lift-off (n = 0), the boundary of its friction
  // piece or t_end.
  void slip(int sigma, double t_end) {
    const FeederConstants::SlipPiece piece = c.slip_piece(x, sigma);
    const double cc = sigma * c.kinetic(sigma, 1.0, piece.m);
    const double Bg = T.X3 + std::abs(cc) * T.Z3, Bg1 = T.X4 + std::abs(cc) * T.Z4;
    // sigma (boundary - x) >= 0 falls at |u| with curvature |u'| <= Bx
    const bool bounded = std::isfinite(piece.boundary);
    const double Bx = T.X2 + std::abs(c.gs) + std::abs(cc) * (c.gc + T.Z2);
    const double t0 = t, x0 = x, u0 = u;
    const D4 dx0 = T.x(t0), dz0 = T.z(t0);
    const bool from_rest = u0 == 0;
    double tau = 0;
    D4 dx = dx0, dz = dz0;
    enum { horizon, velocity_zero, lift_off, boundary } end = horizon;
    double g = sigma * u0;
    const auto place = [&](double tau_, const D4& dx, const D4& dz) {
      return x0 + u0 * tau_ - taylor_gap(dx, dx0, tau_) - 0.5 * c.gs * tau_ * tau_ -
             cc * (0.5 * c.gc * tau_ * tau_ + taylor_gap(dz, dz0, tau_));
    };
    const auto velocity = [&](double tau_, const D4& dx, const D4& dz) {
      return u0 - (dx[1] - dx0[1]) - c.gs * tau_ - cc * (c.gc * tau_ + dz[1] - dz0[1]);
    };
    double ahead = bounded ? sigma * (piece.boundary - x0) : kInf;
    for (long long i = 0;; ++i) {
      if (i == kMaxFeederSteps) exceed_feeder_budget(t0 + tau);
      const double n = c.gc + dz[2];
      double g1 = sigma * (-dx[2] - c.gs - cc * n);
      if (from_rest && i == 0) g1 = std::max(g1, 0.0);  // at a break: u' >= 0 but rounding
      const double g2 = sigma * (-dx[3] - cc * dz[3]);
      const double quadratic = safe_step(g, g1, Bg);
      const double local = safe_step_local(g, g1, 0.5 * std::abs(g2), Bg1 / 6,
                                           std::max(2 * quadratic, 1e-300));
      const double dg = std::max({quadratic, local, g1 >= 0 ? safe_step(g1, g2, Bg1) : 0.0});
      const double dn = T.normal ? safe_step(n, dz[3], T.Z4) : kInf;
      const double db = bounded ? safe_step(ahead, -g, Bx) : kInf;
      const double step = std::min({dg, dn, db});
      const double now = t0 + tau;
      if (now + step >= t_end) {
        tau = t_end - t0;
        dx = T.x(t_end), dz = T.z(t_end);
        break;
      }
      tau += step;
      dx = T.x(t0 + tau), dz = T.z(t0 + tau);
      g = sigma * velocity(tau, dx, dz);
      if (bounded) ahead = sigma * (piece.boundary - place(tau, dx, dz));
      if (bounded && !(ahead > 0)) {  // rounding put the point at the boundary
        end = boundary;
        break;
      }
      if (!(g > 0)) {
        end = velocity_zero;
        break;
      }
      if (step <= time_resolution(now)) {
        if (db <= dg && db <= dn) {  // converged onto the boundary (x moves at |u| > 0)
          end = boundary;
          break;
        }
        if (dg <= dn && g1 < 0) {
          end = velocity_zero;
          break;
        }
        if (dn < dg && dz[3] < 0) {
          end = lift_off;
          break;
        }
        tau += 1024 * time_resolution(now);  // a touch, not a crossing: step past it
        dx = T.x(t0 + tau), dz = T.z(t0 + tau);
        g = sigma * velocity(tau, dx, dz);
      }
    }
    t = t0 + tau;
    x = end == boundary ? piece.boundary : place(tau, dx, dz);
    u = end == velocity_zero ? 0.0 : velocity(tau, dx, dz);
    record_census(stats, FeederMode::slip, tau, t);
    mode = FeederMode::slip;
    if (end == lift_off) {
      mode = FeederMode::flight;
      h = 0, w = 0;
      from_lift_off = true;
      record_lift_off(stats, t);
    }
  }

  // One flight until the landing or t_end.
  void flight(double t_end) {
    const double t0 = t, x0 = x, u0 = u, h0 = h, w0 = w;
    const D4 dx0 = T.x(t0), dz0 = T.z(t0);
    const double Bh = c.gc + T.Z2;
    double tau = 0, hh = h0, ww = w0;
    D4 dz = dz0;
    bool lands = false;
    const auto height = [&](double s, const D4& d) {
      return h0 + w0 * s - 0.5 * c.gc * s * s - taylor_gap(d, dz0, s);
    };
    const auto rate = [&](double s, const D4& d) { return w0 - c.gc * s - (d[1] - dz0[1]); };
    for (long long i = 0;; ++i) {
      if (i == kMaxFeederSteps) exceed_feeder_budget(t0 + tau);
      const double n = c.gc + dz[2];
      const double away = from_lift_off && i == 0 ? std::max(-n, 0.0) : -n;
      const double quadratic = safe_step(hh, ww, Bh);
      const double local = safe_step_local(hh, ww, 0.5 * std::max(n, 0.0), T.Z3 / 6,
                                           std::max(2 * quadratic, 1e-300));
      const double convex = ww >= 0 && hh >= 0 ? safe_step(away, -dz[3], T.Z4) : 0.0;
      const double step = std::max({quadratic, local, convex});
      const double now = t0 + tau;
      if (now + step >= t_end) {
        tau = t_end - t0;
        dz = T.z(t_end);
        break;
      }
      if (step <= time_resolution(now) && ww < 0) {  // converged onto the landing
        tau += std::max(0.0, hh) / -ww;               // one Newton step on h
        dz = T.z(t0 + tau);
        lands = true;
        break;
      }
      tau += std::max(step, step <= time_resolution(now) ? 1024 * time_resolution(now) : 0.0);
      dz = T.z(t0 + tau);
      hh = height(tau, dz);
      ww = rate(tau, dz);
      if (hh <= 0 && ww <= 0) {  // rounding put the point at the landing
        lands = true;
        break;
      }
    }
    from_lift_off = false;
    const D4 dx = T.x(t0 + tau);
    t = t0 + tau;
    x = x0 + u0 * tau - 0.5 * c.gs * tau * tau - taylor_gap(dx, dx0, tau);
    u = u0 - c.gs * tau - (dx[1] - dx0[1]);
    w = rate(tau, dz);
    h = lands ? 0.0 : std::max(0.0, height(tau, dz));
    record_census(stats, FeederMode::flight, tau, t);
    mode = FeederMode::flight;
    if (lands && !feeder_landing(c, t, x, c.gc + dz[2], u, w, stats))
      mode = u == 0 ? FeederMode::stick : FeederMode::slip;
  }
};

}  // namespace

void advance_feeder_smooth(const FeederTrack& k, FeederExactState& st, double t_end,
                           FeederExactStatistics& stats) {
  const SmoothTrack T(k);
  FeederConstants c(k);
  if (k.normal)  // h = ... - (z_T(t) - z_T(t0) - ...): rounding of the normal motion's size
    c.height_resolution = 64 * std::numeric_limits<double>::epsilon() *
                          (k.normal->stroke() + std::abs(k.normal->state(0).y));
  Solver s{T, c, stats, st.t, st.x, st.u, st.h, st.w, st.h > 0 ? FeederMode::flight : st.mode};
  while (s.t < t_end) {
    ++stats.arcs;
    if (s.mode == FeederMode::flight) {
      s.flight(t_end);
      continue;
    }
    const D4 dz = T.z(s.t);
    const double n = c.gc + dz[2];
    if (n < 0 || (n == 0 && dz[3] < 0)) {  // the track falls away faster than gravity
      s.mode = FeederMode::flight;
      s.h = 0, s.w = 0, s.from_lift_off = true;
      record_lift_off(stats, s.t);
      continue;
    }
    int sigma;
    if (s.u != 0) {
      sigma = s.u > 0 ? 1 : -1;
    } else if (s.breaking != 0) {
      sigma = s.breaking;
      s.breaking = 0;
      record_slip_start(stats, s.t, sigma);
    } else {
      const double f = T.x(s.t)[2] + c.gs;
      if (std::abs(f) <= c.static_bound(n, c.level_at(s.x))) {
        s.stick(t_end);
        continue;
      }
      sigma = f > 0 ? -1 : 1;  // it slides against the friction it would need
      record_slip_start(stats, s.t, sigma);
    }
    s.slip(sigma, t_end);
  }
  st.t = s.t, st.x = s.x, st.u = s.u, st.h = s.h, st.w = s.w;
  st.mode = s.mode == FeederMode::slip && s.u == 0 ? FeederMode::stick : s.mode;
}

}  // namespace selfalign::detail
