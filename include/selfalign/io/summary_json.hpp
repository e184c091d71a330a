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
/// The friction law as JSON: the coefficients mu (the kinetic one, the model's unit), mu_static,
/// mu_backward [-] (absolute, as given) and their ratios static, kinetic_forward,
/// kinetic_backward to mu [-]; stribeck_velocity [-] | [m/s], stribeck_exponent [-] and viscous
/// [-] | [1/s] (null when the law has none). `law` is in model units (ratios to `mu`).
nlohmann::json law_json(const FrictionLaw& law, const OutputUnits& units, double mu);

/// The slip integrator's provenance: stepper, tolerances, steps, rejected steps, right-hand-side
/// evaluations and events; null unless method is Method::integrator. `stepper` names how the
/// steps were taken (the 1-D slip integrator's dense output by default).
nlohmann::json integrator_json(Method method, const IntegratorOptions& options,
                               const IntegratorStatistics& statistics,
                               const char* stepper = "Boost.Odeint runge_kutta_dopri5, dense output");

/// The friction map as JSON: kind "two-region" (x_mu, width, c_mu), "field" (footprint, its
/// width, the field's node count, whether the exact solver takes it) or "uniform"; lengths in
/// the run's units.
nlohmann::json friction_json(const FrictionMap& f, const OutputUnits& units);

/// `value` as a JSON number, or null when it is not finite (JSON has neither NaN nor +-inf):
/// the one rule of every report (CLI, Python, WebAssembly) for absent values.
nlohmann::json number_or_null(double value);

nlohmann::json simulate_summary_json(const SimulateModel& model, const SimulationResult& result,
                                     const std::optional<std::string>& trajectory_file);

}  // namespace selfalign
