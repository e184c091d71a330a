// The explorer's API (issue 26, item 1): the library's own front doors behind embind, with
// configs and results as JSON text so that the page and the native CLI speak the same keys.
//   simulate(configJson)  -> the CLI's `simulate --summary` JSON (io/summary_json.hpp)
//   steady(configJson)    -> the CLI's `steady --json` report (io/steady_report.hpp)
//   sweep(configJson, a2Lo, a2Hi, n2, a3Lo, a3Hi, n3)
//                         -> `sweep accelerations`' cells on a linear (y2'', y3'') grid (run
//                            units), row-major with a2 outer: {a2, a3, case_a_priori, case,
//                            v_bar, f} as arrays (null for NaN)
// Errors come back as {"error": "<the CLI's one-line message>"} rather than as exceptions.

#include <emscripten/bind.h>

#include <cmath>
#include <exception>
#include <vector>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/steady_report.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::wasm {
namespace {

// A config from JSON text, read as a config file's keys are (simulate_config_from_json).
SimulateConfig config_of(const std::string& text) {
  return simulate_config_from_json(nlohmann::json::parse(text), "config");
}

std::string error_json(const std::exception& e) {
  return nlohmann::json{{"error", e.what()}}.dump();
}

std::string simulate_json(const std::string& config_text) {
  try {
    SimulateConfig config = config_of(config_text);
    config.out.reset();
    config.summary.reset();
    const SimulateModel model = build_simulate_model(config);
    SimulationOptions options = model.options;
    const SimulationResult result =
        simulate(*model.profile, *model.friction, model.law, model.initial, options);
    return simulate_summary_json(model, result, std::nullopt).dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// As `selfalign steady --json`: a non-physical three-phase request is a result (case 0).
std::string steady_json(const std::string& config_text) {
  try {
    const SimulateConfig config = config_of(config_text);
    const ProfileModel model = build_profile_model(config, NonPhysicalProfile::allow);
    std::optional<SteadyState> steady;
    SteadyStateOptions options;
    options.integrator = model.integrator;
    if (model.profile) steady = steady_state(*model.profile, model.law, options);
    return steady_report_json(model, steady).dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// As `selfalign sweep accelerations --a2-range LO:HI:N --a3-range LO:HI:N` (linear grids).
std::string sweep_json(const std::string& config_text, double a2_lo, double a2_hi, int n2,
                       double a3_lo, double a3_hi, int n3) {
  try {
    const SimulateConfig config = config_of(config_text);
    const ProfileModel model = build_profile_model(config, NonPhysicalProfile::allow);
    if (!model.three_phase)
      throw InvalidParameter("profile", model.profile ? model.profile->kind() : "none",
                             "the acceleration sweep needs profile = three-phase");
    const std::vector<double> a2 = linear_grid(a2_lo, a2_hi, n2), a3 = linear_grid(a3_lo, a3_hi, n3);
    std::vector<double> a2m, a3m;
    for (double v : a2) a2m.push_back(model.to_model_units(Dimension::acceleration, v));
    for (double v : a3) a3m.push_back(model.to_model_units(Dimension::acceleration, v));
    SweepOptions o;
    o.law = model.law;
    o.steady.integrator = model.integrator;
    if (model.jerk) o.jerk = *model.jerk;
    o.threads = 1;
    const std::vector<AccelerationCell> cells =
        sweep_accelerations(model.three_phase->period, model.three_phase->stroke, a2m, a3m, o);
    const OutputUnits u = model.output_units();
    nlohmann::json j;
    j["a2"] = a2, j["a3"] = a3;
    for (const char* key : {"case_a_priori", "case", "v_bar", "f"}) j[key] = nlohmann::json::array();
    for (const AccelerationCell& c : cells) {
      j["case_a_priori"].push_back(static_cast<int>(c.predicted));
      j["case"].push_back(static_cast<int>(c.observed));
      j["v_bar"].push_back(number_or_null(u.velocity(c.v_bar)));
      j["f"].push_back(number_or_null(c.f));
    }
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

}  // namespace
}  // namespace selfalign::wasm

EMSCRIPTEN_BINDINGS(selfalign) {
  emscripten::function("simulate", &selfalign::wasm::simulate_json);
  emscripten::function("steady", &selfalign::wasm::steady_json);
  emscripten::function("sweep", &selfalign::wasm::sweep_json);
}
