#pragma once
/// \file profile_analyses.hpp
/// The analyses of a config's table motion as every front end runs them (`selfalign steady`,
/// `selfalign sweep`, the WebAssembly core): the options they take from the model (the law, the
/// slip integrator's tolerances for a Stribeck or viscous law, the jerk limit).

#include <optional>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign {

/// The steady state on the uniform table that `selfalign steady` reports: none for a
/// non-physical request (model.profile null: case 0, a result), else steady_state under the
/// model's law with its integrator options.
std::optional<SteadyState> steady_state_of(const ProfileModel& model);

/// The model's part of a sweep's options: law, the steady state's integrator options and the
/// jerk limit (threads and progress are the caller's).
SweepOptions sweep_options_of(const ProfileModel& model);

}  // namespace selfalign
