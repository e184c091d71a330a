#include "selfalign/robust/row_monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace row_mc {

// The inputs by name, in InputValues order (uncertain_inputs()).
struct Index {
  std::size_t mu = uncertain_input_index("mu"), c_mu = uncertain_input_index("c_mu"),
              ratio = uncertain_input_index("static_ratio"),
              width = uncertain_input_index("width"),
              offset = uncertain_input_index("x_mu_offset"),
              amplitude = uncertain_input_index("amplitude"),
              period = uncertain_input_index("period_factor");
};
const Index& index() {
  static const Index i;
  return i;
}

// What an input without uncertainty takes for part `p`: mu's reference 1 (the factor),
// the process's c_mu, the part's own static ratio, no width (not drawn), no offset, factors 1.
InputValues known_inputs(const RowProcess& n, const RowPart& p) {
  const Index& k = index();
  InputValues v{};
  v[k.mu] = 1;
  v[k.c_mu] = n.c_mu;
  v[k.ratio] = p.law.static_coefficient() / p.law.kinetic_forward();
  v[k.width] = kNaN;
  v[k.offset] = 0;
  v[k.amplitude] = 1;
  v[k.period] = 1;
  return v;
}

void refuse_width(const ProcessUncertainty& u) {
  if (is_uncertain(u.width))
    throw InvalidParameter("width.uncertain", describe(u.width),
                           "must be known for a queue: each part has its own length and the "
                           "exact row solver's footprint is a point (no transition width)");
}

// The process that per-part inputs `in` (part 0's per-run inputs apply to all) describe; `in`
// gets mu as the factor applied and the run's per-run inputs for every part.
RowProcess apply_inputs(const RowProcess& n, const ProcessUncertainty& u,
                        std::vector<InputValues>& in) {
  const Index& k = index();
  RowProcess out = n;
  const InputValues run = in.front();
  const double a = run[k.amplitude], p = run[k.period];
  const ThreePhaseParameters& t = n.table;
  // y(t) -> a y(t / p): strokes x a, accelerations x a / p^2, the period x p.
  out.table = {t.period * p, t.stroke * a, t.a2 * a / (p * p), t.a3 * a / (p * p)};
  out.step_position = n.step_position + run[k.offset];
  out.c_mu = run[k.c_mu];
  const double mu_nominal = nominal(u.mu, 1.0);
  const bool ratio_drawn = is_uncertain(u.static_ratio);
  for (std::size_t i = 0; i < in.size(); ++i) {
    InputValues& v = in[i];
    for (const std::size_t per_run : {k.c_mu, k.offset, k.amplitude, k.period}) v[per_run] = run[per_run];
    const FrictionLaw& law = n.queue.parts[i].law;
    const double f = is_uncertain(u.mu) ? v[k.mu] / mu_nominal : 1.0;
    v[k.mu] = f;
    const double kf = law.kinetic_forward() * f, kb = law.kinetic_backward() * f;
    // The single-part model's law: static = ratio x mu, backward = min(its ratio, static).
    const double s = ratio_drawn ? v[k.ratio] * kf : law.static_coefficient() * f;
    try {
      out.queue.parts[i].law = FrictionLaw(s, kf, ratio_drawn ? std::min(kb, s) : kb);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter("parts[" + std::to_string(i) + "].law (" + e.name() + ")", e.value(),
                             e.allowed());
    }
  }
  return out;
}

// The model a process builds (what a run builds before it runs): throws what it refuses.
void build(const RowProcess& p, const RowSolver& solver) {
  const ThreePhaseParameters& t = p.table;
  require_positive_moderate("table.period", t.period);
  require_positive_moderate("table.stroke", t.stroke);
  require_positive_moderate("table.a2", t.a2);
  require_positive_moderate("table.a3", t.a3);
  if (!solve_three_phase(t).physical)
    throw InvalidParameter("table", "a2 = " + format_number(t.a2) + ", a3 = " + format_number(t.a3),
                           "must be a physical three-phase profile for its period and stroke "
                           "(case 0: the table cannot reach the stroke)");
  require_moderate("c_mu", p.c_mu);
  if (!(p.c_mu > 0)) throw InvalidParameter("c_mu", p.c_mu, "must be > 0");
  const ThreePhaseProfile profile(p.table);
  const FrictionField field = FrictionField::steps({p.step_position}, {1.0, p.c_mu});
  (void)row_model(profile, p.queue, &field,
                  solver.method == Method::exact ? 1 : solver.steps_per_period);
}

