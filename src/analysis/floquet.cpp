#include "selfalign/analysis/floquet.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_constant.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {

Monodromy make_monodromy(const Eigen::Matrix2d& matrix) {
  Monodromy m;
  m.matrix = matrix;
  m.available = true;
  const Eigen::EigenSolver<Eigen::Matrix2d> solver(matrix, false);
  m.multipliers = {solver.eigenvalues()(0), solver.eigenvalues()(1)};
  if (std::abs(m.multipliers[1]) > std::abs(m.multipliers[0]))
    std::swap(m.multipliers[0], m.multipliers[1]);
  return m;
}

double slip_slip_multiplier(double a2, double a3) {
  require_positive("a2", a2);
  require_positive("a3", a3);
  return ((a2 - 1) * (a3 - 1)) / ((a2 + 1) * (a3 + 1));  // eq. (33)
}

namespace {

struct ArcList final : ArcSink {
  std::vector<Arc> arcs;
  void on_arc(const Arc& a) override { arcs.push_back(a); }
};

// x'' on arc `a` at position x (its start x0 or end x1).
double acceleration(const Arc& a, double x) {
  switch (a.kind) {
    case ArcKind::stick: return 0;
    case ArcKind::parabolic: return a.alpha;
    case ArcKind::harmonic: return -a.omega * a.omega * (x - a.center);
    case ArcKind::hyperbolic: return a.omega * a.omega * (x - a.center);
  }
  return 0;
}

Eigen::Matrix2d fundamental(const Arc& a) {  // Φ over one arc
  const double tau = a.t1 - a.t0;
  Eigen::Matrix2d m;
  switch (a.kind) {
    case ArcKind::stick:
      m << 1, 0, 0, 0;
      break;
    case ArcKind::parabolic:
      m << 1, tau, 0, 1;
      break;
    case ArcKind::harmonic: {
      const double c = std::cos(a.omega * tau), s = std::sin(a.omega * tau);
      m << c, s / a.omega, -a.omega * s, c;
      break;
    }
    case ArcKind::hyperbolic: {
      const double c = std::cosh(a.omega * tau), s = std::sinh(a.omega * tau);
      m << c, s / a.omega, a.omega * s, c;
      break;
    }
  }
  return m;
}

// Saltation matrix at the end of arc `a`, followed by arc `next`.
Eigen::Matrix2d saltation(const Arc& a, const Arc& next) {
  Eigen::Matrix2d s = Eigen::Matrix2d::Identity();
  if (a.end == ArcEnd::velocity_zero) {
    const double before = acceleration(a, a.x1), after = acceleration(next, next.x0);
    s(1, 1) = next.kind == ArcKind::stick || before == 0 ? 0.0 : after / before;
  } else if (a.end == ArcEnd::friction_boundary && a.xd1 != 0) {
    s(1, 0) = (acceleration(next, next.x0) - acceleration(a, a.x1)) / a.xd1;
  }
  return s;
}

}  // namespace

