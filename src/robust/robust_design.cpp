#include "selfalign/robust/robust_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/error.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The verification draws from a stream of its own, not the screen's.
constexpr std::uint64_t kVerificationStream = 0x5eed0f0e11f1ca7eULL;
// Candidates screened per parallel batch (the screen's order is fixed, so is the result).
constexpr std::size_t kScreenBatch = 64;
// When no candidate can reach the target, the best closed-form bounds screened for the best
// achievable probability.
constexpr std::size_t kBestAchievableCandidates = 256;

struct Screened {
  ThreePhaseParameters p{};  // model units
  Process process;           // SI, x_mu placed
  double bound = 0;          // closed-form upper bound of P(within)
  double p_within = -1;      // screened, after placing x_mu; -1: not screened
  double time = kInf;        // screened T_p quantile [s]
  double nominal_time = kInf;  // T_p of the nominal inputs at the provisional x_mu [s]
  FailureCounts failures;
};

// The window of width 2 tol over the sorted values z holding the most of them: its count and
// centre (the midpoint of the extreme values inside; the first such window on ties).
std::pair<int, double> best_window(std::vector<double> z, double tol) {
  std::sort(z.begin(), z.end());
  int best = 0;
  double centre = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t lo = 0, hi = 0; lo < z.size(); ++lo) {
    hi = std::max(hi, lo);
    while (hi + 1 < z.size() && z[hi + 1] - z[lo] <= 2 * tol) ++hi;
    if (static_cast<int>(hi - lo + 1) > best) {
      best = static_cast<int>(hi - lo + 1);
      centre = 0.5 * (z[lo] + z[hi]);
    }
  }
  return {best, centre};
}

const char* dominant(const FailureCounts& f) {
  if (f.outside + f.no_stop + f.no_motion == 0) return "none";
  if (f.outside >= f.no_stop && f.outside >= f.no_motion) return "end-position spread";
  return f.no_stop >= f.no_motion ? "stopping" : "motion";
}

std::string explain(const char* binding) {
  const std::string b = binding;
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

}  // namespace

FailureCounts failure_counts(const MonteCarloResult& r) {
  FailureCounts f;
  for (std::size_t i = 0; i < r.kind.size(); ++i)
    f.add(r.kind[i], r.entry_time[i], r.end_position[i], r.target, r.tolerance);
  return f;
}