// Every uncertain input at either end of its draws (the others known) gives a process the
// model takes; else InvalidParameter naming the input's end (as validate_draws).
void validate_row_draws(const RowProcess& n, const ProcessUncertainty& u, const RowSolver& solver) {
  build(n, solver);
  const auto& inputs = uncertain_inputs();
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const Distribution& d = u.*inputs[k].member;
    if (!is_uncertain(d)) continue;
    const auto [lo, hi] = box(d, 0, kDrawSigmas);
    for (const bool upper : {false, true}) {
      std::vector<InputValues> in;
      for (const RowPart& p : n.queue.parts) {
        in.push_back(known_inputs(n, p));
        in.back()[k] = upper ? hi : lo;
      }
      try {
        build(apply_inputs(n, u, in), solver);
      } catch (const InvalidParameter& e) {
        throw InvalidParameter(std::string(inputs[k].name) + (upper ? ".upper" : ".lower"),
                               upper ? hi : lo,
                               "draws this far give no queue the model takes (" + e.name() +
                                   " = " + e.value() + ": " + e.allowed() + ")");
      }
    }
  }
}

// Mean and sample standard deviation of the non-NaN values (NaN: none; sd NaN below two).
std::pair<double, double> mean_sd(const std::vector<double>& v) {
  double sum = 0;
  std::size_t n = 0;
  for (const double x : v)
    if (!std::isnan(x)) sum += x, ++n;
  if (n == 0) return {kNaN, kNaN};
  const double mean = sum / static_cast<double>(n);
  if (n < 2) return {mean, kNaN};
  double ss = 0;
  for (const double x : v)
    if (!std::isnan(x)) ss += (x - mean) * (x - mean);
  return {mean, std::sqrt(ss / static_cast<double>(n - 1))};
}

// Part `part`'s column of a runs x parts table.
std::vector<double> column(const RowMonteCarloResult& r, const std::vector<double>& table,
                           int part) {
  if (part < 0 || part >= r.parts)
    throw InvalidParameter("part", part, "must be in [0, " + std::to_string(r.parts - 1) + "]");
  std::vector<double> c(static_cast<std::size_t>(r.runs));
  for (std::size_t run = 0; run < c.size(); ++run)
    c[run] = table[run * static_cast<std::size_t>(r.parts) + static_cast<std::size_t>(part)];
  return c;
}

void require_probability(double q) {
  if (!(q > 0 && q <= 1)) throw InvalidParameter("quantile", q, "must be in (0, 1]");
}

// The q-quantile of the non-NaN values of `c`.
double finite_quantile(const std::vector<double>& c, double q) {
  require_probability(q);
  std::vector<double> x;
  for (const double v : c)
    if (!std::isnan(v)) x.push_back(v);
  const std::size_t n = x.size();
  return empirical_quantile(std::move(x), q, n);
}

}  // namespace row_mc

using namespace row_mc;

RowDraw draw_row_process(const RowProcess& n, const ProcessUncertainty& u, std::uint64_t seed,
                         std::uint64_t run) {
  refuse_width(u);
  if (n.queue.parts.empty()) throw InvalidParameter("parts", "none", "needs at least one part");
  RowDraw d;
  for (std::size_t i = 0; i < n.queue.parts.size(); ++i)
    d.inputs.push_back(draw_inputs(known_inputs(n, n.queue.parts[i]), u, seed, run,
                                   kUncertainInputs * i));
  d.process = apply_inputs(n, u, d.inputs);
  return d;
}

