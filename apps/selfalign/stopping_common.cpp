#include "stopping_common.hpp"

#include <string_view>

#include "report.hpp"

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

SimulateModel stopping_model(const SimulateConfig& config) {
  SimulateConfig two_region = config;
  two_region.friction = "two-region";
  two_region.method = "exact";
  return build_simulate_model(two_region);
}

const TwoRegionFriction& two_region(const SimulateModel& model) {
  const TwoRegionFriction* two = model.friction->two_region();
  if (!two)  // stopping_model() builds the two-region table; anything else is a caller's error
    throw InvalidParameter("friction", "not two-region", "this analysis needs the two-region table");
  return *two;
}

nlohmann::json stopping_context_json(const SimulateModel& model, const TwoRegionFriction& f,
                                     bool with_x_mu) {
  const OutputUnits u = model.output_units();
  nlohmann::json j;
  j["units"] = to_string(model.units);
  j["profile"] = model.profile->kind();
  if (with_x_mu) j["x_mu"] = u.length(f.x_mu());
  j["width"] = u.length(f.width());
  j["c_mu"] = f.c_mu();
  return j;
}

nlohmann::json length_or_null(const OutputUnits& u, double x) {
  return number_or_null(u.length(x));
}

}  // namespace selfalign::cli
