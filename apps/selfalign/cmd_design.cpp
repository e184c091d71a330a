// `selfalign design`: from SI actuator limits and an object to the three-phase table profile
// that minimises the process time T_p subject to accumulation (Δx_d = 0) or a positioning
// tolerance (design/process_design.hpp), with its fragility to mu and c_mu
// (robust/fragility.hpp); under --robust, the fastest profile that keeps P(within tolerance)
// >= a target under the stated uncertainty (robust/robust_design.hpp). Writes the profile
// sampled for a motion controller.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "robust_flags.hpp"
#include "warnings.hpp"
#include "selfalign/design/process_design.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/design/actuator_samples.hpp"
#include "selfalign/robust/robust_design.hpp"
#include "selfalign/units.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct DesignFlags {
  DesignRequest request;
  UncertaintyFlags uncertainty;
  bool robust = false;
  RobustOptions robust_options;
  double fragility_level = 0.05;
  int monte_carlo_runs = 0;  // nominal design: Monte Carlo under the uncertainty (0: none)
  bool as_json = false, quiet = false;
  std::optional<std::string> out, profile_csv;
  double sample_rate = 10'000;  // [Hz]
  std::optional<double> moving_mass;  // [kg]
  bool mu_given = false;              // --mu on the command line
};

// One period for a motion controller (design/actuator_samples.hpp) as CSV, and its rate in
// `samples`.
std::string profile_csv(const DesignRequest& q, const DesignResult& d, double rate,
                        const std::optional<double>& moving_mass, json& samples) {
  const ActuatorSamples s = actuator_samples(
      q, d, rate, moving_mass ? *moving_mass : std::numeric_limits<double>::quiet_NaN());
  const bool force = !s.force.empty();
  samples = {{"samples_per_period", s.samples_per_period},
             {"sample_rate_hz", s.sample_rate},
             {"requested_sample_rate_hz", s.requested_rate},
             {"rate_adjusted", s.sample_rate != s.requested_rate},
             {"columns", force ? "t_s,y_m,y_dot_m_per_s,y_ddot_m_per_s2,y_dddot_m_per_s3,force_n"
                               : "t_s,y_m,y_dot_m_per_s,y_ddot_m_per_s2,y_dddot_m_per_s3"}};
  if (force) samples["moving_mass_kg"] = s.moving_mass;
  std::string csv = samples["columns"].get<std::string>() + "\n";
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    csv += csv_number(s.t[i]) + ',' + csv_number(s.y[i]) + ',' + csv_number(s.y_dot[i]) + ',' +
           csv_number(s.y_ddot[i]) + ',' + csv_number(s.y_dddot[i]);
    if (force) csv += ',' + csv_number(s.force[i]);
    csv += '\n';
  }
  return csv;
}

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json design_json(const DesignRequest& q, const DesignResult& d) {
  json j;
  j["units"] = "si";
  j["feasible"] = d.feasible;
  j["message"] = d.message;
  j["profile"] = {{"kind", std::isinf(d.jerk) ? "three-phase" : "jerk-limited-three-phase"},
                  {"jerk_m_per_s3", std::isinf(d.jerk) ? json(nullptr) : json(d.jerk)},
                  {"period_s", d.period}, {"frequency_hz", 1 / d.period},
                  {"stroke_m", d.stroke}, {"a2_m_per_s2", d.a2}, {"a3_m_per_s2", d.a3},
                  {"t1_s", d.t1}, {"t2_s", d.t2}, {"t3_s", d.t3}, {"y_ini_m", d.y_ini},
                  {"y_dot_ini_m_per_s", d.y_dot_ini}, {"velocity_peak_m_per_s", d.velocity_peak}};
  j["case"] = static_cast<int>(d.motion_case);
  j["case_name"] = describe(d.motion_case);
  j["v_bar_m_per_s"] = number_or_null(d.v_bar);
  j["x_mu_m"] = d.x_mu;
  j["end_position_m"] = number_or_null(d.end_position);
  j["error_band_m"] = number_or_null(d.error_band);
  j["process_time_s"] = number_or_null(d.process_time);
  j["stop"] = to_string(d.stop);
  j["requirement"] = q.tolerance == 0 ? "accumulation" : "tolerance";
  // The object and friction the design is for (montecarlo --design reads them back).
  j["request"] = {{"mass_kg", q.mass}, {"width_m", q.width}, {"mu", q.mu}, {"c_mu", q.c_mu},
                  {"g_m_per_s2", q.gravity}, {"mu_static", optional_json(q.mu_static)},
                  {"mu_backward", optional_json(q.mu_backward)}, {"distance_m", q.distance},
                  {"tolerance_m", q.tolerance}};
  // The law's coefficients (absolute) and their ratios to mu, as every report gives them.
  j["law"] = law_json(friction_law(q), OutputUnits{}, q.mu);
  j["candidates"] = d.candidates;
  j["feasible_candidates"] = d.feasible_candidates;
  j["limits"] = d.limits;
  return j;
}

