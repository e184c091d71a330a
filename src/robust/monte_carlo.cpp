#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {


void require_probability(const std::string& name, double q) {
  if (!(q > 0 && q <= 1)) throw InvalidParameter(name, q, "must be in (0, 1]");
}

}  // namespace

double empirical_quantile(std::vector<double> v, double q, std::size_t n) {
  if (n == 0 || v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const auto need = static_cast<std::size_t>(std::ceil(q * static_cast<double>(n) - 1e-9));
  const std::size_t k = std::max<std::size_t>(need, 1) - 1;
  return k < v.size() ? v[k] : kInf;
}

std::pair<double, double> wilson_interval(int k, int n) {
  if (n <= 0) return {std::numeric_limits<double>::quiet_NaN(),
                      std::numeric_limits<double>::quiet_NaN()};
  constexpr double z = 1.959963984540054;  // two-sided 95%
  const double nn = n, p = k / nn, z2 = z * z / nn;
  const double centre = (p + z2 / 2) / (1 + z2);
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / (1 + z2);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

void summarize(MonteCarloResult& r) {
  r.runs = static_cast<int>(r.kind.size());
  r.stopped = r.within = r.never_entered = 0;
  for (std::size_t i = 0; i < r.kind.size(); ++i) {
    r.never_entered += std::isnan(r.entry_time[i]);
    if (r.kind[i] == StopKind::not_stopped) continue;
    ++r.stopped;
    r.within += std::abs(r.end_position[i] - r.target) <= r.tolerance;
  }
  r.p_stop = r.runs ? static_cast<double>(r.stopped) / r.runs : 0;
  r.p_within = r.runs ? static_cast<double>(r.within) / r.runs : 0;
  std::tie(r.p_within_low, r.p_within_high) = wilson_interval(r.within, r.runs);
}

MonteCarloResult monte_carlo(const DesignRequest& q, const Process& p,
                             const ProcessUncertainty& u, const MonteCarloOptions& o) {
  validate(q);
  validate(p);
  validate(u);
  validate_draws(q, p, u);
  if (o.runs < 1 || o.runs > 10'000'000)
    throw InvalidParameter("runs", o.runs, "must be in [1, 1e7]");
  if (o.max_periods < 1 || o.max_periods > 10'000'000)
    throw InvalidParameter("max_periods", o.max_periods, "must be in [1, 1e7]");
  if (!(q.tolerance > 0))
    throw InvalidParameter("tolerance", q.tolerance,
                           "must be > 0 [m]: the band around the target a run must end in");
  MonteCarloResult r;
  r.seed = o.seed;
  r.first_run = o.first_run;
  r.target = q.distance;
  r.tolerance = q.tolerance;
  const auto n = static_cast<std::size_t>(o.runs);
  r.inputs.assign(kUncertainInputs, std::vector<double>(n));
  r.kind.assign(n, StopKind::not_stopped);
  r.end_position.assign(n, std::numeric_limits<double>::quiet_NaN());
  r.process_time = r.end_position;
  r.entry_time = r.end_position;
  const ProcessFamily family(q, p);
  SweepOptions sweep;
  sweep.threads = o.threads;
  sweep.progress = o.progress;
  detail::parallel_cells(
      n, sweep,
      [&](std::size_t i) {
        const InputValues v = draw_inputs(q, u, o.seed, o.first_run + i);
        for (std::size_t k = 0; k < kUncertainInputs; ++k) r.inputs[k][i] = v[k];
        const ProcessOutcome out = run_process(family, v, o.max_periods);
        r.kind[i] = out.kind;
        r.end_position[i] = out.end_position;
        r.process_time[i] = out.process_time;
        r.entry_time[i] = out.entry_time;
      });
  summarize(r);
  return r;
}

MonteCarloResult merge_monte_carlo(const std::vector<MonteCarloResult>& parts) {
  if (parts.empty()) throw InvalidParameter("parts", "[]", "must hold at least one result");
  MonteCarloResult r = parts.front();
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const MonteCarloResult& p = parts[k];
    if (p.seed != r.seed || p.target != r.target || p.tolerance != r.tolerance ||
        p.first_run != r.first_run + r.kind.size())
      throw InvalidParameter("parts", std::to_string(k),
                             "must continue one study: same seed, target and tolerance, "
                             "first_run = the previous part's first_run + runs");
    for (std::size_t i = 0; i < kUncertainInputs; ++i)
      r.inputs[i].insert(r.inputs[i].end(), p.inputs[i].begin(), p.inputs[i].end());
    r.kind.insert(r.kind.end(), p.kind.begin(), p.kind.end());
    r.end_position.insert(r.end_position.end(), p.end_position.begin(), p.end_position.end());
    r.process_time.insert(r.process_time.end(), p.process_time.begin(), p.process_time.end());
    r.entry_time.insert(r.entry_time.end(), p.entry_time.begin(), p.entry_time.end());
  }
  summarize(r);
  return r;
}

double process_time_quantile(const MonteCarloResult& r, double q) {
  require_probability("quantile", q);
  std::vector<double> t;
  for (double v : r.process_time)
    if (!std::isnan(v)) t.push_back(v);
  return empirical_quantile(std::move(t), q, r.process_time.size());
}

double end_position_quantile(const MonteCarloResult& r, double q) {
  require_probability("quantile", q);
  std::vector<double> x;
  for (double v : r.end_position)
    if (!std::isnan(v)) x.push_back(v);
  const std::size_t n = x.size();
  return empirical_quantile(std::move(x), q, n);
}

Histogram histogram(const std::vector<double>& values, int bins) {
  if (bins < 1 || bins > 100'000) throw InvalidParameter("bins", bins, "must be in [1, 1e5]");
  Histogram h;
  double lo = kInf, hi = -kInf;
  for (double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) return h;
  if (lo == hi) hi = lo + std::max(1e-300, std::abs(lo) * 1e-12);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (int k = 0; k <= bins; ++k) h.edges.push_back(lo + (hi - lo) * k / bins);
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    const auto k = std::min<long>(bins - 1, static_cast<long>((v - lo) / (hi - lo) * bins));
    ++h.counts[static_cast<std::size_t>(k)];
  }
  return h;
}

}  // namespace selfalign
