#pragma once
/// \file stop_report.hpp
/// The report of a stopping run at the friction step (Sect. 7; `selfalign stop`, and the
/// WebAssembly core's `stop`, wasm/api.cpp), and the parts the Sect. 7 reports share: the model
/// on the two-region table (or the config's friction field), the table's context and absent
/// lengths as null. Lengths and times in the run's units.

#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/analysis/stopping.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign {

/// The run's model on the two-region table, or on the config's friction field where the
/// config names it (friction = field, or a field_file, which implies it); method exact
/// (accumulation then needs the field to be the paper's table: as_two_region_table).
/// friction = uniform (no rise: nothing stops) is refused naming "friction", never replaced by
/// the default table; `command` names the caller in that message. Validated by
/// build_simulate_model: x_mu, width, c_mu, t0, x0, v0 and output_step in [-], errors restated
/// in SI for SI runs; a case-0 request is an error.
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

/// The report of `run` (`selfalign stop --json`): stopping_context_json, "stop" (how it
/// stopped), "accumulation_proven", "law", "method", "end_position" and "process_time" (null when
/// not stopped; process_time null for accumulation, reached only as t -> inf), "entry_time",
/// "x_stick_min" (eq. 41), "stick_positions", "fractions" (p, the position x_mu + p
/// (x_stick,min - x_mu), the time it is reached for good and the periods from entry), "initial"
/// and "max_periods".
nlohmann::json stop_report_json(const SimulateModel& model, const StoppingOptions& options,
                                const StoppingRun& run);

/// Where a stopping run's trajectory ends [-]: the stop (permanent stick); the last fraction
/// reached plus one period (accumulation, whose stop is at t = inf); the whole run of
/// `max_periods` periods (not stopped). At least one period after t0.
double stop_trajectory_end(const StoppingRun& run, double t0, double period, int max_periods);

}  // namespace selfalign
