// `selfalign planar simulate | steady | field | stop`: planar motion of a rigid part on a
// contact patch (planar/planar_rigid.hpp, planar/planar_analysis.hpp) from a TOML/JSON config
// (io/planar_config.hpp), in SI units. Each writes a JSON report (--out, or the table / --json
// on stdout) and, with --csv, its rows (trajectory, drift field, stopping runs).

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "sweep_common.hpp"  // cell_status, failures_json
#include "warnings.hpp"
#include "selfalign/planar/planar_run.hpp"
#include "selfalign/planar/planar_steady_state.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/planar_config.hpp"
#include "selfalign/io/planar_report.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxTimeSteps, kMaxRecordedSamples

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct PlanarFlags {
  std::string config;
  std::vector<std::string> set;  // "section.key=value" over the config's values
  std::optional<std::string> out, csv;
  bool as_json = false, quiet = false;
};

using Si = PlanarUnits;

// A key the config gives that nothing read has no effect: say so (after the output).
void warn_unused_keys(const PlanarSetup& s) {
  for (const std::string& key : s.unused_keys)
    warn("planar: " + key + " is not used by this config (its kinds do not read it): it has no "
         "effect");
}

PlanarSetup load(const PlanarFlags& f, std::vector<ConfigSection::Read>* reads = nullptr) {
  require_report_paths(f.out, ExtraFile{"csv", f.csv});
  PlanarSetup s = load_planar_config(f.config, f.set, reads);
  warn_unused_keys(s);
  return s;
}

// The recorded run as CSV rows, in the run's units; the world pose of the part is the table's
// pose composed with the part's pose on it.
std::string trajectory_csv(const PlanarTrajectory& r, const Si& si) {
  std::ostringstream out;
  out << "t" << si.u("_s", "") << ",x" << si.u("_m", "") << ",y" << si.u("_m", "")
      << ",angle_rad,ux" << si.u("_m_per_s", "") << ",uy" << si.u("_m_per_s", "")
      << ",omega" << si.u("_rad_per_s", "") << ",mode,world_x" << si.u("_m", "")
      << ",world_y" << si.u("_m", "") << ",world_angle_rad\n";
  for (std::size_t i = 0; i < r.size(); ++i) {
    PlanarTablePose table;
    table.x = r.table_x[i], table.y = r.table_y[i], table.angle = r.table_angle[i];
    const PlanarPose w = world_pose(table, {r.x[i], r.y[i], r.angle[i]});
    out << csv_number(si.time(r.t[i])) << ',' << csv_number(si.length(r.x[i])) << ','
        << csv_number(si.length(r.y[i])) << ',' << csv_number(r.angle[i]) << ','
        << csv_number(si.velocity(r.ux[i])) << ',' << csv_number(si.velocity(r.uy[i])) << ','
        << csv_number(si.rate(r.omega[i])) << ',' << patch_mode_name(r.mode[i]) << ','
        << csv_number(si.length(w.x)) << ',' << csv_number(si.length(w.y)) << ','
        << csv_number(w.angle) << '\n';
  }
  return out.str();
}

void run_simulate(const PlanarFlags& f) {
  const PlanarSetup s = load(f);
  const Si si{s};
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  const PlanarTrajectory run = planar_simulate_run(s, [&bar](long long done, long long total) {
    bar.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
  });
  bar.finish();
  const json r = planar_simulate_report_json(s, run);
  TextTable t;
  t.row("end pose x, y [" + si.u("m", "-") + "], angle [rad]",
        table_text(r["end_pose"]["x"]) + ", " + table_text(r["end_pose"]["y"]) + ", " + table_text(r["end_pose"]["angle_rad"]));
  t.row("steps stick / pivot / slip", std::to_string(run.census.stick) + " / " + std::to_string(run.census.pivot) + " / " + std::to_string(run.census.slip));
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv},
                           f.csv ? trajectory_csv(run, si) : std::string());
}

