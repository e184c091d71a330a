// The explorer's API (issue 26, item 1): the library's own front doors behind embind, with
// configs and results as JSON text so that the page and the native CLI speak the same keys.
//   simulate(configJson)  -> the CLI's `simulate --summary` JSON (io/summary_json.hpp)
// Errors come back as {"error": "<the CLI's one-line message>"} rather than as exceptions.

#include <emscripten/bind.h>

#include <exception>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::wasm {
namespace {

// A config from JSON text: every key as `set_simulate_config_value` takes it (numbers written
// with 17 digits, arrays comma-separated), so the page's keys are the config files' keys.
SimulateConfig config_of(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  SimulateConfig c;
  for (const auto& [key, value] : j.items()) {
    std::string v;
    if (value.is_string()) {
      v = value.get<std::string>();
    } else if (value.is_array()) {
      for (const auto& e : value) {
        std::ostringstream s;
        s.precision(17);
        s << e.get<double>();
        v += (v.empty() ? "" : ",") + s.str();
      }
    } else {
      std::ostringstream s;
      s.precision(17);
      s << value.get<double>();
      v = s.str();
    }
    set_simulate_config_value(c, key, v);
  }
  return c;
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

}  // namespace
}  // namespace selfalign::wasm

EMSCRIPTEN_BINDINGS(selfalign) {
  emscripten::function("simulate", &selfalign::wasm::simulate_json);
}