std::string design_table(const json& j) {
  TextTable t;
  for (const char* key : {"frequency_hz", "stroke_m", "a2_m_per_s2", "a3_m_per_s2",
                          "velocity_peak_m_per_s"})
    t.row(std::string("profile ") + key, table_text(j["profile"][key]));
  for (const char* key : {"case_name", "v_bar_m_per_s", "x_mu_m", "end_position_m",
                          "error_band_m", "process_time_s", "stop"})
    t.row(key, table_text(j[key]));
  for (const json& l : j["limits"]) t.row("at limit", l.get<std::string>());
  if (j.contains("robust")) {
    const json& r = j["robust"];
    t.row("robust meets_target", table_text(r["meets_target"]));
    t.row("robust p_within", table_text(r["verification"]["p_within"]));
    t.row("robust p_within_95ci", table_text(r["verification"]["p_within_95ci"]));
    t.row("robust selection p_within", table_text(r["selection"]["p_within"]));
    t.row("robust time_quantile_s", table_text(r["time_quantile_value_s"]));
    t.row("robust achievable_tolerance_m", table_text(r["achievable_tolerance_m"]));
    t.row("robust binding", table_text(r["binding"]));
    t.row("robust message", table_text(r["message"]));
  }
  if (j.contains("monte_carlo")) {
    t.row("monte_carlo p_stop", table_text(j["monte_carlo"]["p_stop"]));
    t.row("monte_carlo p_within", table_text(j["monte_carlo"]["p_within"]));
  }
  for (const json& w : j["fragility"]["warnings"]) t.row("WARNING (fragile)", w.get<std::string>());
  return t.str();
}