RobustDesignResult design_robust(const DesignRequest& q, const ProcessUncertainty& u,
                                 const RobustOptions& o) {
  validate(q);
  validate(u);
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

  RobustDesignResult r;
  const DesignCandidates grid = design_candidates(q);
  r.candidates = static_cast<int>(grid.profiles.size());
  if (grid.profiles.empty()) {
    r.message = grid.message;
    r.binding = "actuator limits";
    return r;
  }
  const Scales sc(q.width, q.mu, q.gravity);
  const InputValues nominal = nominal_inputs(q, u);
  const double ratio = nominal[2];
  std::vector<InputValues> draws(static_cast<std::size_t>(o.screening_runs));
  for (std::size_t j = 0; j < draws.size(); ++j) draws[j] = draw_inputs(q, u, o.seed, j);

  // 1. The closed-form bound of every candidate.
  std::vector<Screened> cands;
  for (const ThreePhaseParameters& p : grid.profiles) {
    Screened c;
    c.p = p;
    c.process = {sc.time_to_si(p.period), sc.length_to_si(p.stroke),
                 sc.acceleration_to_si(p.a2), sc.acceleration_to_si(p.a3), q.jerk_max, 0};
    const double peak = std::max(c.process.a2, c.process.a3);
    int possible = 0;
    for (const InputValues& v : draws) {
      const double acc = v[5] / (v[6] * v[6]);  // amplitude / period_factor^2
      const double slip = v[2] * v[0] * q.gravity;
      possible += c.process.a2 * acc > slip && peak * acc <= slip * v[1];
    }
    c.bound = static_cast<double>(possible) / static_cast<double>(draws.size());
    // Provisional x_mu: the nominal x_stick,min (eq. 41) lands on the target.
    const double rise = std::max(0.0, peak / (ratio * sc.acceleration()) - 1) / (q.c_mu - 1);
    c.process.x_mu = std::max(q.distance - q.width * rise, 1e-3 * q.distance);
    cands.push_back(c);
  }
  // 2a. One run per candidate at the nominal inputs: its T_p orders the screen and bounds
  // the periods a screening run may take (slow_factor).
  SweepOptions sweep;
  sweep.threads = o.threads;
  detail::parallel_cells(cands.size(), sweep, [&](std::size_t i) {
    Screened& c = cands[i];
    if (c.bound <= 0) return;
    const ProcessOutcome out = run_process(q, c.process, nominal, o.max_periods);
    if (out.kind != StopKind::not_stopped) c.nominal_time = out.process_time;
  });
  std::vector<std::size_t> to_screen;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cands[i].bound >= o.probability_target && std::isfinite(cands[i].nominal_time))
      to_screen.push_back(i);
  const bool reachable = !to_screen.empty();
  if (!reachable) {  // none can reach the target: find the best achievable
    for (std::size_t i = 0; i < cands.size(); ++i)
      if (std::isfinite(cands[i].nominal_time)) to_screen.push_back(i);
    std::stable_sort(to_screen.begin(), to_screen.end(), [&](std::size_t a, std::size_t b) {
      return cands[a].bound > cands[b].bound;
    });
    to_screen.resize(std::min<std::size_t>(to_screen.size(), kBestAchievableCandidates));
  }
  std::stable_sort(to_screen.begin(), to_screen.end(), [&](std::size_t a, std::size_t b) {
    return cands[a].nominal_time < cands[b].nominal_time;
  });

  // 2b. The Monte-Carlo screen on the common draws, placing x_mu; in batches in the order of
  // the nominal T_p, so that once a candidate qualifies with screened quantile T*, candidates
  // whose nominal T_p already exceeds T* are not screened (their quantile cannot be lower).
  const auto screen = [&](Screened& c) {
    const double x_mu0 = c.process.x_mu;
    const double period = c.process.period;
    const int budget = static_cast<int>(std::min<double>(
        o.max_periods, std::ceil(o.slow_factor * c.nominal_time / period) + 8));
    std::vector<ProcessOutcome> outs(draws.size());
    std::vector<double> z;
    for (std::size_t j = 0; j < draws.size(); ++j) {
      outs[j] = run_process(q, c.process, draws[j], budget);
      if (outs[j].kind != StopKind::not_stopped) z.push_back(outs[j].end_position - x_mu0);
    }
    const auto [count, centre] = best_window(z, q.tolerance);
    if (count == 0 || !(q.distance - centre > 0)) {
      c.p_within = 0;
      return;
    }
    c.process.x_mu = q.distance - centre;
    c.p_within = static_cast<double>(count) / static_cast<double>(draws.size());
    // T_p moves with x_mu at each run's own walking speed (x_mu0 + offset) / entry time.
    std::vector<double> t(draws.size(), kInf);
    for (std::size_t j = 0; j < draws.size(); ++j) {
      const ProcessOutcome& out = outs[j];
      const double end = out.end_position - x_mu0 + c.process.x_mu;
      c.failures.add(out.kind, out.entry_time, end, q.distance, q.tolerance);
      if (out.kind == StopKind::not_stopped) continue;
      const double speed = (x_mu0 + draws[j][4]) / out.entry_time;
      t[j] = out.process_time + (c.process.x_mu - x_mu0) / speed;
    }
    const std::size_t n = t.size();
    c.time = empirical_quantile(std::move(t), o.time_quantile, n);
  };
  double best_time = kInf;
  std::size_t screened = 0, done = 0;
  for (std::size_t begin = 0; begin < to_screen.size(); begin += kScreenBatch) {
    std::vector<std::size_t> batch;
    for (std::size_t k = begin; k < std::min(to_screen.size(), begin + kScreenBatch); ++k)
      if (cands[to_screen[k]].nominal_time <= best_time) batch.push_back(to_screen[k]);
    if (batch.empty()) break;
    detail::parallel_cells(
        batch.size(), sweep, [&](std::size_t k) { screen(cands[batch[k]]); },
        [&](std::size_t k, const std::string&) { cands[batch[k]].p_within = 0; });
    screened += batch.size();
    for (std::size_t i : batch)
      if (cands[i].p_within >= o.probability_target) best_time = std::min(best_time, cands[i].time);
    done = std::min(to_screen.size(), begin + kScreenBatch);
    if (o.progress) o.progress(done, to_screen.size());
  }
  to_screen.resize(done);
  r.screened = static_cast<int>(screened);

  // 3. Verify the best finalists with fresh draws.
  const bool any_qualifies = std::any_of(to_screen.begin(), to_screen.end(), [&](std::size_t i) {
    return cands[i].p_within >= o.probability_target;
  });
  std::vector<std::size_t> finalists;
  for (std::size_t i : to_screen)
    if (cands[i].p_within > 0 && (!any_qualifies || cands[i].p_within >= o.probability_target))
      finalists.push_back(i);
  std::stable_sort(finalists.begin(), finalists.end(), [&](std::size_t a, std::size_t b) {
    if (any_qualifies) return cands[a].time < cands[b].time;
    if (cands[a].p_within != cands[b].p_within) return cands[a].p_within > cands[b].p_within;
    return cands[a].time < cands[b].time;
  });
  finalists.resize(std::min<std::size_t>(finalists.size(), static_cast<std::size_t>(o.finalists)));
  if (finalists.empty()) {
    r.message = "no candidate stops within the tolerance in any screening run";
    r.binding = "end-position spread";
    return r;
  }
  MonteCarloOptions mo;
  mo.seed = o.seed ^ kVerificationStream;
  mo.runs = o.verification_runs;
  mo.max_periods = o.max_periods;
  mo.threads = o.threads;
  std::size_t chosen = finalists.front();
  double chosen_time = kInf;
  bool meets = false;
  for (std::size_t i : finalists) {
    MonteCarloResult v = monte_carlo(q, cands[i].process, u, mo);
    ++r.verified;
    const double t = process_time_quantile(v, o.time_quantile);
    const bool passes = v.p_within_low >= o.probability_target;
    const bool better =
        r.verified == 1 ||
        (passes && (!meets || t < chosen_time)) ||
        (!passes && !meets &&
         (v.p_within > r.verification.p_within ||
          (v.p_within == r.verification.p_within && t < chosen_time)));
    if (better) {
      chosen = i, chosen_time = t, meets = meets || passes;
      r.verification = std::move(v);
    }
  }
  const Screened& c = cands[chosen];
  r.meets_target = meets;
  r.process = c.process;
  r.time_quantile_value = chosen_time;
  r.failures = failure_counts(r.verification);
  r.design = describe_design(q, c.p, sc.length_from_si(c.process.x_mu), 0);
  r.design.candidates = r.candidates;
  r.design.feasible_candidates = 0;
  for (std::size_t i : to_screen) r.design.feasible_candidates += cands[i].p_within >= o.probability_target;
  const std::string p_text = format_number(r.verification.p_within) + " [" +
                             format_number(r.verification.p_within_low) + ", " +
                             format_number(r.verification.p_within_high) + "]";
  if (meets) {
    // What keeps the design from being faster: the failures of the faster candidates.
    FailureCounts faster;
    for (std::size_t i : to_screen)
      if (cands[i].time < c.time && cands[i].p_within < o.probability_target) {
        faster.no_motion += cands[i].failures.no_motion;
        faster.no_stop += cands[i].failures.no_stop;
        faster.outside += cands[i].failures.outside;
      }
    r.binding = dominant(faster);
    if (r.binding == "none") r.binding = "actuator limits";
    r.message = "P(within +-" + format_number(q.tolerance) + " m) = " + p_text +
                " over " + std::to_string(r.verification.runs) +
                " verification runs; faster candidates fail on: " +
                (r.binding == "actuator limits" ? std::string("none (the fastest of the grid)")
                                                : explain(r.binding.c_str()));
  } else {
    r.binding = dominant(r.failures);
    const std::string target = "P(within +-" + format_number(q.tolerance) + " m) >= " +
                               format_number(o.probability_target);
    r.message = (any_qualifies
                     ? "none of the " + std::to_string(r.verified) +
                           " finalists that passed the screen verifies " + target +
                           " (more --finalists or --screening-runs may find one)"
                     : "no profile within the limits reaches " + target) +
                "; the best found reaches " + p_text + " over " +
                std::to_string(r.verification.runs) + " runs: " + explain(r.binding.c_str());
  }
  return r;
}

}  // namespace selfalign
