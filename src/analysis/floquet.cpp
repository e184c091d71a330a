#include "selfalign/analysis/floquet.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/analysis/period_map.hpp"

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

FloquetAnalysis floquet_multipliers(const TableProfile& profile, const FloquetOptions& o) {
  return floquet_multipliers(profile, FrictionLaw{}, o);
}

FloquetAnalysis floquet_multipliers(const TableProfile& profile, const FrictionLaw& law,
                                    const FloquetOptions& o) {
  if (!law.velocity_dependent()) require_exact_profile(profile, "Floquet analysis");
  else if (!integrable_profile(profile))
    throw InvalidParameter("profile", profile.kind(),
                           "Floquet analysis under a velocity-dependent law needs a "
                           "piecewise-polynomial or smooth table motion");
  PeriodMapOptions mo;
  mo.integrator = o.steady.integrator;
  const UniformFriction uniform(1.0);
  const PeriodMap map(profile, uniform, law, mo);
  return floquet_multipliers(map, o);
}

FloquetAnalysis floquet_multipliers(const PeriodMap& map, const FloquetOptions& o) {
  // Beyond 0.1 (a tenth of the length scale) a central difference approximates no derivative.
  require_in_half_open("fd_step", o.fd_step, 0.0, 0.1);
  // Saltation needs the arcs: refuse a time-stepping map by name. The integrator's map has no
  // closed-form arcs either, but its finite differences are accurate to its tolerance.
  const bool integrated = map.method() == Method::integrator;
  if (!map.has_arcs() && !integrated) map.exact_setup();
  FloquetAnalysis r;
  r.steady = steady_state(map, o.steady);
  // 2. Saltation: transition matrices of the arcs of one steady period, coupled at events.
  if (!integrated) r.saltation = make_monodromy(map.saltation_monodromy(0, r.steady.x_dot_0s));
  // 3. Central finite differences of the period map.
  r.finite_difference =
      make_monodromy(map.finite_difference_monodromy(0, r.steady.x_dot_0s, o.fd_step));
  if (integrated) {  // one method: no spread to report
    r.spread = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  r.spread = 0;
  for (int k = 0; k < 2; ++k)
    r.spread = std::max(r.spread, std::abs(r.saltation.multipliers[k] -
                                           r.finite_difference.multipliers[k]));
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
  const PeriodMap map(profile);
  const std::vector<Arc> arcs = map.arcs(0, r.steady.x_dot_0s);
  double scale = arcs.front().kind() == ArcKind::stick ? 0 : 1, m12 = 0, t_prev = 0;
  for (std::size_t i = 0; i + 1 < arcs.size() && scale != 0; ++i) {
    const Arc& arc = arcs[i];
    if (arc.end != ArcEnd::velocity_zero) continue;
    m12 += scale * (arc.t1 - t_prev);
    t_prev = arc.t1;
    if (arcs[i + 1].kind() == ArcKind::stick) {
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
