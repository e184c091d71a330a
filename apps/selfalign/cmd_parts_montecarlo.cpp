// `selfalign parts montecarlo`: a queue stopping at the friction step (the parts config) under
// the robust-design uncertainty model (robust/row_monte_carlo.hpp, docs/rows.md section 11):
// the uncertainty flags and file of `selfalign montecarlo`, per-part probabilities of ending
// within the tolerance, end-position, error and process-time statistics, a per-run CSV.

#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "parts_config.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "robust_flags.hpp"
#include "selfalign/error.hpp"
#include "selfalign/robust/row_monte_carlo.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct PartsMonteCarloFlags {
  PartsFlags parts;
  UncertaintyFlags uncertainty;
  RowMonteCarloOptions options;
  bool quiet = false;
  std::optional<std::string> runs_csv;
};

// Which inputs a queue draws per part and which once per run (docs/rows.md section 11).
const char* applies(const std::string& name) {
  if (name == "mu") return "per part: a factor mu / nominal(mu) on its coefficients";
  if (name == "static_ratio") return "per part: mu_static = ratio x forward kinetic";
  if (name == "width") return "not drawn (must be known)";
  if (name == "x_mu_offset") return "per run: the step moves by it [-]";
  return "per run";
}

json uncertainty_report(const ProcessUncertainty& u) {
  json j = json::object();
  for (const UncertainInput& in : uncertain_inputs())
    j[in.name] = {{"distribution", describe(u.*in.member)}, {"applies", applies(in.name)}};
  return j;
}

json quantiles(double (*f)(const RowMonteCarloResult&, int, double), const RowMonteCarloResult& r,
               int part, std::initializer_list<double> qs) {
  json j = json::object();
  for (const double q : qs) j[format_number(q)] = number_or_null(f(r, part, q));
  return j;
}

json part_report(const RowMonteCarloResult& r, int i) {
  const RowPartSummary& s = r.summary[static_cast<std::size_t>(i)];
  return {{"part", i},
          {"within", s.within},
          {"p_within", number_or_null(s.p_within)},
          {"p_within_95ci", {number_or_null(s.p_within_low), number_or_null(s.p_within_high)}},
          {"end_position_mean", number_or_null(s.end_mean)},
          {"end_position_sd", number_or_null(s.end_sd)},
          {"end_position_quantiles",
           quantiles(row_end_position_quantile, r, i, {0.005, 0.05, 0.5, 0.95, 0.995})},
          {"error_mean", number_or_null(s.error_mean)},
          {"error_sd", number_or_null(s.error_sd)},
          {"error_quantiles", quantiles(row_error_quantile, r, i, {0.005, 0.05, 0.5, 0.95, 0.995})},
          {"process_time_mean", number_or_null(s.process_time_mean)},
          {"process_time_sd", number_or_null(s.process_time_sd)},
          {"process_time_quantiles", quantiles(row_process_time_quantile, r, i, {0.5, 0.9, 0.99})}};
}

// One row per run and part: the inputs it ran with, whether the queue stopped, the results.
std::string runs_csv(const RowMonteCarloResult& r) {
  std::string csv = "run,part";
  const auto& inputs = uncertain_inputs();
  for (const UncertainInput& in : inputs)
    if (std::string(in.name) != "width")
      csv += "," + std::string(in.name) + (std::string(in.name) == "mu" ? "_factor" : "");
  csv += ",queue_stopped,accumulated,end_position,error,process_time\n";
  const auto parts = static_cast<std::size_t>(r.parts);
  for (std::size_t run = 0; run < static_cast<std::size_t>(r.runs); ++run)
    for (std::size_t i = 0; i < parts; ++i) {
      const std::size_t at = run * parts + i;
      csv += std::to_string(r.first_run + run) + "," + std::to_string(i);
      for (std::size_t k = 0; k < inputs.size(); ++k)
        if (std::string(inputs[k].name) != "width")
          csv += "," + csv_number(r.inputs[at * kUncertainInputs + k]);
      csv += "," + std::to_string(r.queue_stopped[run]) + "," + std::to_string(r.accumulated[run]) +
             "," + csv_number(r.end_position[at]) + "," + csv_number(r.error[at]) + "," +
             csv_number(r.process_time[at]) + "\n";
    }
  return csv;
}

