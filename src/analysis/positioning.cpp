#include "selfalign/analysis/positioning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "parallel_cells.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
void validate(const PositioningOptions& o) {
  // Each entry is a stopping run of up to max_periods periods: bounded so a call ends.
  if (o.entries < 1 || o.entries > 100'000)
    throw InvalidParameter("entries", o.entries, "must be in [1, 1e5]");
  if (o.stopping.max_periods < 1)
    throw InvalidParameter("max_periods", o.stopping.max_periods, "must be >= 1");
}

namespace {


// Δx of Sect. 7.1: the largest displacement in one period from x = 0, x' = v0 at phase 0, by
// the exact solver's arcs or the slip integrator's intervals (D27: under a speed-dependent
// law the arcs were asked of the integrator, which has none, and Δx came out as -inf).
double largest_displacement(const PeriodMap& map, double v0) {
  Reach reach;
  map(0, v0, &reach);
  return reach.x;
}

}  // namespace

PositioningAccuracy positioning_accuracy(const TableProfile& profile, double width, double c_mu,
                                         const PositioningOptions& o) {
  return positioning_accuracy(profile, FrictionLaw{}, width, c_mu, o);
}

namespace {

// Sect. 7.1 once the steady state and Δx are known: the entries x0 in [X - Δx - v̄Δt, X - Δx]
// walk onto `friction`, whose rise is X, and their stopping runs give eq. (39).
void run_entries(PositioningAccuracy& r, const TableProfile& profile, const FrictionLaw& law,
                 const FrictionMap& friction, double dx, const PositioningOptions& o) {
  const double X = r.x_mu;
  const double span = r.steady.v_bar * profile.period();
  r.entries = o.entries == 1 ? std::vector<double>{0.0} : linear_grid(-span, 0.0, o.entries);
  const double offset = X - dx;  // 0 on the paper's table, where x_mu = Δx
  if (offset != 0)
    for (double& x0 : r.entries) x0 += offset;
  r.overshoot_min = std::numeric_limits<double>::infinity();
  r.overshoot_max = -std::numeric_limits<double>::infinity();
  r.all_stopped = true;
  for (double x0 : r.entries) {
    r.runs.push_back(
        stopping_run(profile, friction, law, {0, x0, r.steady.x_dot_0s}, o.stopping));
    const StoppingRun& run = r.runs.back();
    if (run.kind == StopKind::not_stopped) {
      r.all_stopped = false;
      if (o.stop_at_first_failure) break;
      continue;
    }
    r.accumulating_entries += run.kind == StopKind::accumulation;
    r.overshoot_min = std::min(r.overshoot_min, run.end_position - X);
    r.overshoot_max = std::max(r.overshoot_max, run.end_position - X);
  }
  r.accumulates = r.all_stopped && r.accumulating_entries == o.entries;
  if (r.all_stopped) {
    r.dx_d = 0.5 * (r.overshoot_max - r.overshoot_min);  // eq. (39)
    r.x_d = X + r.overshoot_min + r.dx_d;
  } else {
    r.dx_d = r.x_d = kNaN;
  }
}

// The level a positioning study walks onto: piecewise affine, 1 before a rise (InvalidParameter
// naming "friction" otherwise).
const PiecewiseAffineFriction* require_positioning_level(const FrictionMap& friction) {
  const PiecewiseAffineFriction* pieces = friction.piecewise_affine();
  if (!pieces)
    throw InvalidParameter("friction", "not piecewise affine",
                           "positioning needs a piecewise-affine friction level (a field of "
                           "steps, or ramps under a point footprint)");
  if (!std::isfinite(friction_rise(*pieces)))
    throw InvalidParameter("friction", "uniform", "positioning needs a rise of friction");
  if (pieces->pieces().front().bound_at_begin != 1.0)
    throw InvalidParameter("friction", pieces->pieces().front().bound_at_begin,
                           "the level before the rise must be 1 (mu_1): the part arrives in "
                           "the steady state of the uniform table");
  return pieces;
}

// The steady state the part arrives in and Δx, its largest displacement in one steady period
// (Sect. 7.1, from x = 0 at phase 0); false (and the numbers NaN) when v̄ <= 0.
bool arrive(PositioningAccuracy& r, const TableProfile& profile, const FrictionLaw& law,
            const PositioningOptions& o, double& dx) {
  r.steady = steady_state(profile, law, o.steady);
  r.reaches = r.steady.v_bar > 0;
  if (!r.reaches) {
    r.x_mu = r.x_stick_min = r.overshoot_min = r.overshoot_max = r.dx_d = r.x_d = kNaN;
    return false;
  }
  // Δx from the steady period the search found: under the same integrator tolerances.
  const PeriodMap map(profile, law, PeriodMapOptions{.integrator = o.steady.integrator});
  dx = largest_displacement(map, r.steady.x_dot_0s);
  return true;
}

// Sect. 7.1 on `friction` once the part has arrived (r.steady, Δx = dx): x_mu is the level's
// rise, x_stick,min eq. (41) (the two-region table's closed form under the paper's law, the
// level's pieces otherwise), then the entries.
void walk_onto(PositioningAccuracy& r, const TableProfile& profile, const FrictionLaw& law,
               const FrictionMap& friction, double dx, const PositioningOptions& o) {
  r.x_mu = friction_rise(friction);
  const TwoRegionTable* two = friction.two_region();
  r.x_stick_min = two && law.is_unit()
                      ? stick_position_min(*two, profile.peak_acceleration())
                      : stick_position_min(*friction.piecewise_affine(), law,
                                           profile.peak_acceleration());
  run_entries(r, profile, law, friction, dx, o);
}

}  // namespace

PositioningAccuracy positioning_accuracy(const TableProfile& profile, const FrictionLaw& law,
                                         double width, double c_mu,
                                         const PositioningOptions& o) {
  validate(o);
  require_exact_profile(profile, "positioning");
  TwoRegionTable(0.0, width, c_mu);  // validates width and c_mu by name
  PositioningAccuracy r;
  double dx = 0;
  if (!arrive(r, profile, law, o, dx)) return r;
  // The paper's placement: x_mu = Δx.
  walk_onto(r, profile, law, two_region_friction(dx, width, c_mu), dx, o);
  return r;
}

PositioningAccuracy positioning_accuracy(const TableProfile& profile, const FrictionLaw& law,
                                         const FrictionMap& friction,
                                         const PositioningOptions& o) {
  validate(o);
  require_exact_profile(profile, "positioning");
  // The paper's table where it stands needs no check: its eq. (41) and accumulation proof apply.
  if (!friction.two_region()) require_positioning_level(friction);
  PositioningAccuracy r;
  double dx = 0;
  if (!arrive(r, profile, law, o, dx)) return r;
  walk_onto(r, profile, law, friction, dx, o);
  return r;
}

namespace {

// The Fig. 17 cells, each the positioning accuracy `accuracy(profile, options)` of its profile.
template <class Accuracy>
std::vector<PositioningCell> surfaces(double period, double stroke,
                                      const std::vector<double>& a2,
                                      const std::vector<double>& a3, const PositioningOptions& o,
                                      const SweepOptions& sweep, const Accuracy& accuracy) {
  require_positive("period", period);
  require_positive("stroke", stroke);
  validate(o);  // up front, not from inside a worker thread
  for (double v : a2) require_positive("a2", v);
  for (double v : a3) require_positive("a3", v);
  std::vector<PositioningCell> cells(a2.size() * a3.size());
  PositioningOptions per_cell = o;
  per_cell.stopping.fractions = {0.99, 0.999};
  per_cell.stop_at_first_failure = true;
  detail::parallel_cells(cells.size(), sweep, [&](std::size_t k) {
    PositioningCell& c = cells[k];
    c.a2 = a2[k / a3.size()];
    c.a3 = a3[k % a3.size()];
    const ThreePhaseParameters p{period, stroke, c.a2, c.a3};
    if (!three_phase_is_physical(p, sweep.jerk)) {
      c.f = c.dx_d = kNaN;
      return;
    }
    const std::unique_ptr<TableProfile> profile = make_three_phase_profile(p, sweep.jerk);
    const PositioningAccuracy acc = accuracy(*profile, per_cell);
    c.motion_case = acc.steady.motion_case;
    c.f = acc.steady.f;
    c.accumulates = acc.accumulates;
    c.accumulating_entries = acc.accumulating_entries;
    c.dx_d = acc.dx_d;
    // Periods from entry to p = 0.99 / 0.999 over the accumulating entries (Sect. 7.3).
    for (const StoppingRun& run : acc.runs) {
      if (run.kind != StopKind::accumulation) continue;
      c.max_periods_p99 = std::max(c.max_periods_p99, run.periods_to_fraction[0]);
      c.max_periods_p999 = std::max(c.max_periods_p999, run.periods_to_fraction[1]);
    }
  }, [&](std::size_t k, const std::string& why) {
    PositioningCell& c = cells[k];
    c = PositioningCell{};
    c.a2 = a2[k / a3.size()];
    c.a3 = a3[k % a3.size()];
    c.f = c.dx_d = kNaN;
    c.failure = why;
  });
  return cells;
}

}  // namespace

std::vector<PositioningCell> positioning_surfaces(double period, double stroke, double width,
                                                  double c_mu, const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const PositioningOptions& o,
                                                  const SweepOptions& sweep) {
  TwoRegionTable(0.0, width, c_mu);  // validates width and c_mu by name
  return surfaces(period, stroke, a2, a3, o, sweep,
                  [&](const TableProfile& profile, const PositioningOptions& per_cell) {
                    return positioning_accuracy(profile, sweep.law, width, c_mu, per_cell);
                  });
}

std::vector<PositioningCell> positioning_surfaces(double period, double stroke,
                                                  const FrictionMap& friction,
                                                  const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const PositioningOptions& o,
                                                  const SweepOptions& sweep) {
  require_positioning_level(friction);
  return surfaces(period, stroke, a2, a3, o, sweep,
                  [&](const TableProfile& profile, const PositioningOptions& per_cell) {
                    return positioning_accuracy(profile, sweep.law, friction, per_cell);
                  });
}

}  // namespace selfalign
