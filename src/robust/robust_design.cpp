#include "selfalign/robust/robust_design.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "../analysis/parallel_cells.hpp"
#include "robust_screen.hpp"
#include "selfalign/error.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

// The selection and the verification draw from streams of their own, not the screen's.
constexpr std::uint64_t kSelectionStream = 0x5eed0f0e11f1ca7eULL;
constexpr std::uint64_t kVerificationStream = 0x7e21f1ca7e0fd2a5ULL;
// Closed-form draws of the prune (screening draws 0 ... 2047, whatever screening_runs is).
constexpr int kBoundDraws = 2048;
// When no candidate can reach the target, the best closed-form bounds screened for the best
// achievable probability (the nominal runs of up to kBestBoundPool of them).
constexpr std::size_t kBestAchievableCandidates = 256;
constexpr std::size_t kBestBoundPool = 4096;
// Grid points a parallel chunk of the prune takes.
constexpr std::size_t kChunk = 1024;

const char* dominant(const FailureCounts& f) {
  if (f.outside + f.no_stop + f.no_motion == 0) return "none";
  if (f.outside >= f.no_stop && f.outside >= f.no_motion) return "end-position spread";
  return f.no_stop >= f.no_motion ? "stopping" : "motion";
}

std::string explain(const std::string& b) {
  if (b == "end-position spread")
    return "the spread of the end position (mu, c_mu, width and x_mu errors move where the "
           "part stops) exceeds the tolerance";
  if (b == "stopping")
    return "the peak table acceleration is too close to mu_static c_mu g: low mu or c_mu "
           "draws never stop (eq. 40)";
  if (b == "motion")
    return "y2'' is too close to mu_static g: high mu draws never reach the rough region";
  return b;
}

