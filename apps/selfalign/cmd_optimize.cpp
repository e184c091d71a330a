// `selfalign optimize`: constrained profile optimisation (Sect. 4.4.2, taken further). Finds
// the profile of a family (three-phase, K-segment piecewise-constant, Fourier of order N) that
// minimises f of eq. (11) within the actuator limits (exact period and stroke, |y'| and |y''|
// bounded over the whole period), or compares all three families. Dimensionless inputs.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "warnings.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/optimize.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"
#include "selfalign/error.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct OptimizeFlags {
  std::string family = "fourier";
  ActuatorLimits limits;
  OptimizeOptions options;
  bool as_json = false, quiet = false;
  std::optional<std::string> out;
  // The law's coefficients, absolute as everywhere (docs/config.md "Friction law").
  double mu = 0.3;
  std::optional<double> mu_static, mu_backward;
  bool mu_given = false;  // --mu on the command line
};

json result_json(const OptimizationResult& r) {
  return {{"family", r.family},
          {"feasible", r.feasible},
          {"f", number_or_null(r.feasible ? r.f : std::nan(""))},
          {"v_bar", number_or_null(r.feasible ? r.v_bar : std::nan(""))},
          {"parameters", r.parameters},
          {"max_velocity", r.max_velocity},
          {"max_acceleration", r.max_acceleration},
          {"max_jerk", number_or_null(r.max_jerk)},
          {"evaluations", r.evaluations},
          {"starts", r.starts},
          {"message", r.message}};
}

// The library's names of the limits and options, as the flags that set them.
constexpr UserName kFlagNames[] = {{"max_velocity", "velocity-max"},
                                   {"max_acceleration", "acceleration-max"},
                                   {"max_jerk", "jerk-max"},
                                   {"max_evaluations", "max-evaluations"},
                                   {"mu_static", "mu-static"},
                                   {"mu_backward", "mu-backward"}};

void run_optimize(OptimizeFlags& f) {
  with_user_names(kFlagNames, [&] {
    validate(f.limits);
    f.options.law = law_of_coefficients(f.mu, f.mu_static, f.mu_backward);
    validate(f.options);
  });
  warn_default_mu(f.mu_given, f.mu, f.mu_static, f.mu_backward);
  if (f.out) require_output_path("out", *f.out);
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  f.options.progress = [&bar](int done, int total) {
    bar.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
  };
  std::vector<OptimizationResult> results;
  if (f.family == "all") results = compare_families(f.limits, f.options);
  else if (f.family == "three-phase") results = {optimize_three_phase(f.limits, f.options)};
  else if (f.family == "piecewise-constant")
    results = {optimize_piecewise_constant(f.limits, f.options)};
  else if (f.family == "fourier") results = {optimize_fourier(f.limits, f.options)};
  else
    throw InvalidParameter("family", f.family,
                           "must be one of: three-phase, piecewise-constant, fourier, all");
  bar.finish();
  json report = {{"limits",
                  {{"period", f.limits.period},
                   {"stroke", f.limits.stroke},
                   {"max_velocity", f.limits.max_velocity},
                   {"max_acceleration", f.limits.max_acceleration},
                   {"max_jerk", number_or_null(f.limits.max_jerk)}}},
                 {"law", law_json(f.options.law, OutputUnits{}, f.mu)},
                 {"results", json::array()}};
  TextTable table;
  for (const OptimizationResult& r : results) {
    report["results"].push_back(result_json(r));
    table.row(r.family, r.feasible ? "f = " + table_text(r.f) + ", v_bar = " + table_text(r.v_bar)
                                   : "infeasible: " + r.message);
  }
  deliver_report(report, table.str(), f.as_json, f.out);
}

}  // namespace

void add_optimize_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "optimize",
      "Optimise the table profile within actuator limits (Sect. 4.4.2): minimise f of eq. (11) "
      "over a family (three-phase, piecewise-constant with K segments, Fourier of order N), or "
      "compare all three. Dimensionless inputs; defaults: the paper's Fig. 6 setting.");
  auto f = std::make_shared<OptimizeFlags>();
  sub->add_option("--family", f->family, "three-phase, piecewise-constant, fourier or all");
  sub->add_option("--period", f->limits.period, "period Δt [-], > 0. Default: 0.072");
  sub->add_option("--stroke", f->limits.stroke, "stroke Δy [-], exact, > 0. Default: 0.021");
  sub->add_option("--velocity-max", f->limits.max_velocity, "|y'| limit [-]. Default: 3.2");
  sub->add_option("--acceleration-max", f->limits.max_acceleration,
                  "|y''| limit [-]. Default: 1275");
  sub->add_option("--jerk-max", f->limits.max_jerk,
                  "jerk limit |d3y/dt3| [-], > 0: the three-phase family uses ramps at this jerk, the "
                  "piecewise-constant one (jumps) is infeasible, a Fourier optimum is checked. "
                  "Default: none");
  sub->add_option("--mu", f->mu,
                  "kinetic friction coefficient mu_1 [-], > 0: the unit of the law's "
                  "coefficients (the optimisation itself is dimensionless). Default: 0.3");
  sub->add_option("--mu-static", f->mu_static,
                  "static friction coefficient [-] (absolute, like --mu), >= mu and "
                  ">= mu-backward; the law's static ratio is mu-static/mu. Default: mu");
  sub->add_option("--mu-backward", f->mu_backward,
                  "kinetic coefficient of backward slip [-] (absolute), > 0. Default: mu");
  sub->add_option("--order", f->options.order, "Fourier order N, in [1, 100]. Default: 12");
  sub->add_option("--segments", f->options.segments, "K of piecewise-constant, in [2, 64]. Default: 4");
  sub->add_option("--starts", f->options.starts, "multi-starts, in [1, 1000]. Default: 8");
  sub->add_option("--max-evaluations", f->options.max_evaluations,
                  "objective evaluations per local run, in [1, 1e6]");
  sub->add_option("--seed", f->options.seed, "seed of the deterministic random starts");
  sub->add_option("--threads", f->options.threads,
                  "worker threads of the Fourier optimiser's gradient stencils, >= 0 (0: all "
                  "cores; the result does not depend on it). Default: 0");
  sub->add_flag("--json", f->as_json, "print the report as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE")
      ->type_name("FILE")
      ->group("Output");
  sub->callback([f, sub] {
    f->mu_given = sub->count("--mu") > 0;
    run_optimize(*f);
  });
}

}  // namespace selfalign::cli
