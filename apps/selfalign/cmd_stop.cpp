// `selfalign stop`: one stopping run (Sect. 7). The object walks from (t0, x0, v0) into the
// friction transition region of the two-region table and stops for good: by permanent stick
// (eq. 40) or by accumulation of its stick positions at x_stick,min (eqs. 59, 60), reached only
// as t -> inf; with the times to reach x_mu + p (x_stick,min - x_mu) for good (Sect. 7.3). With
// --out, the trajectory of the run as a phase portrait (Fig. 16).

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "report.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "stopping_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

struct StopFlags {
  bool as_json = false;
  std::vector<double> fractions = StoppingOptions{}.fractions;
  int max_periods = StoppingOptions{}.max_periods;
};

// Header "t,x,x_dot,stick": time, position, velocity in the run's units; stick 0/1.
std::string phase_portrait_csv(const Trajectory& tr, const OutputUnits& u) {
  std::string csv = "t,x,x_dot,stick\n";
  for (std::size_t i = 0; i < tr.size(); ++i)
    csv += csv_number(u.time(tr.t[i])) + ',' + csv_number(u.length(tr.x[i])) + ',' +
           csv_number(u.velocity(tr.xd[i])) + ',' + (tr.stick[i] ? "1" : "0") + '\n';
  return csv;
}

std::string stop_table(const json& j, UnitSystem units) {
  auto with_unit = [&](const json& v, D d) {
    return v.is_null() ? std::string("-") : table_text(v) + " " + unit_label(units, d);
  };
  TextTable t;
  t.row("stop", table_text(j["stop"]));
  t.row("end_position", with_unit(j["end_position"], D::length));
  t.row("process_time", j["stop"] == "accumulation" ? std::string("inf (accumulation)")
                                                    : with_unit(j["process_time"], D::time));
  t.row("entry_time", with_unit(j["entry_time"], D::time));
  t.row("x_mu", with_unit(j["x_mu"], D::length));
  t.row("x_stick_min", with_unit(j["x_stick_min"], D::length));
  const json& sticks = j["stick_positions"];
  t.row("stick_positions", sticks.empty() ? std::string("none")
                                          : std::to_string(sticks.size()) + ", first " +
                                                with_unit(sticks.front(), D::length) +
                                                ", last " + with_unit(sticks.back(), D::length));
  for (const json& p : j["fractions"])
    t.row("p = " + table_text(p["p"]),
          "x = " + with_unit(p["position"], D::length) + " at t = " +
              with_unit(p["time"], D::time) + ", " + table_text(p["periods_from_entry"]) +
              " periods from entry");
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_stop(const ConfigFlags& flags, const StopFlags& f) {
  const SimulateConfig config = read_config(flags);
  const ReportPaths paths = resolve_report_paths(config, f.as_json);
  const SimulateModel model = stopping_model(config, "stop");
  const FrictionMap& friction = *model.friction;  // two-region, or the config's field
  StoppingOptions options;
  options.max_periods = f.max_periods;
  options.fractions = f.fractions;
  options.integrator = model.options.integrator;  // Stribeck or viscous laws
  const StoppingRun run = stopping_run(*model.profile, friction, model.law, model.initial, options);

  std::string csv;
  if (paths.csv) {  // the same run, sampled by simulate() with the exact solver
    SimulationOptions o = model.options;
    o.duration = stop_trajectory_end(run, model.initial.t, model.profile->period(), f.max_periods) -
                 model.initial.t;
    csv = phase_portrait_csv(simulate(*model.profile, friction, model.law, model.initial, o).trajectory,
                             model.output_units());
  }
  const json report = stop_report_json(model, options, run);
  deliver_csv_and_report(paths, csv, report, stop_table(report, model.units));
}

}  // namespace

void add_stop_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "stop",
      "One stopping run on the two-region table, or on a friction field given by --field-file "
      "(its rise stands for x_mu) (Sect. 7): from (t0, x0, v0) until the object "
      "sticks for good (eq. 40) or its stick positions provably accumulate at x_stick,min "
      "(eqs. 41, 59, 60); times to reach x_mu + p (x_stick,min - x_mu) for good. --out: the "
      "trajectory CSV t,x,x_dot,stick (Fig. 16). Needs a piecewise-constant table "
      "acceleration.");
  auto flags = add_stopping_config_flags(
      *sub,
      {{"out", "trajectory CSV t,x,x_dot,stick (Fig. 16) from t0 to the stop (accumulation: to "
               "the last fraction reached plus one period; not stopped: max-periods periods); "
               "default: none"},
       {"summary", "report JSON file, - for stdout (default: <out without extension>"
                   ".summary.json when out is given, else the report is printed)"}});
  auto f = std::make_shared<StopFlags>();
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table; with --out: "
                                      "instead of writing <stem>.summary.json)")
      ->group("Output");
  sub->add_option("--fractions", f->fractions,
                  "fractions p in [0, 1]: report when x >= x_mu + p (x_stick,min - x_mu) is "
                  "reached for good (the last crossing after slides back). Default: 0.99,0.999")
      ->delimiter(',')
      ->type_name("LIST")
      ->group("Solver");
  add_max_periods_option(*sub, f->max_periods);
  sub->callback([flags, f] { run_stop(*flags, *f); });
}

}  // namespace selfalign::cli