void run_steady(const PlanarFlags& f) {
  const PlanarSetup s = load(f);
  const Si si{s};
  if (s.window_given)
    warn("planar steady: [run] window is not used: the steady state is the fixed point of the "
         "period map (searched for at most [run] steady_periods periods after [run] transient)");
  PlanarSteadyStateOptions options;
  options.transient_periods = s.transient;
  options.max_periods = s.steady_periods;
  options.tolerance = s.tolerance;
  const PlanarSteadyState res = planar_steady_state(s.problem, s.pose, s.twist, options);
  json r = planar_report_header(s);
  r["command"] = "planar steady";
  r["method"] = res.method == Method::exact ? "exact point solver" : "time-stepping";
  r["transient_periods"] = s.transient;
  r["converged"] = res.converged;
  r["periods"] = res.periods;
  // Absent values are null: no drift where the search did not converge.
  r["drift_x"] = si.velocity(res.drift_x);
  r["drift_y"] = si.velocity(res.drift_y);
  r["rotation_rate"] = si.rate(res.rotation_rate);
  r["twist_0s"] = {{"ux", si.velocity(res.twist_0s.ux)}, {"uy", si.velocity(res.twist_0s.uy)},
                   {"omega", si.rate(res.twist_0s.omega)}};
  r["residual"] = res.residual;   // [-]: |z_n - z_(n-1)|, twist and displacement per time
  r["error"] = res.error;         // [-]: its estimate of |z - z*|
  r["census"] = res.method == Method::exact ? json(nullptr) : planar_census_json(res.census);
  r["end_pose"] = planar_pose_json(res.end_pose, si);
  r["level_under_part"] = {{"min", res.level_min}, {"max", res.level_max}};
  r["level_changed"] = res.level_changed;
  if (res.level_changed)
    warn("planar steady: the friction level under the part changed from " +
         format_number(res.level_min) + " to " + format_number(res.level_max) +
         " during the run (it entered another region of the field): " +
         (res.converged ? "the steady state reported is the one where it ended, not where it "
                          "started"
                        : "no steady drift was found") +
         "; start elsewhere ([run] pose) or shorten [run] transient");
  if (!res.converged && !res.level_changed)
    warn("planar steady: no fixed point within " + std::to_string(res.periods) +
         " periods (residual " + format_number(res.residual) +
         "); raise [run] steady_periods or [run] tolerance");
  TextTable t;
  t.row("drift velocity x, y [" + si.u("m/s", "-") + "]", table_text(r["drift_x"]) + ", " + table_text(r["drift_y"]));
  t.row("rotation rate [" + si.u("rad/s", "-") + "]", table_text(r["rotation_rate"]));
  t.row("converged (periods)", table_text(r["converged"]) + " (" + std::to_string(res.periods) + ")");
  t.row("error estimate [-]", table_text(r["error"]));
  t.row("method", r["method"].get<std::string>());
  t.row("level changed", table_text(r["level_changed"]));
  std::string csv;
  if (f.csv) csv = "drift_x,drift_y,rotation_rate\n" + csv_number(r["drift_x"]) + "," + csv_number(r["drift_y"]) + "," + csv_number(r["rotation_rate"]) + "\n";
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv}, csv);
}

