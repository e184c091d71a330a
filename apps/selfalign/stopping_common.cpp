#include "stopping_common.hpp"

#include <string_view>

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

}  // namespace selfalign::cli