void run_parts_montecarlo(const PartsMonteCarloFlags& f) {
  const ExtraFile csv_file{"runs-csv", f.runs_csv};
  require_report_paths(f.parts.out, csv_file);
  const PartsSetup s = read_parts_config(f.parts);
  if (!s.step_position)
    throw InvalidParameter("friction.step_position", "missing",
                           "a stopping queue needs the friction step (in " + f.parts.config + ")");
  const ProcessUncertainty u = f.uncertainty.read();
  if (!any_uncertain(u))
    throw InvalidParameter("uncertain", "none",
                           "parts montecarlo needs an uncertain input (--uncertain NAME=DIST or "
                           "--uncertainty-file); without one every run is the nominal run");
  RowProcess p;
  p.table = s.table;
  p.step_position = *s.step_position;
  p.c_mu = s.c_mu;
  p.queue = s.queue;
  RowMonteCarloOptions o = f.options;
  o.max_periods = s.max_periods;
  o.solver = s.solver;
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
  const RowMonteCarloResult r = row_monte_carlo(p, u, o);
  bar.finish();
  json j;
  j["units"] = "dimensionless";
  j["method"] = to_string(s.solver.method);
  j["steps_per_period"] =
      s.solver.method == Method::exact ? json(nullptr) : json(s.solver.steps_per_period);
  j["max_periods"] = s.max_periods;
  j["step_position"] = r.step_position;
  j["parts"] = r.parts;
  j["uncertainty"] = uncertainty_report(u);
  j["runs"] = r.runs;
  j["seed"] = r.seed;
  j["first_run"] = r.first_run;
  j["tolerance"] = r.tolerance;
  j["queue_stopped"] = r.queue_stops;
  j["p_stop"] = number_or_null(r.p_stop);
  int accumulated = 0;
  for (const auto a : r.accumulated) accumulated += a;
  j["accumulated"] = accumulated;
  j["all_within"] = r.all_within;
  j["p_all_within"] = number_or_null(r.p_all_within);
  j["p_all_within_95ci"] = {number_or_null(r.p_all_within_low), number_or_null(r.p_all_within_high)};
  j["per_part"] = json::array();
  for (int i = 0; i < r.parts; ++i) j["per_part"].push_back(part_report(r, i));
  TextTable t;
  for (const char* key : {"runs", "parts", "queue_stopped", "p_stop", "accumulated", "all_within",
                          "p_all_within"})
    t.row(key, table_text(j[key]));
  t.row("p_all_within 95% CI",
        table_text(j["p_all_within_95ci"][0]) + " .. " + table_text(j["p_all_within_95ci"][1]));
  for (const json& part : j["per_part"]) {
    const std::string name = "part " + std::to_string(part["part"].get<int>());
    t.row(name + " p_within (95% CI)", table_text(part["p_within"]) + " (" +
                                           table_text(part["p_within_95ci"][0]) + " .. " +
                                           table_text(part["p_within_95ci"][1]) + ")");
    t.row(name + " end position mean, sd [-]",
          table_text(part["end_position_mean"]) + ", " + table_text(part["end_position_sd"]));
    t.row(name + " error mean, sd [-]",
          table_text(part["error_mean"]) + ", " + table_text(part["error_sd"]));
    t.row(name + " process time q0.99 [-]", table_text(part["process_time_quantiles"]["0.99"]));
  }
  deliver_report_with_file(j, t.str(), f.parts.as_json, f.parts.out, csv_file,
                           f.runs_csv ? runs_csv(r) : std::string());
}

}  // namespace

void add_parts_montecarlo_command(CLI::App& parts) {
  auto f = std::make_shared<PartsMonteCarloFlags>();
  CLI::App* sub = parts.add_subcommand(
      "montecarlo",
      "Monte Carlo of the queue stopping at the friction step under uncertain inputs (the "
      "uncertainty model of `selfalign montecarlo`: mu and static_ratio drawn per part, c_mu, "
      "x_mu_offset, amplitude and period_factor per run; width must be known): P(stop), each "
      "part's P(|error| <= tolerance) with its 95% interval, end-position, error and "
      "process-time statistics. Deterministic for a --seed, whatever --threads");
  PartsFlags& p = f->parts;
  sub->add_option("--config", p.config,
                  "the queue: [table], [friction] (step_position, c_mu), [run] and one "
                  "[[parts]] table per part or group of parts (docs/rows.md)")
      ->required()
      ->type_name("FILE");
  sub->add_option("--method", p.method, "exact (default) or time-stepping (Moreau)");
  sub->add_option("--steps-per-period", p.steps_per_period, "Moreau's steps per period (2000)");
  sub->add_option("--restitution", p.restitution, "Newton's e between parts, in [0, 1] (0)");
  sub->add_option("--max-periods", p.max_periods,
                  "periods after which a run counts as not stopped (the config's, 1000)");
  add_uncertainty_flags(sub, f->uncertainty);
  RowMonteCarloOptions& o = f->options;
  sub->add_option("--tolerance", o.tolerance,
                  "allowed |positioning error| of each part [-], > 0. Default: 0.01")
      ->group("Monte Carlo");
  add_monte_carlo_run_flags(sub, o.runs, o.seed, o.first_run, o.threads);
  sub->add_flag("--json", p.as_json, "print the report as JSON (default: a table)")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", p.out, "write the JSON report to FILE (nothing printed)")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--runs-csv", f->runs_csv,
                  "write one row per run and part (its inputs, whether the queue stopped, end "
                  "position, error, process time) to FILE")
      ->type_name("FILE")
      ->group("Output");
  sub->callback([f] { run_parts_montecarlo(*f); });
}

}  // namespace selfalign::cli