void validate(const RobustOptions& o, const DesignRequest& q) {
  if (!(o.probability_target > 0 && o.probability_target < 1))
    throw InvalidParameter("probability_target", o.probability_target, "must be in (0, 1)");
  if (!(o.time_quantile > 0 && o.time_quantile < 1))
    throw InvalidParameter("time_quantile", o.time_quantile, "must be in (0, 1)");
  if (o.screening_runs < 10 || o.screening_runs > 100'000)
    throw InvalidParameter("screening_runs", o.screening_runs, "must be in [10, 1e5]");
  if (o.verification_runs < 100 || o.verification_runs > 10'000'000)
    throw InvalidParameter("verification_runs", o.verification_runs, "must be in [100, 1e7]");
  if (!(o.slow_factor >= 1 && o.slow_factor <= 1e6))
    throw InvalidParameter("slow_factor", o.slow_factor, "must be in [1, 1e6]");
  if (o.finalists < 1 || o.finalists > 1000)
    throw InvalidParameter("finalists", o.finalists, "must be in [1, 1000]");
  if (!(q.tolerance > 0))
    throw InvalidParameter("tolerance", q.tolerance,
                           "must be > 0 [m] for a robust design (the band the end must reach)");
  const double points = static_cast<double>(q.acceleration_grid) * q.acceleration_grid *
                        q.period_grid * q.stroke_grid;
  if (points > kMaxRobustCandidates)
    throw InvalidParameter(
        "grid",
        std::to_string(q.acceleration_grid) + "^2 x " + std::to_string(q.period_grid) + " x " +
            std::to_string(q.stroke_grid) + " = " + format_number(points) + " candidates",
        "acceleration_grid^2 x period_grid x stroke_grid must be <= 1e7 for a robust design");
}

// A grid point through the prune: its closed-form bound (fraction of the bound draws).
struct Pruned {
  std::size_t index;
  double bound;
};

// The prune over the whole grid, streamed in chunks: the points whose bound's Wilson upper
// limit reaches the target, and the kBestBoundPool best bounds of the others (positive only).
struct PruneResult {
  std::vector<Pruned> passing, best_others;
  std::size_t candidates = 0, non_physical = 0, too_fast = 0;  // the grid's points
};

PruneResult prune(const DesignRequest& q, const DesignGrid& grid,
                  const std::vector<InputValues>& draws, const RobustOptions& o) {
  // Per draw: the acceleration factor a/p^2, mu_static g and mu_static c_mu g.
  std::vector<std::array<double, 3>> d;
  for (const InputValues& v : draws) {
    const double slip = v[2] * v[0] * q.gravity;
    d.push_back({v[5] / (v[6] * v[6]), slip, slip * v[1]});
  }
  const Scales sc(q.width, q.mu, q.gravity);
  const auto by_bound = [](const Pruned& a, const Pruned& b) {
    return a.bound > b.bound || (a.bound == b.bound && a.index < b.index);
  };
  std::vector<PruneResult> chunks((grid.size() + kChunk - 1) / kChunk);
  SweepOptions sweep;
  sweep.threads = o.threads;
  detail::parallel_cells(chunks.size(), sweep, [&](std::size_t k) {
    PruneResult& r = chunks[k];
    for (std::size_t i = k * kChunk; i < std::min(grid.size(), (k + 1) * kChunk); ++i) {
      DesignGrid::Skip why{};
      const std::optional<ThreePhaseParameters> p = grid.at(i, &why);
      r.non_physical += why == DesignGrid::Skip::non_physical;
      r.too_fast += why == DesignGrid::Skip::too_fast;
      if (!p) continue;
      ++r.candidates;
      const double a2 = sc.acceleration_to_si(p->a2);
      const double peak = std::max(a2, sc.acceleration_to_si(p->a3));
      int possible = 0;
      for (const auto& [acc, slip, stop] : d) possible += a2 * acc > slip && peak * acc <= stop;
      const double bound = static_cast<double>(possible) / static_cast<double>(d.size());
      if (wilson_interval(possible, static_cast<int>(d.size())).second >= o.probability_target)
        r.passing.push_back({i, bound});
      else if (possible > 0)
        r.best_others.push_back({i, bound});
    }
    std::sort(r.best_others.begin(), r.best_others.end(), by_bound);
    if (r.best_others.size() > kBestBoundPool) r.best_others.resize(kBestBoundPool);
  });
  PruneResult all;
  for (PruneResult& c : chunks) {
    all.candidates += c.candidates, all.non_physical += c.non_physical, all.too_fast += c.too_fast;
    all.passing.insert(all.passing.end(), c.passing.begin(), c.passing.end());
    all.best_others.insert(all.best_others.end(), c.best_others.begin(), c.best_others.end());
    std::sort(all.best_others.begin(), all.best_others.end(), by_bound);
    if (all.best_others.size() > kBestBoundPool) all.best_others.resize(kBestBoundPool);
  }
  return all;
}

// The screen's candidates among `points`: one run each at the nominal inputs with x_mu such
// that the nominal x_stick,min (eq. 41) lands on the target; those that stop, by nominal T_p.
std::vector<detail::ScreenCandidate> nominal_runs(const DesignRequest& q, const DesignGrid& grid,
                                                  const std::vector<Pruned>& points,
                                                  const InputValues& nominal,
                                                  const RobustOptions& o) {
  const Scales sc(q.width, q.mu, q.gravity);
  std::vector<std::optional<detail::ScreenCandidate>> runs(points.size());
  SweepOptions sweep;
  sweep.threads = o.threads;
  detail::parallel_cells(points.size(), sweep, [&](std::size_t k) {
    const ThreePhaseParameters p = *grid.at(points[k].index);
    detail::ScreenCandidate c;
    c.grid_index = points[k].index;
    c.bound = points[k].bound;
    c.process = {sc.time_to_si(p.period), sc.length_to_si(p.stroke), sc.acceleration_to_si(p.a2),
                 sc.acceleration_to_si(p.a3), q.jerk_max, 0};
    const double peak = std::max(p.a2, p.a3);
    const double rise = std::max(0.0, peak / nominal[2] - 1) / (q.c_mu - 1);
    c.process.x_mu = std::max(q.distance - q.width * rise, 1e-3 * q.distance);
    const ProcessOutcome out = run_process(q, c.process, nominal, o.max_periods);
    if (out.kind == StopKind::not_stopped) return;
    const double period = c.process.period * nominal[6];
    c.nominal_time = out.process_time;
    c.nominal_step = c.process.x_mu * period / out.entry_time;
    c.budget = static_cast<int>(
        std::min<double>(o.max_periods, std::ceil(o.slow_factor * out.process_time / period) + 8));
    runs[k] = c;
  }, [](std::size_t, const std::string&) {});  // a point the runs cannot resolve: no candidate
  std::vector<detail::ScreenCandidate> out;
  for (const auto& c : runs)
    if (c) out.push_back(*c);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.nominal_time < b.nominal_time;
  });
  return out;
}