void run_field(const PlanarFlags& f) {
  const PlanarSetup s = load(f);
  const Si si{s};
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  const auto samples = planar_drift_field(s.problem, s.grid_x, s.grid_y, s.grid_angles, s.field_periods,
                                          [&bar](std::size_t d, std::size_t n) { bar.update(d, n); });
  bar.finish();
  std::ostringstream csv;
  csv << "x" << si.u("_m", "") << ",y" << si.u("_m", "") << ",angle_rad,drift_x" << si.u("_m_per_s", "")
      << ",drift_y" << si.u("_m_per_s", "") << ",rotation_rate" << si.u("_rad_per_s", "")
      << ",stick,pivot,slip,status\n";
  double largest = 0;
  for (const auto& d : samples) {
    csv << csv_number(si.length(d.x)) << ',' << csv_number(si.length(d.y)) << ',' << csv_number(d.angle) << ','
        << csv_number(si.velocity(d.drift_x)) << ',' << csv_number(si.velocity(d.drift_y)) << ','
        << csv_number(si.rate(d.rotation_rate)) << ',' << d.census.stick << ',' << d.census.pivot << ','
        << d.census.slip << ',' << cell_status(d.failure) << '\n';
    if (d.failure.empty()) largest = std::max(largest, std::hypot(d.drift_x, d.drift_y));
  }
  json r = planar_report_header(s);
  r["command"] = "planar field";
  r["samples"] = samples.size();
  r["periods_per_sample"] = s.field_periods;
  r["largest_drift"] = si.velocity(largest);
  r["failures"] = failures_json(samples, [&si](const PlanarDriftSample& d) {
    return json{{"x", si.length(d.x)}, {"y", si.length(d.y)}, {"angle", d.angle}};
  });
  TextTable t;
  t.row("samples", std::to_string(samples.size()) + " (" +
                       table_text(r["failures"]["count"]) + " failed)");
  t.row("largest drift [" + si.u("m/s", "-") + "]", table_text(r["largest_drift"]));
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv}, csv.str());
}

// The parameter view (planar_model_parameters): each number the model depends on, as the
// config gives it (after --set), with unit, section and meaning.
void run_parameters(const PlanarFlags& f) {
  std::vector<ConfigSection::Read> reads;
  const PlanarSetup s = load(f, &reads);
  const std::vector<ModelParameter> view = planar_model_parameters(reads, s.si);
  json r = {{"config", s.path}, {"units", s.si ? "si" : "dimensionless"}};
  r["parameters"] = json::array();
  TextTable t;
  std::ostringstream csv;
  csv << "name,value,unit,group\n";
  for (const ModelParameter& p : view) {
    r["parameters"].push_back({{"name", p.name},
                               {"value", number_or_null(p.value)},
                               {"unit", p.unit},
                               {"group", p.group},
                               {"meaning", p.meaning}});
    t.row(p.name, table_text(number_or_null(p.value)) + " " + p.unit);
    csv << p.name << ',' << csv_number(p.value) << ',' << p.unit << ',' << p.group << '\n';
  }
  t.row("units", s.si ? "si" : "dimensionless");
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv}, csv.str());
}

void run_stop(const PlanarFlags& f) {
  const PlanarSetup s = load(f);
  const Si si{s};
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  const PlanarStopSummary sum = planar_stop(s.problem, s.entries, s.max_periods,
                                            [&bar](std::size_t d, std::size_t n) { bar.update(d, n); });
  bar.finish();
  std::ostringstream csv;
  csv << "entry_x" << si.u("_m", "") << ",entry_y" << si.u("_m", "") << ",entry_angle_rad,stopped,end_x"
      << si.u("_m", "") << ",end_y" << si.u("_m", "") << ",end_angle_rad,process_time" << si.u("_s", "")
      << ",status\n";
  for (const auto& run : sum.runs)
    csv << csv_number(si.length(run.entry.x)) << ',' << csv_number(si.length(run.entry.y)) << ','
        << csv_number(run.entry.angle) << ',' << (run.stopped ? "true" : "false") << ','
        << csv_number(si.length(run.end.x)) << ',' << csv_number(si.length(run.end.y)) << ','
        << csv_number(run.end.angle) << ',' << csv_number(si.time(run.process_time)) << ','
        << cell_status(run.failure) << '\n';
  json r = planar_report_header(s);
  r["command"] = "planar stop";
  r["runs"] = sum.runs.size();
  r["stopped"] = sum.stopped;
  r["failures"] = failures_json(sum.runs, [&si](const PlanarStopRun& run) {
    return json{{"entry", planar_pose_json(run.entry, si)}};
  });
  r["max_periods"] = s.max_periods;
  r["mean_end"] = planar_pose_json({sum.mean_x, sum.mean_y, sum.mean_angle}, si);
  r["end_region"] = {{"min_x", number_or_null(si.length(sum.min_x))}, {"max_x", number_or_null(si.length(sum.max_x))},
                     {"min_y", number_or_null(si.length(sum.min_y))}, {"max_y", number_or_null(si.length(sum.max_y))},
                     {"radius", number_or_null(si.length(sum.radius))}};
  r["orientation_error_rad"] = number_or_null(sum.angle_range);
  r["max_process_time"] = number_or_null(si.time(sum.max_process_time));
  r["never_stops"] = sum.never_stops;
  TextTable t;
  t.row("stopped", std::to_string(sum.stopped) + " of " + std::to_string(sum.runs.size()) + " (" +
                       std::to_string(sum.failed) + " failed)");
  if (sum.never_stops)
    t.row("never stops", "proven: the table's velocity change in some step of every period "
                         "exceeds the most friction can give (h s max m); nothing simulated");
  t.row("mean end x, y [" + si.u("m", "-") + "]", table_text(r["mean_end"]["x"]) + ", " + table_text(r["mean_end"]["y"]));
  t.row("end region radius [" + si.u("m", "-") + "]", table_text(r["end_region"]["radius"]));
  t.row("orientation error [rad]", table_text(r["orientation_error_rad"]));
  t.row("largest T_p [" + si.u("s", "-") + "]", table_text(r["max_process_time"]));
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv}, csv.str());
}

