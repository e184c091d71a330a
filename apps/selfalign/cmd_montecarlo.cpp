// `selfalign montecarlo`: a designed process (a `design` report, or its profile given by flags)
// under uncertain inputs: Monte Carlo (robust/monte_carlo.hpp) and, with --worst-case, the
// worst case over the uncertainty box (robust/worst_case.hpp).

#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "design_report.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "robust_flags.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

// The process flags as given: none where a flag was not given (then the --design report's
// value, or an error naming the flag). A value given is checked, whatever it is: NaN included.
struct ProcessFlags {
  std::optional<double> period, stroke, a2, a3, jerk, x_mu;
};

struct MonteCarloFlags {
  DesignRequest request;
  UncertaintyFlags uncertainty;
  std::optional<std::string> design_file;
  ProcessFlags process;
  MonteCarloOptions options;
  bool worst = false;
  WorstCaseOptions worst_options;
  double time_quantile = 0.99;
  int bins = 20;
  bool as_json = false, quiet = false;
  std::optional<std::string> out, runs_csv;
  std::set<std::string> given;  // request flags given on the command line
};

// The library's names of the process (validate(Process)) as the flags that set them.
constexpr UserName kProcessFlagNames[] = {
    {"period", "period-s"}, {"stroke", "stroke-m"}, {"x_mu", "x-mu"}};

// The process given by flags alone (no --design): every flag but --jerk is required.
Process process_from_flags(const ProcessFlags& f) {
  const auto need = [](const std::optional<double>& v, const char* flag) {
    if (!v)
      throw InvalidParameter(flag, "none",
                             "must be given (or --design FILE, a `selfalign design` report)");
    return *v;
  };
  return {need(f.period, "period-s"), need(f.stroke, "stroke-m"), need(f.a2, "a2"),
          need(f.a3, "a3"), f.jerk.value_or(std::numeric_limits<double>::infinity()),
          need(f.x_mu, "x-mu")};
}

// The process of a `design` report (its profile and x_mu) and the object and friction it was
// designed for (its `request`); flags given explicitly win.
Process read_design(const std::string& path, const ProcessFlags& flags, DesignRequest& request,
                    const std::set<std::string>& given) {
  const DesignReport report = read_design_report(path);
  Process r = report.process;
  r.period = flags.period.value_or(r.period);
  r.stroke = flags.stroke.value_or(r.stroke);
  r.a2 = flags.a2.value_or(r.a2);
  r.a3 = flags.a3.value_or(r.a3);
  r.x_mu = flags.x_mu.value_or(r.x_mu);
  r.jerk = flags.jerk.value_or(r.jerk);
  for (const RequestKey& k : design_request_keys())
    if (!given.count(k.flag))
      std::visit([&](auto field) { request.*field = report.request.*field; }, k.field);
  return r;
}

void run_monte_carlo(const MonteCarloFlags& f) {
  const ExtraFile csv_file{"runs-csv", f.runs_csv};
  require_report_paths(f.out, csv_file);
  if (!(f.time_quantile > 0 && f.time_quantile < 1))
    throw InvalidParameter("time-quantile", f.time_quantile, "must be in (0, 1)");
  if (f.bins < 1 || f.bins > 10'000) throw InvalidParameter("bins", f.bins, "must be in [1, 1e4]");
  DesignRequest q = f.request;
  const Process p = f.design_file ? read_design(*f.design_file, f.process, q, f.given)
                                  : process_from_flags(f.process);
  with_user_names(kProcessFlagNames, [&] { validate(p); });
  warn_about_request(q, f.given.count("--mu") > 0 || f.design_file.has_value());
  const ProcessUncertainty u = f.uncertainty.read();
  // Without an uncertain input every run would be the nominal one: say so rather than run it
  // --runs times (docs/cli.md, montecarlo).
  if (!any_uncertain(u))
    throw InvalidParameter("uncertain", "none",
                           "montecarlo needs an uncertain input (--uncertain NAME=DIST or "
                           "--uncertainty-file); without one every run is the nominal run");
  MonteCarloOptions o = f.options;
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
  const MonteCarloResult r = monte_carlo(q, p, u, o);
  bar.finish();
  json report;
  report["units"] = "si";
  report["process"] = {{"period_s", p.period}, {"stroke_m", p.stroke}, {"a2_m_per_s2", p.a2},
                       {"a3_m_per_s2", p.a3}, {"jerk_m_per_s3", number_or_null(p.jerk)},
                       {"x_mu_m", p.x_mu}};
  report["uncertainty"] = uncertainty_json(q, u);
  report["monte_carlo"] = monte_carlo_json(r, f.time_quantile, f.bins);
  if (f.worst) {
    WorstCaseOptions w = f.worst_options;
    w.threads = o.threads;
    w.max_periods = o.max_periods;
    report["worst_case"] = worst_case_json(worst_case(q, p, u, w));
  }
  TextTable t;
  const json& m = report["monte_carlo"];
  for (const char* key : {"runs", "stopped", "within", "never_entered", "p_stop", "p_within"})
    t.row(key, table_text(m[key]));
  t.row("p_within 95% CI", table_text(m["p_within_95ci"][0]) + " .. " +
                               table_text(m["p_within_95ci"][1]));
  for (const auto& [q_text, v] : m["process_time_quantiles_s"].items())
    t.row("process time q" + q_text + " [s]", table_text(v));
  if (!m["process_time_quantiles_s"].contains(format_number(f.time_quantile)))
    t.row("process time q" + format_number(f.time_quantile) + " [s]",
          table_text(m["process_time_at_quantile_s"]));
  for (const auto& [q_text, v] : m["end_position_quantiles_m"].items())
    t.row("end position q" + q_text + " [m]", table_text(v));
  if (f.worst) {
    const json& w = report["worst_case"];
    t.row("worst case |end - target| [m]", table_text(w["worst_error_m"]));
    t.row("worst case all within", table_text(w["all_within"]));
    t.row("worst case slowest T_p [s]", table_text(w["slowest_process_time_s"]));
    t.row("worst case search", w["method"].get<std::string>() + " (" +
                                   std::to_string(w["evaluations"].get<int>()) + " runs in all)");
  }
  deliver_report_with_file(report, t.str(), f.as_json, f.out, csv_file,
                           f.runs_csv ? monte_carlo_csv(r) : std::string());
}

}  // namespace

