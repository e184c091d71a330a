#include "stopping_common.hpp"

#include <string_view>

#include "report.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/io/summary_json.hpp"

namespace selfalign::cli {

std::shared_ptr<ConfigFlags> add_stopping_config_flags(CLI::App& command,
                                                       std::vector<KeyFlag> overrides) {
  for (std::string_view key : {"friction", "method", "step", "theta", "periods"})
    overrides.push_back({key, ""});
  return add_config_flags(command, overrides);
}

void add_max_periods_option(CLI::App& command, int& max_periods) {
  command
      .add_option("--max-periods", max_periods,
                  "give up a stopping run (not-stopped) after N table periods, >= 1. Default: " +
                      std::to_string(max_periods))
      ->type_name("N")
      ->group("Solver");
}

SimulateModel stopping_model(const SimulateConfig& config, const std::string& command) {
  SimulateConfig c = config;
  // friction as the config resolves it (a field_file alone implies field: simulate_config.cpp)
  const bool field = *resolve_simulate_config(config).friction == "field";
  if (config.friction && *config.friction == "uniform")
    throw InvalidParameter("friction", "uniform",
                           command + " needs a rise of friction: two-region or field");
  if (!field) c.friction = "two-region";
  c.method = "exact";
  return build_simulate_model(c);
}

nlohmann::json stopping_context_json(const SimulateModel& model, bool with_x_mu) {
  const OutputUnits u = model.output_units();
  nlohmann::json j;
  j["units"] = to_string(model.units);
  j["profile"] = model.profile->kind();
  if (const TwoRegionTable* f = model.friction->two_region()) {
    if (with_x_mu) j["x_mu"] = u.length(f->x_mu());
    j["width"] = u.length(f->width());
    j["c_mu"] = f->c_mu();
    return j;
  }
  // A field: the rise of its level stands for x_mu (stopping.hpp), no single c_mu.
  if (with_x_mu) j["x_mu"] = length_or_null(u, friction_rise(*model.friction));
  add_field_json(j, *model.friction, u);
  return j;
}

void add_field_json(nlohmann::json& j, const FrictionMap& field, const OutputUnits& u) {
  const FieldFriction* f = field.field_friction();
  const auto* uniform = f ? std::get_if<UniformFootprint>(&f->footprint()) : nullptr;
  j["width"] = uniform ? nlohmann::json(u.length(uniform->width)) : nlohmann::json(nullptr);
  j["c_mu"] = nullptr;
  j["friction"] = friction_json(field, u);
}

nlohmann::json length_or_null(const OutputUnits& u, double x) {
  return number_or_null(u.length(x));
}

}  // namespace selfalign::cli
