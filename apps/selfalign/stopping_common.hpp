#pragma once
// The parts the Sect. 7 subcommands share (stop, accuracy, accumulation, sweep positioning):
// the config-key flags without the keys they do not use, the model on the two-region table,
// the stopping options, and formatting a stopping run's outcome.

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "config_flags.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign::cli {

/// Adds the config-key flags for a Sect. 7 command: the table is always two-region and the
/// solver exact, so --friction, --method, --step, --theta and --periods are left out (still
/// accepted, and ignored, in a --config file); `overrides` rewords or removes more keys.
std::shared_ptr<ConfigFlags> add_stopping_config_flags(CLI::App& command,
                                                       std::vector<KeyFlag> overrides);

/// Adds --max-periods (StoppingOptions::max_periods, >= 1) with its default.
void add_max_periods_option(CLI::App& command, int& max_periods);

/// The run's model on the two-region table, or on the config's friction field where the
/// config names it (friction = field, or a field_file, which implies it); method exact
/// (accumulation then needs the field to be the paper's table: as_two_region_table).
/// friction = uniform (no rise: nothing stops) is refused naming "friction", never replaced by
/// the default table. Validated by build_simulate_model: x_mu, width, c_mu, t0, x0, v0 and
/// output_step in [-], errors restated in SI for SI runs; a case-0 request is an error.
SimulateModel stopping_model(const SimulateConfig& config, const std::string& command);

/// The unit system and the table's friction parameters of a report: "units", "profile",
/// "x_mu" (omitted when `with_x_mu` is false), "width", "c_mu"; lengths in the run's units.
/// On a field: "x_mu" is the rise of its level (friction_rise: where stopping_run measures
/// from), "width" the footprint's (null for a point), "c_mu" null, and "friction" the field's
/// description (summary_json's friction_json).
nlohmann::json stopping_context_json(const SimulateModel& model, bool with_x_mu);

/// A field's part of a report: "width" the footprint's (null for a point), "c_mu" null (a field
/// has no single ratio) and "friction" the field's description (summary_json's friction_json).
void add_field_json(nlohmann::json& j, const FrictionMap& field, const OutputUnits& u);

/// A position [-] in the run's units, or null when not finite (x_stick,min = +inf when the
/// peak acceleration exceeds c_mu; NaN where there is none).
nlohmann::json length_or_null(const OutputUnits& u, double x);

}  // namespace selfalign::cli