FloquetAnalysis floquet_multipliers(const TableProfile& profile, const FloquetOptions& o) {
  // Beyond 0.1 (a tenth of the length scale) a central difference approximates no derivative.
  require_in_half_open("fd_step", o.fd_step, 0.0, 0.1);
  const PiecewiseConstantProfile* pwc = profile.piecewise_constant();
  if (!pwc)
    throw InvalidParameter("profile", profile.kind(),
                           "Floquet analysis needs a piecewise-constant table acceleration");
  FloquetAnalysis r;
  r.steady = steady_state(profile, o.steady);
  const UniformFriction friction(1.0);
  const ExactSetup setup{*pwc, *friction.piecewise_affine()};
  const double P = profile.period();
  auto period_map = [&](double x0, double v0, ArcSink* sink) {
    ExactState s = make_exact_state(setup, {0, x0, v0});
    advance_exact(setup, s, P, sink);
    return s.object;
  };

  // 2. Saltation: fundamental solutions of the arcs of one steady period, coupled at events.
  ArcList list;
  period_map(0, r.steady.x_dot_0s, &list);
  // The arc that follows the period's last one is the next period's first.
  Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
  for (std::size_t i = 0; i < list.arcs.size(); ++i) {
    m = fundamental(list.arcs[i]) * m;
    const Arc& next = i + 1 < list.arcs.size() ? list.arcs[i + 1] : list.arcs.front();
    m = saltation(list.arcs[i], next) * m;
  }
  r.saltation = make_monodromy(m);

  // 3. Central finite differences of the period map.
  const double h = o.fd_step;
  Eigen::Matrix2d fd;
  for (int col = 0; col < 2; ++col) {
    const double dx = col == 0 ? h : 0, dv = col == 1 ? h : 0;
    const ObjectState plus = period_map(dx, r.steady.x_dot_0s + dv, nullptr);
    const ObjectState minus = period_map(-dx, r.steady.x_dot_0s - dv, nullptr);
    fd(0, col) = (plus.x - minus.x) / (2 * h);
    fd(1, col) = (plus.xd - minus.xd) / (2 * h);
  }
  r.finite_difference = make_monodromy(fd);
  r.spread = std::abs(r.saltation.multipliers[0] - r.finite_difference.multipliers[0]);
  r.spread = std::max(r.spread, std::abs(r.saltation.multipliers[1] - r.finite_difference.multipliers[1]));
  return r;
}

FloquetAnalysis floquet_multipliers(const ThreePhaseProfile& profile, const FloquetOptions& o) {
  FloquetAnalysis r = floquet_multipliers(static_cast<const TableProfile&>(profile), o);
  // 1. Analytic, eqs. (25)-(33): Φ = [[1, m12], [0, m22]]. A position shift passes through
  // unchanged; m22 = 0 once the response sticks (eq. 30) and λ2 = c4 of eq. (33) in slip-slip.
  // m12 = d x(t3)/d x'_0s (eqs. 28, 31): a velocity perturbation rides unchanged along a slip,
  // is scaled by x''+/x''- = (σ - y'')/(-σ - y'') at a reversal and erased at a stick; the
  // event times are those of the closed-form steady solution (the exact arcs).
  const ThreePhaseParameters& p = profile.parameters();
  ArcList list;
  const UniformFriction friction(1.0);
  const ExactSetup setup{*profile.piecewise_constant(), *friction.piecewise_affine()};
  ExactState s = make_exact_state(setup, {0, 0, r.steady.x_dot_0s});
  advance_exact(setup, s, p.period, &list);
  double scale = list.arcs.front().kind == ArcKind::stick ? 0 : 1, m12 = 0, t_prev = 0;
  for (std::size_t i = 0; i + 1 < list.arcs.size() && scale != 0; ++i) {
    const Arc& arc = list.arcs[i];
    if (arc.end != ArcEnd::velocity_zero) continue;
    m12 += scale * (arc.t1 - t_prev);
    t_prev = arc.t1;
    if (list.arcs[i + 1].kind == ArcKind::stick) {
      scale = 0;  // eq. (30): the stick erases the velocity perturbation
    } else {
      const double y_dd = arc.table_accel;
      scale *= (arc.direction - y_dd) / (-arc.direction - y_dd);
    }
  }
  m12 += scale * (p.period - t_prev);
  const bool slip_slip = r.steady.motion_case == StickSlipCase::slip_slip;
  Eigen::Matrix2d a;
  a << 1, m12, 0, slip_slip ? slip_slip_multiplier(p.a2, p.a3) : 0.0;
  r.analytic = make_monodromy(a);
  for (int k = 0; k < 2; ++k) {
    r.spread = std::max(r.spread, std::abs(r.analytic.multipliers[k] - r.saltation.multipliers[k]));
    r.spread = std::max(r.spread,
                        std::abs(r.analytic.multipliers[k] - r.finite_difference.multipliers[k]));
  }
  return r;
}

}  // namespace selfalign