void add_montecarlo_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "montecarlo",
      "Evaluate a designed process under uncertain inputs: P(stop), P(|end - distance| <= "
      "tolerance) with its 95% interval, quantiles of T_p and of the end position, a "
      "histogram; --worst-case searches the uncertainty box (corners, Halton points, "
      "Nelder-Mead). Deterministic for a --seed, whatever --threads. The process comes from "
      "--design (a `selfalign design` JSON report) or --period-s/--stroke-m/--a2/--a3/--x-mu.");
  auto f = std::make_shared<MonteCarloFlags>();
  add_request_flags(sub, f->request);
  f->request.tolerance = 1e-4;
  sub->get_option("--tolerance")->description(
      "allowed |end - distance| [m], > 0. Default: 0.0001");
  add_uncertainty_flags(sub, f->uncertainty);
  sub->add_option("--design", f->design_file,
                  "a `selfalign design --json` report to evaluate: its profile, x_mu and the "
                  "request it was designed for (width, mu, c_mu, g, mu-static, mu-backward, "
                  "distance, tolerance, mass); flags given here override them")
      ->type_name("FILE")->group("Process");
  ProcessFlags& p = f->process;
  sub->add_option("--period-s", p.period, "table period [s]")->group("Process");
  sub->add_option("--stroke-m", p.stroke, "table stroke [m]")->group("Process");
  sub->add_option("--a2", p.a2, "y2'' [m/s^2]")->group("Process");
  sub->add_option("--a3", p.a3, "y3'' [m/s^2]")->group("Process");
  sub->add_option("--jerk", p.jerk, "jerk limit [m/s^3] (default: jump accelerations)")
      ->group("Process");
  sub->add_option("--x-mu", p.x_mu, "start of the rough region [m]")->group("Process");
  MonteCarloOptions& o = f->options;
  add_monte_carlo_run_flags(sub, o.runs, o.seed, o.first_run, o.threads);
  sub->add_option("--max-periods", o.max_periods,
                  "table periods after which a run counts as not stopped. Default: 3000")
      ->group("Monte Carlo");
  sub->add_option("--time-quantile", f->time_quantile,
                  "the T_p quantile reported beside 0.5, 0.9, 0.99, in (0, 1). Default: 0.99")
      ->group("Monte Carlo");
  sub->add_option("--bins", f->bins, "histogram bins of the end position, in [1, 1e4]. Default: 20")
      ->group("Monte Carlo");
  sub->add_flag("--worst-case", f->worst, "also search the worst case over the uncertainty box")
      ->group("Worst case");
  sub->add_option("--sigmas", f->worst_options.sigmas,
                  "an untruncated normal spans mean -/+ this many sd in the box, in (0, 8]. "
                  "Default: 3")
      ->group("Worst case");
  sub->add_option("--interior-points", f->worst_options.interior_points,
                  "Halton points inside the box, in [0, 1e5]. Default: 64")
      ->group("Worst case");
  sub->add_flag("--json", f->as_json, "print the report as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE")->type_name("FILE")->group("Output");
  sub->add_option("--runs-csv", f->runs_csv,
                  "write one row per run (its inputs, stop kind, end position, T_p) to FILE")
      ->type_name("FILE")->group("Output");
  sub->callback([f, sub] {
    for (const RequestKey& k : design_request_keys())
      if (sub->count(k.flag) > 0) f->given.insert(k.flag);
    run_monte_carlo(*f);
  });
}

}  // namespace selfalign::cli
