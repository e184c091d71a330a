#pragma once
/// \file steady_report.hpp
/// The JSON report of a steady state on the uniform table (`selfalign steady --json`, and the
/// WebAssembly core's `steady`, wasm/api.cpp): the profile (kind, period, stroke, a2, a3, jerk,
/// the appendix's switch times), the motion case (observed and, for the paper's three-phase
/// profile, a priori), the law, and v̄, f, x'_0s, phase, displacement, convergence, the
/// stick/slip pattern and the integrator's provenance, in the run's units (f always [-]).
/// Absent values are null; a non-physical request (no steady state) is case 0.

#include <optional>

#include <nlohmann/json.hpp>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign {

nlohmann::json steady_report_json(const ProfileModel& model,
                                  const std::optional<SteadyState>& steady);

}  // namespace selfalign
