#include "selfalign/design/process_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/analysis/positioning.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/special_values.hpp"
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
  if (q.width < 1e-9 * q.distance)  // TwoRegionTable's resolution bound at x_mu ~ distance
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
  return make_three_phase_profile(r.dimensionless, r.jerk_dimensionless);
}

namespace {


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

DesignGrid::DesignGrid(const DesignRequest& q) : request_(q) {
  validate(q);
  const Scales sc(q.width, q.mu, q.gravity);  // L = width, so w = 1 in model units
  const double a_max = sc.acceleration_from_si(q.acceleration_max);
  v_max_ = sc.velocity_from_si(q.velocity_max);
  jerk_ = sc.acceleration_from_si(q.jerk_max) * sc.time();  // [m/s^3] -> [-]
  a_hi_ = std::min(q.c_mu, a_max);
  if (a_hi_ <= 1) return;  // nothing moves the object: an empty grid
  periods_ = log_grid(sc.time_from_si(1 / q.frequency_max), sc.time_from_si(1 / q.frequency_min),
                      q.period_grid);
  for (int k = q.stroke_grid; k >= 1; --k)
    strokes_.push_back(sc.length_from_si(q.stroke_max) * k / q.stroke_grid);
  a2s_ = linear_grid(1 + (a_hi_ - 1) / q.acceleration_grid, a_hi_, q.acceleration_grid);
  a3s_ = linear_grid(a_hi_ / q.acceleration_grid, a_hi_, q.acceleration_grid);
  size_ = periods_.size() * strokes_.size() * a2s_.size() * a3s_.size();
}

std::optional<ThreePhaseParameters> DesignGrid::at(std::size_t i, Skip* why) const {
  // Periods outermost, then strokes (largest first), y2'', y3''.
  const std::size_t n3 = a3s_.size(), n2 = a2s_.size(), ns = strokes_.size();
  const ThreePhaseParameters p{periods_[i / (n3 * n2 * ns)], strokes_[i / (n3 * n2) % ns],
                               a2s_[i / n3 % n2], a3s_[i % n3]};
  double yd_ini = 0, D = 0;  // y' on the hold (its largest) and the swing (eq. 65)
  bool physical = false;
  if (std::isinf(jerk_)) {
    const ThreePhaseSolution s = solve_three_phase(p);
    physical = s.physical, yd_ini = s.yd_ini, D = p.a2 * (s.t2 - s.t1);
  } else {
    const JerkLimitedThreePhaseSolution s =
        solve_jerk_limited_three_phase({p.period, p.stroke, p.a2, p.a3, jerk_});
    physical = s.physical, yd_ini = s.yd_ini, D = s.velocity_swing;
  }
  const Skip skip = !physical                             ? Skip::non_physical
                    : std::max(yd_ini, D - yd_ini) > v_max_ ? Skip::too_fast
                                                            : Skip::none;
  if (why) *why = skip;
  if (skip != Skip::none) return std::nullopt;
  return p;
}

std::string DesignGrid::empty_message(std::size_t non_physical, std::size_t too_fast) const {
  const DesignRequest& q = request_;
  if (a_hi_ <= 1)
    return "acceleration_max = " + format_number(q.acceleration_max) +
           " m/s^2 binds: the table must exceed mu g = " + format_number(q.mu * q.gravity) +
           " m/s^2 to make the object slip";
  return "no three-phase profile fits the limits: " + std::to_string(non_physical) +
         " candidates cannot reach the stroke (stroke_max, frequency_min, acceleration_max and "
         "jerk_max bind: case 0), " + std::to_string(too_fast) +
         " exceed velocity_max = " + format_number(q.velocity_max) + " m/s";
}

std::vector<std::string> DesignGrid::pinned_limits(const ThreePhaseParameters& p) const {
  const DesignRequest& q = request_;
  const DesignRequest defaults;
  std::vector<std::string> out;
  const auto pinned = [&](const std::string& what, const char* name, double value,
                          double default_value, const char* unit) {
    out.push_back(what + " at " + name + " = " + format_number(value) + " " + unit +
                  (value == default_value ? " (the default)" : ""));
  };
  if (periods_.empty()) return out;
  // The grid's own values: the same numbers the search used, so equality is exact.
  if (periods_.size() > 1 || q.frequency_min == q.frequency_max) {
    if (p.period == periods_.back())
      pinned("frequency", "frequency_min", q.frequency_min, defaults.frequency_min, "Hz");
    if (p.period == periods_.front() && q.frequency_min != q.frequency_max)
      pinned("frequency", "frequency_max", q.frequency_max, defaults.frequency_max, "Hz");
  }
  if (p.stroke == strokes_.front())
    pinned("stroke", "stroke_max", q.stroke_max, defaults.stroke_max, "m");
  if (std::max(p.a2, p.a3) == a_hi_) {
    if (a_hi_ < q.c_mu)
      pinned("peak acceleration", "acceleration_max", q.acceleration_max,
             defaults.acceleration_max, "m/s^2");
    else
      out.push_back("peak acceleration at the grid's top c_mu mu g = " +
                    format_number(q.c_mu * q.mu * q.gravity) +
                    " m/s^2 (the search's bound: with mu_static = mu the part stops for good only below it, "
                    "eq. 40)");
  }
  return out;
}

namespace {

// What one chunk of the grid leaves for the selection: its best candidate and its counts.
struct ChunkResult {
  std::size_t candidates = 0, feasible = 0, reaching = 0, non_physical = 0, too_fast = 0;
  double best_dx_d = kInf;
  bool found = false;
  Candidate best{};
};

// Grid points a parallel chunk evaluates, one after the other. A chunk is the parallel loop's
// cell, so a front end's cancellation (Ctrl-C) waits for at most the chunks in flight: 32
// candidates of the default grid take ~0.1 s, where 1024 took over 1 s (python
// test_interrupt's 0.8 s bound, missed in CI). Any size gives the same design: the chunks
// merge in order and keep the first best candidate.
constexpr std::size_t kChunk = 32;

// Evaluates one grid candidate: its steady state, positioning accuracy and estimated T_p.
void evaluate(Candidate& c, double jerk, const FrictionLaw& law, double c_mu, double distance,
              double tolerance, const PositioningOptions& po) {
  c.evaluated = true;
  const std::unique_ptr<TableProfile> profile = make_three_phase_profile(c.p, jerk);
  const PositioningAccuracy acc = positioning_accuracy(*profile, law, 1.0, c_mu, po);
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
}

}  // namespace

DesignResult design_process(const DesignRequest& q, const SweepOptions& sweep) {
  const DesignGrid grid(q);
  const double work = static_cast<double>(q.acceleration_grid) * q.acceleration_grid *
                      q.period_grid * q.stroke_grid * q.entries;
  if (work > kMaxDesignEntries)
    throw InvalidParameter(
        "grid",
        std::to_string(q.acceleration_grid) + "^2 x " + std::to_string(q.period_grid) + " x " +
            std::to_string(q.stroke_grid) + " x " + std::to_string(q.entries) + " = " +
            format_number(work) + " steady entries",
        "acceleration_grid^2 x period_grid x stroke_grid x entries must be <= 1e9 (about 8 h "
        "on one core); lower one of them");
  const Scales sc(q.width, q.mu, q.gravity);
  const double distance = sc.length_from_si(q.distance);
  const double tolerance = sc.length_from_si(q.tolerance);
  const double jerk = grid.jerk();
  const FrictionLaw law = friction_law(q);

  PositioningOptions po;
  po.entries = q.entries;
  po.stopping.max_periods = 300;
  po.stopping.fractions = {kFraction};
  po.stop_at_first_failure = true;
  // Each chunk keeps its first best candidate (lowest index on ties); the chunks merge in
  // order, so the result is the sequential search's for any thread count.
  std::vector<ChunkResult> chunks((grid.size() + kChunk - 1) / kChunk);
  detail::parallel_cells(chunks.size(), sweep, [&](std::size_t k) {
    ChunkResult& r = chunks[k];
    for (std::size_t i = k * kChunk; i < std::min(grid.size(), (k + 1) * kChunk); ++i) {
      DesignGrid::Skip why = DesignGrid::Skip::none;
      const std::optional<ThreePhaseParameters> p = grid.at(i, &why);
      r.non_physical += why == DesignGrid::Skip::non_physical;
      r.too_fast += why == DesignGrid::Skip::too_fast;
      if (!p) continue;
      ++r.candidates;
      Candidate c{*p};
      try {
        evaluate(c, jerk, law, q.c_mu, distance, tolerance, po);
      } catch (const std::exception&) {
        // A candidate the analysis cannot resolve (e.g. its one-period displacement is 1e9
        // object widths, beyond the transition region's resolution) is not a design, not an
        // error.
        c.reaches = c.positioned = false;
      }
      r.reaching += c.reaches;
      if (c.reaches) r.best_dx_d = std::min(r.best_dx_d, c.dx_d);
      if (!c.positioned) continue;
      ++r.feasible;
      if (!r.found || c.estimate < r.best.estimate) r.best = c, r.found = true;
    }
  });

  DesignResult r;
  ChunkResult all;
  for (const ChunkResult& c : chunks) {
    all.candidates += c.candidates, all.feasible += c.feasible, all.reaching += c.reaching;
    all.non_physical += c.non_physical, all.too_fast += c.too_fast;
    all.best_dx_d = std::min(all.best_dx_d, c.best_dx_d);
    if (c.found && (!all.found || c.best.estimate < all.best.estimate)) all.best = c.best, all.found = true;
  }
  r.candidates = static_cast<int>(all.candidates);
  r.feasible_candidates = static_cast<int>(all.feasible);
  if (all.candidates == 0) {
    r.message = grid.empty_message(all.non_physical, all.too_fast);
    return r;
  }
  if (!all.found) {
    r.message = all.reaching == 0
                    ? "no candidate moves the object forward and stops it (acceleration_max, "
                      "velocity_max and c_mu bind)"
                    : "the positioning requirement binds: no candidate " +
                          std::string(tolerance == 0 ? "accumulates (Δx_d = 0)"
                                                     : "reaches the tolerance") +
                          "; the smallest Δx_d found is " +
                          format_number(sc.length_to_si(all.best_dx_d)) + " m";
    return r;
  }

  DesignResult described = describe_design(q, all.best.p, all.best.x_mu, all.best.dx_d);
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
  const std::unique_ptr<TableProfile> profile = make_three_phase_profile(p, jerk);
  const SteadyState steady = steady_state(*profile, law);
  r.motion_case = steady.motion_case;
  r.v_bar = sc.velocity_to_si(steady.v_bar);
  const FieldFriction friction = two_region_friction(x_mu, 1.0, q.c_mu);
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
  r.limits = DesignGrid(q).pinned_limits(p);
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