void run_design(const DesignFlags& f) {
  const ExtraFile csv_file{"profile-csv", f.profile_csv};
  require_report_paths(f.out, csv_file);
  if (!(f.fragility_level > 0 && f.fragility_level < 1))
    throw InvalidParameter("fragility-level", f.fragility_level, "must be in (0, 1)");
  if (f.moving_mass && !(*f.moving_mass > 0 && std::isfinite(*f.moving_mass)))
    throw InvalidParameter("moving-mass", *f.moving_mass, "must be > 0 [kg]");
  if (f.monte_carlo_runs < 0 || f.monte_carlo_runs > 10'000'000)
    throw InvalidParameter("monte-carlo", f.monte_carlo_runs, "must be in [0, 1e7]");
  const ProcessUncertainty uncertainty = f.uncertainty.read();
  const DesignRequest& q = f.request;
  warn_about_request(q, f.mu_given);
  if (f.moving_mass) warn_if_grams("--moving-mass", *f.moving_mass);
  const bool uncertain = any_uncertain(uncertainty);
  json report;
  DesignResult d;
  if (f.robust) {
    if (!uncertain)
      throw InvalidParameter("uncertain", "none",
                             "--robust needs at least one --uncertain input (or --uncertainty-file)");
    validate(q);
    RobustOptions o = f.robust_options;
    ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
    o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
    const RobustDesignResult r = design_robust(q, uncertainty, o);
    bar.finish();
    if (r.verified == 0) throw std::runtime_error("design infeasible: " + r.message);
    d = r.design;
    report = design_json(q, d);
    report["robust"] = {
        {"meets_target", r.meets_target},
        {"message", r.message},
        {"binding", r.binding},
        {"probability_target", o.probability_target},
        {"time_quantile", o.time_quantile},
        {"time_quantile_value_s", number_or_null(r.time_quantile_value)},
        {"failures", {{"no_motion", r.failures.no_motion}, {"no_stop", r.failures.no_stop},
                      {"outside", r.failures.outside}}},
        {"achievable_tolerance_m", number_or_null(r.achievable_tolerance)},
        {"limits", r.limits},
        {"candidates", r.candidates},
        {"screened", r.screened},
        {"rungs", r.rungs},
        {"verified", r.verified},
        {"selection",
         {{"runs", r.selection.runs},
          {"seed", r.selection.seed},
          {"p_within", r.selection.p_within},
          {"p_within_95ci", {r.selection.p_within_low, r.selection.p_within_high}},
          {"process_time_at_quantile_s",
           number_or_null(process_time_quantile(r.selection, o.time_quantile))}}},
        {"verification", monte_carlo_json(r.verification, o.time_quantile, 20)}};
  } else {
    d = design_process(q);
    if (!d.feasible) throw std::runtime_error("design infeasible: " + d.message);
    report = design_json(q, d);
    if (f.monte_carlo_runs > 0) {
      if (!uncertain)
        throw InvalidParameter("monte-carlo", f.monte_carlo_runs,
                               "needs at least one --uncertain input (or --uncertainty-file)");
      MonteCarloOptions mo;
      mo.runs = f.monte_carlo_runs;
      mo.seed = f.robust_options.seed;
      mo.threads = f.robust_options.threads;
      report["monte_carlo"] = monte_carlo_json(monte_carlo(q, process_of(d), uncertainty, mo),
                                               f.robust_options.time_quantile, 20);
    }
  }
  if (uncertain) report["uncertainty"] = uncertainty_json(q, uncertainty);
  report["fragility"] = fragility_json(fragility(q, process_of(d), f.fragility_level));
  report["warnings"] = report["fragility"]["warnings"];
  std::string csv;
  if (f.profile_csv) {
    json samples;
    csv = profile_csv(q, d, f.sample_rate, f.moving_mass, samples);
    report["profile_csv"] = samples;
  }
  deliver_report_with_file(report, design_table(report), f.as_json, f.out, csv_file, csv);
}

}  // namespace

