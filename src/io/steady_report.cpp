// The steady-state report (io/steady_report.hpp): moved from the CLI's `steady` so that the
// WebAssembly core reports the same keys.

#include "selfalign/io/steady_report.hpp"

#include <cmath>
#include <string>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

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

}  // namespace

json steady_report_json(const ProfileModel& model, const std::optional<SteadyState>& steady) {
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


}  // namespace selfalign