void add_planar_sub(CLI::App* parent, const char* name, const char* help, void (*run)(const PlanarFlags&),
                    const char* csv_help) {
  CLI::App* sub = parent->add_subcommand(name, help);
  auto f = std::make_shared<PlanarFlags>();
  sub->add_option("--config", f->config, "the planar configuration (.toml or .json; docs/planar.md)")
      ->required()->type_name("FILE");
  sub->add_option("--set", f->set,
                  "set a config key over the file's value, as the file's table and key: "
                  "--set run.step=4e-5 --set table.x.a2=5 --set run.pose=0.01,0,0, or one element "
                  "of an array the file gives: --set field.levels[2]=1.5 (repeatable; the value is "
                  "checked as in the file; docs/planar.md lists the keys)")
      ->type_name("SECTION.KEY=VALUE");
  sub->add_option("--csv", f->csv, csv_help)->type_name("FILE")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE")
      ->type_name("FILE")
      ->group("Output");
  sub->add_flag("--json", f->as_json, "print the report as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar (drawn only when stderr is a terminal)")
      ->group("Output");
  sub->callback([f, run] { run(*f); });
}

}  // namespace

void add_planar_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "planar",
      "Planar motion of a rigid part on a contact patch (translation and rotation) on a table "
      "moving in the plane, by Moreau time-stepping with exact set-valued friction (docs/planar.md)");
  sub->require_subcommand(1);
  add_planar_sub(sub, "simulate", "one run from [run] pose/twist for [run] periods ([run] method: time-stepping, exact for a point part, or integrator: the patch integrator, docs/planar-integrator.md)",
                 &run_simulate, "write the trajectory (every [run] every steps) to FILE");
  add_planar_sub(sub, "steady",
                 "steady drift velocity and rotation rate: the fixed point of the period map "
                 "(exact for a point part on a uniform field), with the stick/pivot/slip census",
                 &run_steady, "write the drift as one CSV row to FILE");
  add_planar_sub(sub, "field",
                 "the drift field over [field_map] x, y, angles: from rest, the mean drift over "
                 "[field_map] periods",
                 &run_field, "write one row per grid point to FILE");
  add_planar_sub(sub, "stop",
                 "stopping in the rough region from each [stop] entry pose: end pose, process "
                 "time, the 2-D end region and the orientation error",
                 &run_stop, "write one row per entry to FILE");
  add_planar_sub(sub, "parameters",
                 "the model's named parameters (its parameter view): every number the planar "
                 "model of this config depends on (scales, table motion, part, friction, field, "
                 "initial pose and twist) with its value as the config gives it and its unit; "
                 "--set SECTION.KEY=VALUE or SECTION.KEY[i]=VALUE changes them first",
                 &run_parameters, "write one row per parameter (name,value,unit,group) to FILE");
}

}  // namespace selfalign::cli
