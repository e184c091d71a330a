#include "selfalign/design/process_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/analysis/positioning.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/units.hpp"

namespace selfalign {

void validate(const DesignRequest& q) {
  // Positive scales within [1e-50, 1e50] (error.hpp): beyond, their ratios overflow.
  require_positive_moderate("mass", q.mass);
  require_positive_moderate("width", q.width);
  require_positive_moderate("mu", q.mu);
  require_greater("c_mu", q.c_mu, 1.0);
  require_moderate("c_mu", q.c_mu);
  require_positive_moderate("g", q.gravity);
  require_positive_moderate("distance", q.distance);
  require_positive_moderate("stroke_max", q.stroke_max);
  require_positive_moderate("frequency_min", q.frequency_min);
  require_greater("frequency_max", q.frequency_max, q.frequency_min * (1 - 1e-15));
  require_positive_moderate("frequency_max", q.frequency_max);
  require_positive_moderate("velocity_max", q.velocity_max);
  require_positive_moderate("acceleration_max", q.acceleration_max);
  if (!(q.jerk_max > 0) || std::isnan(q.jerk_max))
    throw InvalidParameter("jerk_max", q.jerk_max, "must be > 0 [m/s^3] (+inf: jump accelerations)");
  friction_law(q);
  require_non_negative("tolerance", q.tolerance);
  require_moderate("tolerance", q.tolerance);
  if (q.width < 1e-9 * q.distance)  // TwoRegionFriction's resolution bound at x_mu ~ distance
    throw InvalidParameter("width", q.width,
                           "must be >= 1e-9 x distance = " + format_number(1e-9 * q.distance) +
                               " m (the transition region must be resolvable at the end position)");
  if (q.acceleration_grid < 2 || q.acceleration_grid > 200)
    throw InvalidParameter("acceleration_grid", q.acceleration_grid, "must be in [2, 200]");
  if (q.period_grid < 1 || q.period_grid > 100)
    throw InvalidParameter("period_grid", q.period_grid, "must be in [1, 100]");
  if (q.stroke_grid < 1 || q.stroke_grid > 20)
    throw InvalidParameter("stroke_grid", q.stroke_grid, "must be in [1, 20]");
  if (q.entries < 2 || q.entries > 1000)
    throw InvalidParameter("entries", q.entries, "must be in [2, 1000]");
}

FrictionLaw friction_law(const DesignRequest& q) {
  return law_of_coefficients(q.mu, q.mu_static, q.mu_backward);
}

std::unique_ptr<TableProfile> recommended_profile(const DesignResult& r) {
  if (!r.feasible) throw InvalidParameter("result", "infeasible", "has no recommended profile");
  const ThreePhaseParameters& p = r.dimensionless;
  if (std::isinf(r.jerk_dimensionless)) return std::make_unique<ThreePhaseProfile>(p);
  return std::make_unique<JerkLimitedThreePhaseProfile>(
      JerkLimitedThreePhaseParameters{p.period, p.stroke, p.a2, p.a3, r.jerk_dimensionless});
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A candidate's profile: the paper's jump accelerations, or ramps at the jerk limit.
std::unique_ptr<TableProfile> candidate_profile(const ThreePhaseParameters& p, double jerk) {
  if (std::isinf(jerk)) return std::make_unique<ThreePhaseProfile>(p);
  return std::make_unique<JerkLimitedThreePhaseProfile>(
      JerkLimitedThreePhaseParameters{p.period, p.stroke, p.a2, p.a3, jerk});
}
constexpr double kFraction = 0.999;  // "arrived" for accumulation: p = 0.999 (Sect. 7.3)

struct Candidate {
  ThreePhaseParameters p;
  bool evaluated = false, reaches = false, positioned = false;
  double dx_d = kInf, x_mu = 0, estimate = kInf, v_bar = 0;
  StickSlipCase motion_case = StickSlipCase::non_physical;
};

// Settling time of one entry: from crossing x_mu to the final stop (or p = 0.999).
double settling(const StoppingRun& run) {
  const double done = run.kind == StopKind::accumulation ? run.time_to_fraction[0]
                                                         : run.process_time;
  return done - run.entry_time;
}

}  // namespace

DesignCandidates design_candidates(const DesignRequest& q) {
  validate(q);
  const Scales sc(q.width, q.mu, q.gravity);  // L = width, so w = 1 in model units
  const double a_max = sc.acceleration_from_si(q.acceleration_max);
  const double v_max = sc.velocity_from_si(q.velocity_max);
  DesignCandidates out;
  out.jerk = sc.acceleration_from_si(q.jerk_max) * sc.time();  // [m/s^3] -> [-]
  const double jerk = out.jerk;
  const double a_hi = std::min(q.c_mu, a_max);
  if (a_hi <= 1) {
    out.message = "acceleration_max = " + format_number(q.acceleration_max) +
                  " m/s^2 binds: the table must exceed mu g = " +
                  format_number(sc.acceleration()) + " m/s^2 to make the object slip";
    return out;
  }
  const std::vector<double> periods = log_grid(sc.time_from_si(1 / q.frequency_max),
                                               sc.time_from_si(1 / q.frequency_min), q.period_grid);
  const std::vector<double> a2s = linear_grid(1 + (a_hi - 1) / q.acceleration_grid, a_hi,
                                              q.acceleration_grid);
  const std::vector<double> a3s = linear_grid(a_hi / q.acceleration_grid, a_hi, q.acceleration_grid);
  int non_physical = 0, too_fast = 0;
  for (double period : periods)
    for (int k = q.stroke_grid; k >= 1; --k) {
      const double stroke = sc.length_from_si(q.stroke_max) * k / q.stroke_grid;
      for (double a2 : a2s)
        for (double a3 : a3s) {
          const ThreePhaseParameters p{period, stroke, a2, a3};
          double yd_ini = 0, D = 0;  // y' on the hold (its largest) and the swing (eq. 65)
          if (std::isinf(jerk)) {
            const ThreePhaseSolution s = solve_three_phase(p);
            if (!s.physical) {
              ++non_physical;
              continue;
            }
            yd_ini = s.yd_ini;
            D = a2 * (s.t2 - s.t1);
          } else {
            const JerkLimitedThreePhaseSolution s =
                solve_jerk_limited_three_phase({period, stroke, a2, a3, jerk});
            if (!s.physical) {
              ++non_physical;
              continue;
            }
            yd_ini = s.yd_ini;
            D = s.velocity_swing;
          }
          if (std::max(yd_ini, D - yd_ini) > v_max) {
            ++too_fast;
            continue;
          }
          out.profiles.push_back(p);
        }
    }
  if (out.profiles.empty())
    out.message = "no three-phase profile fits the limits: " + std::to_string(non_physical) +
                  " candidates cannot reach the stroke (stroke_max, frequency_min, "
                  "acceleration_max and jerk_max bind: case 0), " + std::to_string(too_fast) +
                  " exceed velocity_max = " + format_number(q.velocity_max) + " m/s";
  return out;
}

DesignResult design_process(const DesignRequest& q, const SweepOptions& sweep) {
  const DesignCandidates grid = design_candidates(q);
  const Scales sc(q.width, q.mu, q.gravity);
  const double distance = sc.length_from_si(q.distance);
  const double tolerance = sc.length_from_si(q.tolerance);
  const double jerk = grid.jerk;
  const FrictionLaw law = friction_law(q);
  DesignResult r;
  std::vector<Candidate> cands;
  for (const ThreePhaseParameters& p : grid.profiles) cands.push_back({p});
  r.candidates = static_cast<int>(cands.size());
  if (cands.empty()) {
    r.message = grid.message;
    return r;
  }

  PositioningOptions po;
  po.entries = q.entries;
  po.stopping.max_periods = 300;
  po.stopping.fractions = {kFraction};
  po.stop_at_first_failure = true;
  detail::parallel_cells(cands.size(), sweep, [&](std::size_t i) {
    Candidate& c = cands[i];
    c.evaluated = true;
    const std::unique_ptr<TableProfile> profile = candidate_profile(c.p, jerk);
    const PositioningAccuracy acc = positioning_accuracy(*profile, law, 1.0, q.c_mu, po);
    c.motion_case = acc.steady.motion_case;
    c.v_bar = acc.steady.v_bar;
    c.reaches = acc.reaches && acc.all_stopped;
    if (!c.reaches) return;
    c.dx_d = acc.dx_d;
    c.positioned = tolerance == 0 ? acc.accumulates : acc.dx_d <= tolerance;
    if (!c.positioned) return;
    // x_d = x_mu + overshoot_min + Δx_d must be the requested distance.
    c.x_mu = distance - (acc.overshoot_min + acc.dx_d);
    if (c.x_mu <= 0) {
      c.positioned = false;
      return;
    }
    double settle = 0;
    for (const StoppingRun& run : acc.runs) settle = std::max(settle, settling(run));
    c.estimate = c.x_mu / c.v_bar + settle;
  }, [&](std::size_t i, const std::string&) {
    // A candidate the analysis cannot resolve (e.g. its one-period displacement is 1e9 object
    // widths, beyond the transition region's resolution) is not a design, not an error.
    cands[i].evaluated = true;
    cands[i].reaches = cands[i].positioned = false;
  });

  const Candidate* best = nullptr;
  double best_dx_d = kInf;
  int reaching = 0;
  for (const Candidate& c : cands) {
    reaching += c.reaches;
    if (c.reaches) best_dx_d = std::min(best_dx_d, c.dx_d);
    if (!c.positioned) continue;
    ++r.feasible_candidates;
    if (!best || c.estimate < best->estimate) best = &c;
  }
  if (!best) {
    r.message = reaching == 0
                    ? "no candidate moves the object forward and stops it (acceleration_max, "
                      "velocity_max and c_mu bind)"
                    : "the positioning requirement binds: no candidate " +
                          std::string(tolerance == 0 ? "accumulates (Δx_d = 0)"
                                                     : "reaches the tolerance") +
                          "; the smallest Δx_d found is " +
                          format_number(sc.length_to_si(best_dx_d)) + " m";
    return r;
  }

  DesignResult described = describe_design(q, best->p, best->x_mu, best->dx_d);
  described.candidates = r.candidates;
  described.feasible_candidates = r.feasible_candidates;
  return described;
}

DesignResult describe_design(const DesignRequest& q, const ThreePhaseParameters& p, double x_mu,
                             double dx_d) {
  const Scales sc(q.width, q.mu, q.gravity);
  const double jerk = sc.acceleration_from_si(q.jerk_max) * sc.time();
  const FrictionLaw law = friction_law(q);
  DesignResult r;
  const std::unique_ptr<TableProfile> profile = candidate_profile(p, jerk);
  const SteadyState steady = steady_state(*profile, law);
  r.motion_case = steady.motion_case;
  r.v_bar = sc.velocity_to_si(steady.v_bar);
  const TwoRegionFriction friction(x_mu, 1.0, q.c_mu);
  StoppingOptions so;
  so.fractions = {kFraction};
  const StoppingRun run = stopping_run(*profile, friction, law, {0, 0, 0}, so);
  // Switch times: the jump profile's t1, t2, t3; under a jerk limit the starts of the ramps
  // down to -y2'' and up to +y3'', and the period.
  double t1 = 0, t2 = 0, t3 = p.period, y_ini = 0, yd_ini = 0, swing = 0;
  if (std::isinf(jerk)) {
    const ThreePhaseSolution s = solve_three_phase(p);
    t1 = s.t1, t2 = s.t2, t3 = s.t3, y_ini = s.y_ini, yd_ini = s.yd_ini;
    swing = p.a2 * (s.t2 - s.t1);
  } else {
    const JerkLimitedThreePhaseSolution s = solve_jerk_limited_three_phase(
        {p.period, p.stroke, p.a2, p.a3, jerk});
    t1 = s.hold0;
    t2 = t1 + s.ramp_down + s.hold2;
    y_ini = profile->state(0).y, yd_ini = s.yd_ini, swing = s.velocity_swing;
  }
  r.feasible = run.kind != StopKind::not_stopped;
  r.message = r.feasible ? "ok" : "the recommended profile did not stop from rest";
  r.dimensionless = p;
  r.jerk_dimensionless = jerk;
  r.jerk = q.jerk_max;
  r.x_mu_dimensionless = x_mu;
  r.period = sc.time_to_si(p.period);
  r.stroke = sc.length_to_si(p.stroke);
  r.a2 = sc.acceleration_to_si(p.a2);
  r.a3 = sc.acceleration_to_si(p.a3);
  r.t1 = sc.time_to_si(t1);
  r.t2 = sc.time_to_si(t2);
  r.t3 = sc.time_to_si(t3);
  r.y_ini = sc.length_to_si(y_ini);
  r.y_dot_ini = sc.velocity_to_si(yd_ini);
  r.velocity_peak = sc.velocity_to_si(std::max(yd_ini, swing - yd_ini));
  r.x_mu = sc.length_to_si(x_mu);
  r.stop = run.kind;
  // Accumulation ends at x_stick,min in the limit; "arrived" is p = 0.999 of the way.
  const double band = run.kind == StopKind::accumulation
                          ? (1 - kFraction) * (run.x_stick_min - x_mu)
                          : dx_d;
  r.end_position = sc.length_to_si(run.end_position);
  r.error_band = sc.length_to_si(std::max(band, dx_d));
  r.process_time = sc.time_to_si(run.kind == StopKind::accumulation ? run.time_to_fraction[0]
                                                                    : run.process_time);
  return r;
}

}  // namespace selfalign
