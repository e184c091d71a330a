// `selfalign accuracy`: positioning accuracy (Sect. 7.1, eq. 39). The object enters the
// high-friction region in its steady state from N entries x_0s in [-v̄Δt, 0] (x_mu is placed at
// Δx, the largest displacement in one steady period); each entry's stopping run gives an end
// position, and their spread the positioning error Δx_d and the desired end position x_d.

#include <limits>
#include <memory>
#include <string>

#include "commands.hpp"
#include "selfalign/special_values.hpp"
#include "report.hpp"
#include "selfalign/analysis/positioning.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "stopping_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;


struct AccuracyFlags {
  bool as_json = false;
  int entries = PositioningOptions{}.entries;
  int max_periods = StoppingOptions{}.max_periods;
};

// Header "x0s,end_position,overshoot,stop,periods_p99,periods_p999": one row per entry;
// positions in the run's units (nan where the entry did not stop); periods from entry to
// p = 0.99 / 0.999 of the way to x_stick,min, -1 where not reached.
std::string entries_csv(const PositioningAccuracy& a, const OutputUnits& u) {
  std::string csv = "x0s,end_position,overshoot,stop,periods_p99,periods_p999\n";
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    const StoppingRun& r = a.runs[i];
    const double end = r.kind == StopKind::not_stopped ? kNaN : r.end_position;
    csv += csv_number(u.length(a.entries[i])) + ',' + csv_number(u.length(end)) + ',' +
           csv_number(u.length(end - a.x_mu)) + ',' + to_string(r.kind) + ',' +
           std::to_string(r.periods_to_fraction[0]) + ',' +
           std::to_string(r.periods_to_fraction[1]) + '\n';
  }
  return csv;
}

json accuracy_json(const SimulateModel& model, const PositioningAccuracy& a, int max_periods) {
  const OutputUnits u = model.output_units();
  json j = stopping_context_json(model, false);
  j["reaches"] = a.reaches;
  j["case"] = static_cast<int>(a.steady.motion_case);
  j["case_name"] = describe(a.steady.motion_case);
  j["v_bar"] = number_or_null(u.velocity(a.steady.v_bar));
  j["f"] = number_or_null(a.steady.f);  // [-] always
  j["x_dot_0s"] = number_or_null(u.velocity(a.steady.x_dot_0s));
  j["x_mu"] = length_or_null(u, a.x_mu);
  j["x_stick_min"] = length_or_null(u, a.x_stick_min);
  j["overshoot_min"] = length_or_null(u, a.overshoot_min);
  j["overshoot_max"] = length_or_null(u, a.overshoot_max);
  j["dx_d"] = length_or_null(u, a.dx_d);
  j["x_d"] = length_or_null(u, a.x_d);
  j["accumulates"] = a.accumulates;
  j["entries"] = a.entries.size();
  j["accumulating_entries"] = a.accumulating_entries;
  j["all_stopped"] = a.all_stopped;
  j["max_periods"] = max_periods;
  return j;
}

std::string accuracy_table(const json& j, UnitSystem units) {
  auto with_unit = [&](const char* key, D d) {
    return j[key].is_null() ? std::string("-") : table_text(j[key]) + " " + unit_label(units, d);
  };
  auto yes_no = [&](const char* key) { return std::string(j[key].get<bool>() ? "yes" : "no"); };
  TextTable t;
  t.row("dx_d (eq. 39)", with_unit("dx_d", D::length));
  t.row("x_d", with_unit("x_d", D::length));
  t.row("accumulates", yes_no("accumulates") + " (" + table_text(j["accumulating_entries"]) +
                           " of " + table_text(j["entries"]) + " entries)");
  t.row("all_stopped", yes_no("all_stopped"));
  t.row("overshoot", with_unit("overshoot_min", D::length) + " .. " +
                         with_unit("overshoot_max", D::length));
  t.row("x_mu (= dx)", with_unit("x_mu", D::length));
  t.row("x_stick_min", with_unit("x_stick_min", D::length));
  t.row("case", table_text(j["case"]) + " (" + table_text(j["case_name"]) + ")");
  t.row("v_bar", with_unit("v_bar", D::velocity));
  t.row("f", table_text(j["f"]));
  t.row("reaches", yes_no("reaches"));
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_accuracy(const ConfigFlags& flags, const AccuracyFlags& f) {
  const SimulateConfig config = read_config(flags);
  const ReportPaths paths = resolve_report_paths(config, f.as_json);
  const SimulateModel model = stopping_model(config, "accuracy");
  PositioningOptions options;
  options.entries = f.entries;
  options.stopping.max_periods = f.max_periods;
  options.stopping.fractions = {0.99, 0.999};  // the CSV's periods_p99, periods_p999
  // Stribeck or viscous laws: the steady state, Δx and the stopping runs all integrate.
  options.steady.integrator = options.stopping.integrator = model.options.integrator;
  // The two-region table is placed at x_mu = Δx (the paper's Sect. 7.1); a field stands where
  // its file puts it, and the entries are placed before its rise.
  const TwoRegionTable* two = model.friction->two_region();
  const PositioningAccuracy a =
      two ? positioning_accuracy(*model.profile, model.law, two->width(), two->c_mu(), options)
          : positioning_accuracy(*model.profile, model.law, *model.friction, options);
  const json report = accuracy_json(model, a, f.max_periods);
  deliver_csv_and_report(paths, paths.csv ? entries_csv(a, model.output_units()) : "", report,
                         accuracy_table(report, model.units));
}

}  // namespace

void add_accuracy_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "accuracy",
      "Positioning accuracy (Sect. 7.1): N steady-state entries x_0s in [-v_bar dt, 0] walk into "
      "the two-region table with x_mu = dx (the largest displacement in one steady period); "
      "their end positions give dx_d (eq. 39), x_d and whether every entry accumulates at "
      "x_stick,min (eq. 41). On a friction field (--field-file; level 1 before its rise) the "
      "field stands where the file puts it, x_mu is its rise and the entries lie in "
      "[x_mu - dx - v_bar dt, x_mu - dx]. --out: per-entry CSV. Needs a piecewise-constant "
      "table acceleration.");
  auto flags = add_stopping_config_flags(
      *sub,
      {{"x_mu", ""}, {"x0", ""}, {"v0", ""}, {"t0", ""}, {"output_step", ""},
       {"out", "per-entry CSV x0s,end_position,overshoot,stop,periods_p99,periods_p999 "
               "(default: none)"},
       {"summary", "report JSON file, - for stdout (default: <out without extension>"
                   ".summary.json when out is given, else the report is printed)"}});
  auto f = std::make_shared<AccuracyFlags>();
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table; with --out: "
                                      "instead of writing <stem>.summary.json)")
      ->group("Output");
  sub->add_option("--entries", f->entries,
                  "number N of steady-state entries x_0s, in [1, 1e5]. Default: " +
                      std::to_string(f->entries))
      ->type_name("N")
      ->group("Solver");
  add_max_periods_option(*sub, f->max_periods);
  sub->callback([flags, f] { run_accuracy(*flags, *f); });
}

}  // namespace selfalign::cli
