// `selfalign parameters`: the named parameter view of a model (io/parameter_view.hpp): which
// numbers the model of a config depends on, with their values and units, optionally after
// changing some of them (--set NAME=VALUE, the view's `with`).

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "config_flags.hpp"
#include "report.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct ParametersFlags {
  bool as_json = false;
  std::vector<std::string> set;  // NAME=VALUE
};

// "NAME=VALUE" -> (NAME, VALUE); the value a C-locale number.
std::pair<std::string, double> parse_assignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InvalidParameter("set", text, "must be NAME=VALUE, e.g. --set c_mu=3");
  const std::string name = text.substr(0, eq);
  return {name, parse_number(name, text.substr(eq + 1))};
}

json parameters_json(const SimulateConfig& resolved) {
  json j;
  j["units"] = *resolved.units;
  j["profile"] = *resolved.profile;
  j["friction"] = *resolved.friction;
  j["parameters"] = json::array();
  for (const ModelParameter& p : model_parameters(resolved))
    j["parameters"].push_back({{"name", p.name},
                               {"value", number_or_null(p.value)},
                               {"unit", p.unit},
                               {"group", p.group},
                               {"meaning", p.meaning}});
  return j;
}

std::string parameters_table(const json& j) {
  TextTable t;
  for (const json& p : j["parameters"])
    t.row(p["name"].get<std::string>(),
          table_text(p["value"]) + " " + p["unit"].get<std::string>() + "  (" +
              p["group"].get<std::string>() + ")");
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_parameters(const ConfigFlags& flags, const ParametersFlags& f) {
  const SimulateConfig config = read_config(flags);
  if (config.out) require_output_path("out", *config.out);
  ParameterValues values;
  for (const std::string& s : f.set) values.push_back(parse_assignment(s));
  const SimulateConfig changed = with_parameters(config, values);
  (void)build_simulate_model(changed);  // the model must exist: values out of range name their key
  const json report = parameters_json(changed);
  deliver_report(report, parameters_table(report), f.as_json, config.out);
}

}  // namespace

void add_parameters_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "parameters",
      "The model's named parameters (its parameter view): every number the model of this "
      "config depends on (law, gravity in SI, friction table, profile, initial state) with its "
      "value and unit, and the two factors on the table's motion (amplitude_scale, time_scale). "
      "--set NAME=VALUE changes parameters first (the names robust design and identification "
      "use; arrays by element, accelerations[0]).");
  auto flags = add_config_flags(
      *sub, without_groups({{"out", "write the JSON report to this file instead of printing "
                                    "(nothing printed)"},
                            {"summary", ""},
                            {"method", ""},
                            {"mass", ""}},
                           {"solver"}));
  auto f = std::make_shared<ParametersFlags>();
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->add_option("--set", f->set,
                  "NAME=VALUE: set a parameter of the view before listing (repeatable; applied "
                  "in order; a factor multiplies the profile's keys as they stand)")
      ->type_name("NAME=VALUE")
      ->group("Parameters");
  sub->callback([flags, f] { run_parameters(*flags, *f); });
}

}  // namespace selfalign::cli
