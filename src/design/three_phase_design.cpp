#include "selfalign/design/three_phase_design.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/design/local_search.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"

namespace selfalign {

namespace {


// Velocity-limit and case-0 constraints of (a2, a3), both as g <= 0 (relative).
struct ThreePhaseConstraints {
  double velocity;  // max(y'_ini, D - y'_ini) / y'_max - 1
  double physical;  // s / s_max - 1
};

ThreePhaseConstraints constraints_of(const ActuatorLimits& l, const ThreePhaseSolution& s,
                                     double max_velocity) {
  return {max_velocity / l.max_velocity - 1.0,
          s.inverse_accel_sum / s.inverse_accel_limit - 1.0};
}

}  // namespace

ThreePhaseDesignPoint evaluate_three_phase(const ActuatorLimits& l, double a2, double a3,
                                           const FrictionLaw& law) {
  ThreePhaseDesignPoint p;
  const ThreePhaseParameters params{l.period, l.stroke, a2, a3};
  if (std::isfinite(l.max_jerk)) {  // ramps at the jerk limit (jerk_limited_three_phase.hpp)
    const JerkLimitedThreePhaseParameters jp{l.period, l.stroke, a2, a3, l.max_jerk};
    const JerkLimitedThreePhaseSolution s = solve_jerk_limited_three_phase(jp);
    if (!s.physical) return p;
    p.max_velocity = std::max(s.yd_ini, s.velocity_swing - s.yd_ini);
  } else {
    const ThreePhaseSolution s = solve_three_phase(params);
    if (!s.physical) return p;
    // Velocity extrema: y'_ini (on [t0, t1]) and y'_ini - D at t2, D = (t3 - t1) / s.
    const double swing = (s.t3 - s.t1) / s.inverse_accel_sum;
    p.max_velocity = std::max(s.yd_ini, swing - s.yd_ini);
  }
  const std::unique_ptr<TableProfile> profile = make_three_phase_profile(params, l.max_jerk);
  p.physical = true;
  const SteadyState st = steady_state(*profile, law);
  p.v_bar = trusted_v_bar(st, p.max_velocity, l.period);  // NaN when not trustworthy
  p.f = objective_f(p.v_bar);
  p.feasible = std::isfinite(p.v_bar) && p.max_velocity <= l.max_velocity * (1 + kFeasibilityTol) &&
               std::max(a2, a3) <= l.max_acceleration * (1 + kFeasibilityTol);
  return p;
}

OptimizationResult optimize_three_phase(const ActuatorLimits& l, const OptimizeOptions& o) {
  validate(l);
  validate(o);
  OptimizationResult r;
  r.family = "three-phase";
  r.limits = l;
  const double s_max = l.period * l.period / (8.0 * l.stroke);  // case-0 bound on 1/a2 + 1/a3
  // Physical needs 1/a2 + 1/a3 <= s_max, hence max(a2, a3) >= 2 / s_max.
  if (l.max_acceleration < 2.0 / s_max) {
    r.message = "no feasible three-phase profile: max_acceleration = " +
                format_number(l.max_acceleration) + " is binding (the stroke needs y''_max >= " +
                format_number(2.0 / s_max) + ")";
    return r;
  }
  const double lo = (1.0 / s_max) * (1.0 + 1e-9), hi = l.max_acceleration;
  // Geometric grid over (lo, hi]: the objective varies on the scale of the accelerations.
  const int n = o.grid;
  std::vector<double> g(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    g[static_cast<std::size_t>(i)] = lo * std::pow(hi / lo, (i + 1.0) / n);
  struct Cell {
    double a2, a3, objective, violation;
    bool feasible;
  };
  std::vector<Cell> cells;
  for (double a2 : g)
    for (double a3 : g) {
      const ThreePhaseDesignPoint p = evaluate_three_phase(l, a2, a3, o.law);
      ++r.evaluations;
      if (!p.physical) continue;
      cells.push_back({a2, a3, design_objective(p.v_bar, l.period, l.stroke),
                       p.max_velocity / l.max_velocity - 1.0, p.feasible});
    }
  // Best cells first: feasible by objective, then the least violating.
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) {
    if (a.feasible != b.feasible) return a.feasible;
    return a.feasible ? a.objective < b.objective : a.violation < b.violation;
  });
  std::vector<std::vector<double>> starts;
  for (const Cell& c : cells) {
    if (static_cast<int>(starts.size()) >= (c.feasible ? o.polish : 1)) break;
    starts.push_back({c.a2, c.a3});
  }
  if (starts.empty()) starts.push_back({hi, hi});

  LocalSearchProblem problem;
  problem.lower = {lo, lo};
  problem.upper = {hi, hi};
  problem.constraint_names = {"max_velocity", "case 0 (1/a2 + 1/a3 <= period^2/(8 stroke))"};
  problem.max_evaluations = o.max_evaluations;
  problem.feasibility_tol = kFeasibilityTol;
  problem.evaluate = [&l, &o, s_max](std::span<const double> x) {
    DesignEvaluation e;
    const ThreePhaseSolution s = solve_three_phase({l.period, l.stroke, x[0], x[1]});
    if (!s.physical) {  // case 0: the solution's fields are 0, so compute s here
      e.objective = design_objective(-1.0, l.period, l.stroke);
      e.constraints = {1e3, (1.0 / x[0] + 1.0 / x[1]) / s_max - 1.0};
      return e;
    }
    const ThreePhaseDesignPoint p = evaluate_three_phase(l, x[0], x[1], o.law);
    if (!p.physical) {  // no ramped profile at this jerk (jerk-limited case 0)
      e.objective = design_objective(-1.0, l.period, l.stroke);
      e.constraints = {1e3, 1e3};
      return e;
    }
    const ThreePhaseConstraints c = constraints_of(l, s, p.max_velocity);
    e.objective = design_objective(p.v_bar, l.period, l.stroke);
    e.constraints = {c.velocity, c.physical};
    return e;
  };
  const LocalSearchResult best = local_search(problem, starts, o.progress);
  r.evaluations += best.evaluations;
  r.starts = best.runs;
  if (!best.feasible) {
    r.message = "no feasible three-phase profile: " + best.binding + " = " +
                format_number(l.max_velocity) + " is binding (least violation " +
                format_number(best.violation) + " relative)";
    if (best.binding != "max_velocity")
      r.message = "no feasible three-phase profile: " + best.binding + " is binding";
    return r;
  }
  const ThreePhaseDesignPoint p = evaluate_three_phase(l, best.x[0], best.x[1], o.law);
  r.parameters = best.x;
  r.max_jerk = l.max_jerk;
  r.v_bar = p.v_bar;
  r.f = p.f;
  r.max_velocity = p.max_velocity;
  r.max_acceleration = std::max(best.x[0], best.x[1]);
  r.feasible = p.feasible && p.v_bar > 0;
  r.message = r.feasible ? "optimum of a " + std::to_string(n) + "x" + std::to_string(n) +
                               " scan polished by LN_COBYLA from " +
                               std::to_string(best.runs) + " cells"
                         : "no three-phase profile moves the object forward within the limits";
  return r;
}

OptimizationResult three_phase_seed(const ActuatorLimits& l, const OptimizeOptions& o,
                                    const OptimizationResult* given, int& evaluations) {
  if (given && given->feasible) return *given;
  OptimizeOptions q = o;
  q.progress = nullptr;
  OptimizationResult three = optimize_three_phase(l, q);
  evaluations += three.evaluations;
  return three;
}

}  // namespace selfalign
