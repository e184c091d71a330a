// `selfalign steady`: the steady state of the object on the uniform table (Sects. 4.3, 5.1):
// motion case (a priori for three-phase profiles, and from the simulated steady period), v̄
// (eq. 10), f (eq. 11) and the steady initial velocity x'_0s. A non-physical (case 0)
// three-phase request is a result here, not an error.

#include <optional>
#include <string>

#include "commands.hpp"
#include "config_flags.hpp"
#include "report.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/profile_analyses.hpp"
#include "selfalign/io/steady_report.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

std::string steady_table(const json& j, UnitSystem units) {
  auto with_unit = [&](const char* key, D d) {
    return j[key].is_null() ? std::string("-") : table_text(j[key]) + " " + unit_label(units, d);
  };
  TextTable t;
  t.row("case", table_text(j["case"]) + " (" + table_text(j["case_name"]) + "), a priori " +
                    table_text(j["case_a_priori"]));
  t.row("v_bar", with_unit("v_bar", D::velocity));
  t.row("f", j["f"].is_null() && !j["v_bar"].is_null() ? "inf (v_bar = 0)" : table_text(j["f"]));
  t.row("x_dot_0s", with_unit("x_dot_0s", D::velocity) + " (error <= " +
                        with_unit("x_dot_0s_error", D::velocity) + ")");
  t.row("phase", with_unit("phase", D::time));
  t.row("displacement", with_unit("displacement", D::length));
  if (!j["converged"].is_null())
    t.row("converged", std::string(j["converged"].get<bool>() ? "yes" : "NO") + ", " +
                           table_text(j["periods"]) + " periods, " + table_text(j["method"]) +
                           " solver");
  if (!j["integrator"].is_null())
    t.row("integrator", "rtol " + table_text(j["integrator"]["relative_tolerance"]) + ", " +
                            table_text(j["integrator"]["steps"]) + " steps (" +
                            table_text(j["integrator"]["rejected"]) + " rejected), " +
                            table_text(j["integrator"]["events"]) + " events");
  t.row("profile", table_text(j["profile"]) + ", period " + with_unit("period", D::time) +
                       ", stroke " + with_unit("stroke", D::length));
  if (!j["a2"].is_null())
    t.row("a2, a3", with_unit("a2", D::acceleration) + ", " + with_unit("a3", D::acceleration));
  if (!j["t1"].is_null()) {
    t.row("t1, t2, t3", table_text(j["t1"]) + ", " + table_text(j["t2"]) + ", " +
                            with_unit("t3", D::time));
    t.row("y_ini, y_dot_ini",
          with_unit("y_ini", D::length) + ", " + with_unit("y_dot_ini", D::velocity));
  }
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_steady(const ConfigFlags& flags, bool as_json) {
  const SimulateConfig config = read_config(flags);
  if (config.out) require_output_path("out", *config.out);
  const ProfileModel model = build_profile_model(config, NonPhysicalProfile::allow);
  const json report = steady_report_json(model, steady_state_of(model));
  deliver_report(report, steady_table(report, model.units), as_json, config.out);
}

}  // namespace

void add_steady_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "steady",
      "Steady state on the uniform low-friction table (Sects. 4.3, 5.1): motion case (Table 1; "
      "a priori too for three-phase profiles), average velocity v_bar (eq. 10), objective f "
      "(eq. 11) and the steady initial velocity x'_0s. A non-physical three-phase request is "
      "reported as case 0. Takes no friction-map, initial-state or time-stepping flags (a config "
      "file may hold those keys; they are ignored).");
  auto flags = add_config_flags(
      *sub, without_uniform_table_keys(
                {{"out", "write the JSON report to this file instead of printing (nothing printed)"},
                 {"summary", ""}}));
  auto as_json = std::make_shared<bool>(false);
  sub->add_flag("--json", *as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->callback([flags, as_json] { run_steady(*flags, *as_json); });
}

}  // namespace selfalign::cli
