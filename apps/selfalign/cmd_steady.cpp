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

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

// The profile part of the report, in the run's units: kind, Δt, Δy, and for three-phase
// profiles y2'', y3'' and the switch times of the appendix (null where there are none).
void add_profile(json& j, const ProfileModel& model) {
  const OutputUnits u = model.output_units();
  const std::optional<ThreePhaseParameters>& p = model.three_phase;
  j["profile"] = model.profile ? model.profile->kind() : std::string("three-phase");
  j["period"] = u.time(p ? p->period : model.profile->period());
  j["stroke"] = u.length(p ? p->stroke : model.profile->stroke());
  j["a2"] = p ? json(u.acceleration(p->a2)) : json(nullptr);
  j["a3"] = p ? json(u.acceleration(p->a3)) : json(nullptr);
  for (const char* key : {"t1", "t2", "t3", "y_ini", "y_dot_ini"}) j[key] = nullptr;
  j["jerk"] = model.jerk ? json(model.from_model_units(Dimension::jerk, *model.jerk)) : json(nullptr);
  if (!p || model.jerk) return;
  const ThreePhaseSolution s = solve_three_phase(*p);  // Appendix, eqs. (61)-(67)
  if (!s.physical) return;
  j["t1"] = u.time(s.t1);
  j["t2"] = u.time(s.t2);
  j["t3"] = u.time(s.t3);
  j["y_ini"] = u.length(s.y_ini);
  j["y_dot_ini"] = u.velocity(s.yd_ini);
}

// The paper's jump-acceleration formulas (switch times, a-priori case) describe the profile
// only without a jerk limit and under the paper's law.
bool paper_three_phase(const ProfileModel& model) {
  return model.three_phase && !model.jerk && model.law.is_unit();
}

json steady_json(const ProfileModel& model, const std::optional<SteadyState>& steady) {
  const OutputUnits u = model.output_units();
  json j;
  j["units"] = to_string(model.units);
  add_profile(j, model);
  const StickSlipCase observed = steady ? steady->motion_case : StickSlipCase::non_physical;
  j["case"] = static_cast<int>(observed);
  j["case_name"] = describe(observed);
  j["case_a_priori"] = paper_three_phase(model)
                           ? json(static_cast<int>(predict_case(*model.three_phase)))
                           : json(nullptr);
  j["law"] = law_json(model.law, model.output_units(), model.scales.mu());
  for (const char* key : {"v_bar", "f", "x_dot_0s", "x_dot_0s_error", "phase", "displacement",
                          "converged", "periods", "method", "pattern", "integrator"})
    j[key] = nullptr;
  if (!steady) return j;
  j["pattern"] = steady->pattern;  // the stick/slip sequence, e.g. "stick,forward,backward"
  j["v_bar"] = u.velocity(steady->v_bar);
  j["f"] = number_or_null(steady->f);  // [-] always: f of the dimensionless v̄
  j["x_dot_0s"] = u.velocity(steady->x_dot_0s);
  j["x_dot_0s_error"] = number_or_null(u.velocity(steady->x_dot_0s_error));  // a bound
  j["phase"] = u.time(steady->phase);
  j["displacement"] = u.length(steady->displacement);
  j["converged"] = steady->converged;
  j["periods"] = steady->periods;
  j["method"] = to_string(steady->method);
  j["integrator"] = integrator_json(steady->method, model.integrator, steady->integrator);
  return j;
}

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
  std::optional<SteadyState> steady;
  SteadyStateOptions options;
  options.integrator = model.integrator;  // Stribeck or viscous laws
  if (model.profile) steady = steady_state(*model.profile, model.law, options);
  const json report = steady_json(model, steady);
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
