#pragma once
/// \file summary_json.hpp
/// The JSON summary of one simulate run: the setup (units, method, profile, friction), the
/// initial and final state, the solver's work and the run's statistics. Every number is in the
/// run's unit system; docs/config.md lists the keys.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/io/simulate_model.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign {

/// The summary of `result`, a run of `model`. trajectory_file: the CSV written, or none (null).
nlohmann::json simulate_summary_json(const SimulateModel& model, const SimulationResult& result,
                                     const std::optional<std::string>& trajectory_file);

}  // namespace selfalign
