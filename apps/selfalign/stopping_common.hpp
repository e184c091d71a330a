#pragma once
// The parts the Sect. 7 subcommands share (stop, accuracy, accumulation, sweep positioning):
// the config-key flags without the keys they do not use and the stopping options. The model on
// the two-region table and the report's parts are the library's (io/stop_report.hpp).

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "config_flags.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/stop_report.hpp"  // stopping_model, stopping_context_json, ...

namespace selfalign::cli {

/// Adds the config-key flags for a Sect. 7 command: the table is always two-region and the
/// solver exact, so --friction, --method, --step, --theta and --periods are left out (still
/// accepted, and ignored, in a --config file); `overrides` rewords or removes more keys.
std::shared_ptr<ConfigFlags> add_stopping_config_flags(CLI::App& command,
                                                       std::vector<KeyFlag> overrides);

/// Adds --max-periods (StoppingOptions::max_periods, >= 1) with its default.
void add_max_periods_option(CLI::App& command, int& max_periods);

}  // namespace selfalign::cli