// A finalist's selection Monte Carlo and the order the selection puts them in.
struct Selected {
  const detail::Screened* screened;
  std::size_t grid_index;
  MonteCarloResult runs;
  double time;
  bool passes;
};

// Better by the selection's order: passing before not; then, passing, the lower T_p quantile,
// else the higher P(within); the same search's ties broken by the grid and x_mu, so that a
// superset of finalists never selects a worse one.
bool better(const Selected& a, const Selected& b) {
  if (a.passes != b.passes) return a.passes;
  const double pa = a.runs.p_within, pb = b.runs.p_within;
  if (a.passes) {
    if (a.time != b.time) return a.time < b.time;
    if (pa != pb) return pa > pb;
  } else {
    if (pa != pb) return pa > pb;
    if (a.time != b.time) return a.time < b.time;
  }
  if (a.grid_index != b.grid_index) return a.grid_index < b.grid_index;
  return a.screened->x_mu < b.screened->x_mu;
}

std::string interval_text(const MonteCarloResult& m) {
  return format_number(m.p_within) + " [" + format_number(m.p_within_low) + ", " +
         format_number(m.p_within_high) + "]";
}

}  // namespace

FailureCounts failure_counts(const MonteCarloResult& r) {
  FailureCounts f;
  for (std::size_t i = 0; i < r.kind.size(); ++i)
    f.add(r.kind[i], r.entry_time[i], r.end_position[i], r.target, r.tolerance);
  return f;
}

double tolerance_at_probability(const MonteCarloResult& r, double probability) {
  std::vector<double> errors;
  for (double end : r.end_position)
    if (!std::isnan(end)) errors.push_back(std::abs(end - r.target));
  return empirical_quantile(std::move(errors), probability, r.end_position.size());
}