RowMonteCarloResult row_monte_carlo(const RowProcess& n, const ProcessUncertainty& u,
                                    const RowMonteCarloOptions& o) {
  if (o.runs < 1 || o.runs > 10'000'000) throw InvalidParameter("runs", o.runs, "must be in [1, 1e7]");
  if (!(o.max_periods >= 1 && o.max_periods <= 100'000'000))
    throw InvalidParameter("max_periods", o.max_periods, "must be in [1, 1e8]");
  if (!(o.tolerance > 0 && o.tolerance <= 1e50))
    throw InvalidParameter("tolerance", o.tolerance,
                           "must be in (0, 1e50] [-]: the band around each part's target");
  if (!std::isfinite(n.step_position))
    throw InvalidParameter("step_position", n.step_position, "must be finite");
  validate(u);
  refuse_width(u);
  validate_row_draws(n, u, o.solver);
  RowMonteCarloResult r;
  r.seed = o.seed;
  r.first_run = o.first_run;
  r.tolerance = o.tolerance;
  r.step_position = n.step_position;
  r.runs = o.runs;
  r.parts = static_cast<int>(n.queue.parts.size());
  const auto runs = static_cast<std::size_t>(o.runs), parts = n.queue.parts.size();
  r.inputs.assign(runs * parts * kUncertainInputs, kNaN);
  r.queue_stopped.assign(runs, 0);
  r.accumulated.assign(runs, 0);
  r.stopped.assign(runs * parts, 0);
  r.end_position.assign(runs * parts, kNaN);
  r.error = r.end_position;
  r.process_time = r.end_position;
  // Each part's target at the nominal step: row_stop's packed targets.
  std::vector<double> ahead(parts, 0.0);  // lengths of the parts ahead of part q
  for (std::size_t q = parts - 1; q-- > 0;) ahead[q] = ahead[q + 1] + n.queue.parts[q + 1].length;
  SweepOptions sweep;
  sweep.threads = o.threads;
  sweep.progress = o.progress;
  detail::parallel_cells(runs, sweep, [&](std::size_t run) {
    const RowDraw d = draw_row_process(n, u, o.seed, o.first_run + run);
    for (std::size_t i = 0; i < parts; ++i)
      std::copy(d.inputs[i].begin(), d.inputs[i].end(),
                r.inputs.begin() + static_cast<std::ptrdiff_t>((run * parts + i) * kUncertainInputs));
    const RowProcess& p = d.process;
    const ThreePhaseProfile profile(p.table);
    const FrictionField field = FrictionField::steps({p.step_position}, {1.0, p.c_mu});
    const RowStop s = row_stop(profile, p.queue, field, o.max_periods, o.solver, 1);
    r.queue_stopped[run] = s.stopped;
    r.accumulated[run] = s.stopped && s.accumulated;
    if (!s.stopped) return;
    for (std::size_t i = 0; i < parts; ++i) {
      const std::size_t at = run * parts + i;
      r.stopped[at] = 1;
      r.end_position[at] = s.x[i];
      r.error[at] = s.x[i] - (n.step_position - ahead[i]);
      r.process_time[at] = s.process_time[i];
    }
  });
  summarize(r);
  return r;
}

void summarize(RowMonteCarloResult& r) {
  r.queue_stops = r.all_within = 0;
  r.summary.assign(static_cast<std::size_t>(r.parts), RowPartSummary{});
  for (std::size_t run = 0; run < static_cast<std::size_t>(r.runs); ++run) {
    r.queue_stops += r.queue_stopped[run] != 0;
    bool all = r.queue_stopped[run] != 0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(r.parts); ++i) {
      const bool within =
          r.queue_stopped[run] != 0 &&
          std::abs(r.error[run * static_cast<std::size_t>(r.parts) + i]) <= r.tolerance;
      r.summary[i].within += within;
      all = all && within;
    }
    r.all_within += all;
  }
  const double runs = r.runs;
  r.p_stop = r.runs ? r.queue_stops / runs : kNaN;
  r.p_all_within = r.runs ? r.all_within / runs : kNaN;
  std::tie(r.p_all_within_low, r.p_all_within_high) = wilson_interval(r.all_within, r.runs);
  for (int i = 0; i < r.parts; ++i) {
    RowPartSummary& s = r.summary[static_cast<std::size_t>(i)];
    s.p_within = r.runs ? s.within / runs : kNaN;
    std::tie(s.p_within_low, s.p_within_high) = wilson_interval(s.within, r.runs);
    std::tie(s.end_mean, s.end_sd) = mean_sd(column(r, r.end_position, i));
    std::tie(s.error_mean, s.error_sd) = mean_sd(column(r, r.error, i));
    std::tie(s.process_time_mean, s.process_time_sd) = mean_sd(column(r, r.process_time, i));
  }
}

double row_end_position_quantile(const RowMonteCarloResult& r, int part, double q) {
  return finite_quantile(column(r, r.end_position, part), q);
}

double row_error_quantile(const RowMonteCarloResult& r, int part, double q) {
  return finite_quantile(column(r, r.error, part), q);
}

double row_process_time_quantile(const RowMonteCarloResult& r, int part, double q) {
  require_probability(q);
  const std::vector<double> c = column(r, r.process_time, part);
  std::vector<double> t;
  for (std::size_t run = 0; run < c.size(); ++run)
    if (r.queue_stopped[run]) t.push_back(std::isnan(c[run]) ? 0.0 : c[run]);
  return empirical_quantile(std::move(t), q, c.size());
}

}  // namespace selfalign