void add_design_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "design",
      "Recommend a three-phase table profile from SI actuator limits: minimise the process "
      "time T_p subject to accumulation (Δx_d = 0) or --tolerance. Reports the profile, v̄, "
      "T_p [s], the end position and its band, the motion case, the limits it sits on, and its "
      "fragility to mu, c_mu and mu_static (warnings when a few per cent error stops it from "
      "stopping or moves the end beyond the tolerance, and whenever it assumed mu_static = "
      "mu). --robust: the fastest profile (a T_p quantile) with P(within --tolerance) >= "
      "--probability-target under the --uncertain inputs, selected and verified by Monte Carlo "
      "on independent draws; when none reaches it, the best found and the tolerance it holds. --profile-csv writes one period for a motion controller. An "
      "infeasible request is an error naming the binding limit.");
  auto f = std::make_shared<DesignFlags>();
  DesignRequest& q = f->request;
  add_request_flags(sub, q);
  sub->add_option("--acceleration-grid", q.acceleration_grid,
                  "candidates per acceleration axis, in [2, 200]; the grid (acceleration-grid^2 x "
                  "period-grid x stroke-grid) at most 1e7 under --robust, and x entries at "
                  "most 1e9 without")->group("Search");
  sub->add_option("--period-grid", q.period_grid, "candidate periods, in [1, 100]")
      ->group("Search");
  sub->add_option("--stroke-grid", q.stroke_grid, "candidate strokes, in [1, 20]")
      ->group("Search");
  sub->add_option("--entries", q.entries,
                  "steady entries per candidate (Sect. 7.1), in [2, 1000]")
      ->group("Search");
  add_uncertainty_flags(sub, f->uncertainty);
  RobustOptions& ro = f->robust_options;
  sub->add_flag("--robust", f->robust,
                "design for the uncertainty: minimise the --time-quantile of T_p subject to "
                "P(|end - distance| <= tolerance) >= --probability-target (needs --tolerance > 0 "
                "and an --uncertain input)")
      ->group("Robust");
  sub->add_option("--probability-target", ro.probability_target,
                  "required P(within tolerance), in (0, 1). Default: 0.99")->group("Robust");
  sub->add_option("--time-quantile", ro.time_quantile,
                  "the quantile of T_p minimised, in (0, 1). Default: 0.99")->group("Robust");
  sub->add_option("--screening-runs", ro.screening_runs,
                  "Monte-Carlo draws per candidate in the screen, in rungs of 25, 50, 100, ... up "
                  "to it, in [10, 1e5]; on that ladder a larger value never selects a worse "
                  "design. Default: 200")
      ->group("Robust");
  sub->add_option("--verification-runs", ro.verification_runs,
                  "Monte-Carlo runs selecting among the finalists (each), and verifying the "
                  "chosen design on independent draws, in [100, 1e7]. Default: 4000")
      ->group("Robust");
  sub->add_option("--finalists", ro.finalists,
                  "finalists per rung of the screen (the fastest and the surest each), in [1, "
                  "1000]. Default: 6")
      ->group("Robust");
  sub->add_option("--seed", ro.seed, "seed of the Monte-Carlo draws. Default: 1")->group("Robust");
  sub->add_option("--threads", ro.threads, "worker threads, >= 0 (0: all cores). Default: 0")
      ->group("Robust");
  sub->add_option("--monte-carlo", f->monte_carlo_runs,
                  "without --robust: also evaluate the nominal design by this many Monte-Carlo "
                  "runs under the --uncertain inputs. Default: 0 (none)")
      ->group("Robust");
  sub->add_option("--fragility-level", f->fragility_level,
                  "relative error of mu, c_mu and mu_static the fragility check applies, in "
                  "(0, 1). "
                  "Default: 0.05")
      ->group("Robust");
  sub->add_flag("--json", f->as_json, "print the report as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE")->type_name("FILE")->group("Output");
  sub->add_option("--profile-csv", f->profile_csv,
                  "write one period of the profile to FILE: t_s,y_m,y_dot_m_per_s,"
                  "y_ddot_m_per_s2,y_dddot_m_per_s3[,force_n]; round(period x rate) samples, no "
                  "repeated endpoint (loops seamlessly); the rate is adjusted to make the period "
                  "a whole number of samples and the report says so")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--sample-rate", f->sample_rate,
                  "profile CSV sample rate [Hz], > 0, at most 1e7 rows a period "
                  "(sample-rate / frequency-min <= 1e7)")
      ->group("Output");
  sub->add_option("--moving-mass", f->moving_mass,
                  "mass the actuator moves [kg], > 0: adds force_n = mass x y'' to the profile "
                  "CSV (inertial force; friction and the part's reaction excluded)")
      ->group("Output");
  sub->callback([f, sub] {
    f->mu_given = sub->count("--mu") > 0;
    // One period has sample_rate / frequency rows; the slowest allowed frequency bounds it.
    constexpr double kMaxRows = 1e7;
    const double f_min = f->request.frequency_min;  // design_process checks it itself
    if (!(f->sample_rate > 0) || (f_min > 0 && !(f->sample_rate <= kMaxRows * f_min)))
      throw InvalidParameter("sample-rate", f->sample_rate,
                             "must be in (0, 1e7 x frequency-min]: one period at most 1e7 rows");
    run_design(*f);
  });
}

}  // namespace selfalign::cli