RobustDesignResult design_robust(const DesignRequest& q, const ProcessUncertainty& u,
                                 const RobustOptions& o) {
  validate(q);
  validate(u);
  validate(o, q);

  RobustDesignResult r;
  const DesignGrid grid(q);
  const Scales sc(q.width, q.mu, q.gravity);
  const InputValues nominal = nominal_inputs(q, u);
  const int n_draws = std::max(o.screening_runs, kBoundDraws);
  std::vector<InputValues> draws(static_cast<std::size_t>(n_draws));
  for (std::size_t j = 0; j < draws.size(); ++j) draws[j] = draw_inputs(q, u, o.seed, j);

  // 1. The prune and the nominal runs.
  const PruneResult pruned =
      prune(q, grid, {draws.begin(), draws.begin() + kBoundDraws}, o);
  std::vector<detail::ScreenCandidate> candidates =
      nominal_runs(q, grid, pruned.passing, nominal, o);
  if (candidates.empty()) {  // none can reach the target: find the best achievable
    candidates = nominal_runs(q, grid, pruned.best_others, nominal, o);
    std::vector<std::size_t> order(candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return candidates[a].bound > candidates[b].bound;
    });
    order.resize(std::min(order.size(), kBestAchievableCandidates));
    std::sort(order.begin(), order.end());  // back to the nominal T_p's order
    std::vector<detail::ScreenCandidate> kept;
    for (std::size_t i : order) kept.push_back(candidates[i]);
    candidates = std::move(kept);
  }
  r.candidates = static_cast<int>(pruned.candidates);
  if (pruned.candidates == 0) {
    r.message = grid.empty_message(pruned.non_physical, pruned.too_fast);
    r.binding = "actuator limits";
    return r;
  }

  // 2. The screen.
  draws.resize(static_cast<std::size_t>(o.screening_runs));
  const detail::ScreenResult screened = detail::screen(q, candidates, draws, o);
  r.rungs = screened.rungs;
  r.screened = static_cast<int>(screened.last_seen.size());
  if (screened.finalists.empty()) {
    r.message = "no candidate stops within the tolerance in any screening run";
    r.binding = "end-position spread";
    return r;
  }

  // 3. Selection, on draws of its own.
  MonteCarloOptions mo;
  mo.runs = o.verification_runs;
  mo.max_periods = o.max_periods;
  mo.threads = o.threads;
  mo.seed = o.seed ^ kSelectionStream;
  std::optional<Selected> chosen;
  for (const detail::Screened& f : screened.finalists) {
    const detail::ScreenCandidate& c = candidates[f.candidate];
    Process p = c.process;
    p.x_mu = f.x_mu;
    Selected s{&f, c.grid_index, monte_carlo(q, p, u, mo), 0, false};
    s.time = process_time_quantile(s.runs, o.time_quantile);
    s.passes = s.runs.p_within_low >= o.probability_target;
    ++r.verified;
    if (!chosen || better(s, *chosen)) chosen = std::move(s);
  }

  // 4. Verification of the chosen design, on draws independent of all the above.
  const detail::Screened& f = *chosen->screened;
  r.process = candidates[f.candidate].process;
  r.process.x_mu = f.x_mu;
  mo.seed = o.seed ^ kVerificationStream;
  r.verification = monte_carlo(q, r.process, u, mo);
  r.selection = std::move(chosen->runs);
  r.time_quantile_value = process_time_quantile(r.verification, o.time_quantile);
  r.achievable_tolerance = tolerance_at_probability(r.verification, o.probability_target);
  r.failures = failure_counts(r.verification);
  const ThreePhaseParameters p = *grid.at(chosen->grid_index);
  r.design = describe_design(q, p, sc.length_from_si(f.x_mu), 0);
  r.design.candidates = r.candidates;
  r.design.feasible_candidates = 0;
  for (const detail::Screened& s : screened.last_seen)
    r.design.feasible_candidates += s.p_within >= o.probability_target;
  r.limits = r.design.limits;
  r.meets_target = chosen->passes && r.verification.p_within >= o.probability_target;

  const std::string tol = "+-" + format_number(q.tolerance) + " m";
  const std::string target = "P(within " + tol + ") >= " + format_number(o.probability_target);
  const std::string runs = " over " + std::to_string(r.verification.runs) +
                           " independent verification runs (selected on " +
                           std::to_string(r.selection.runs) + " others: " +
                           interval_text(r.selection) + ")";
  std::string limits;
  for (const std::string& l : r.limits) limits += (limits.empty() ? "" : "; ") + l;
  if (r.meets_target) {
    // What keeps the design from being faster: the failures of the faster candidates.
    FailureCounts faster;
    for (const detail::Screened& s : screened.last_seen)
      if (s.time < f.time && s.p_within < o.probability_target) {
        faster.no_motion += s.failures.no_motion;
        faster.no_stop += s.failures.no_stop;
        faster.outside += s.failures.outside;
      }
    r.binding = dominant(faster);
    if (r.binding == "none") r.binding = "actuator limits";
    r.message = "P(within " + tol + ") = " + interval_text(r.verification) + runs +
                "; faster candidates fail on: " +
                (r.binding == "actuator limits" ? std::string("none (the fastest of the grid)")
                                                : explain(r.binding));
  } else {
    r.binding = dominant(r.failures);
    std::string why;
    if (chosen->passes)
      why = "the design selected verifies only " + interval_text(r.verification) + " < " +
            format_number(o.probability_target) + " on independent runs (its P is within the "
            "noise of the target: more --verification-runs may settle it)";
    else if (screened.any_qualifies)
      why = "none of the " + std::to_string(r.verified) + " finalists that passed the screen "
            "verifies " + target + " (more --finalists or --screening-runs may find one)";
    else
      why = "no profile within the limits reaches " + target;
    const std::string reach =
        std::isinf(r.achievable_tolerance)
            ? "more than " + format_number(1 - o.probability_target) +
                  " of its runs never stop, so no tolerance is met with P >= " +
                  format_number(o.probability_target)
            : "this design holds +-" + format_number(r.achievable_tolerance) + " m with P >= " +
                  format_number(o.probability_target);
    r.message = why + "; the best found reaches " + interval_text(r.verification) + runs +
                ": " + explain(r.binding) + "; " + reach;
  }
  if (!limits.empty()) r.message += "; the profile sits on its limits: " + limits;
  return r;
}

}  // namespace selfalign
