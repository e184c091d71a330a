#pragma once
/// \file parameter_view.hpp
/// The named parameter view of a 1-D model (issue 21, item 1): which numbers the model a
/// SimulateConfig describes depends on, by name, and `with_parameters(config, values)`, the same
/// model with some of them changed. This is the one place where the robust analyses' uncertain
/// inputs (robust/process_uncertainty.hpp) and the coming friction identification change a
/// model's parameters; `selfalign parameters` lists the view and Python's
/// `model_parameters` / `with_parameters` mirror it.
///
/// A parameter is a number key of the config that the model reads (values in the run's unit
/// system: SI in an SI run), an element of an array key ("accelerations[2]", "fourier_cos[0]"
/// = A_1: indices from 0), or one of two factors on the table's motion, y(t) -> a y(t / p):
///   amplitude_scale a  strokes x a, accelerations x a/p^2, jerks x a/p^3, Fourier coefficients x a
///   time_scale p       period, durations and breakpoint times x p
/// (the profile's keys are rescaled when the factor is applied; the view lists each factor
/// with value 1, the factor of the config as it stands). Which parameters a model has:
///   law       mu (its key group is "scales": the unit of the other coefficients), mu_static,
///             mu_backward (unset: mu), stribeck_velocity (NaN: no Stribeck decay),
///             stribeck_exponent, viscous (0: none)
///   scales    g (SI runs only: it converts the table's accelerations; the unit length_scale
///             and the reported mass are not parameters)
///   friction  two-region: x_mu, width, c_mu; field: field_positions[i] and field_levels[i]
///             when the samples are in the config (not in field_file), width with a uniform
///             footprint; uniform: none
///   profile   three-phase: period, stroke, a2, a3 (jerk when given); fourier: period,
///             fourier_cos[i], fourier_sin[i]; quadratic-sequence: durations[i],
///             accelerations[i]; piecewise-linear: times[i], accelerations[i], period;
///             samples: none (the samples are in their file); the two factors for every family
///             but samples
///   initial   t0, x0, v0
/// Solver, output and unit keys (method, step, periods, units, length_scale, ...) are settings,
/// not parameters.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "selfalign/io/simulate_config.hpp"
#include "selfalign/model_parameter.hpp"

namespace selfalign {

/// The parameters of the model `config` describes (defaults resolved: resolve_simulate_config),
/// in the order of the key table (law, scales, friction, profile, initial), the two factors
/// after the profile's keys. Throws what resolve_simulate_config throws, and InvalidParameter
/// naming profile or friction when either is not one of their kinds.
std::vector<ModelParameter> model_parameters(const SimulateConfig& config);

/// A view with a fixed set of free parameters, for evaluating one model at many parameter
/// values (a Monte Carlo draw, a least-squares iteration): the config is resolved and the
/// names are looked up once; `with(values)` then only copies the config and sets the values.
class ParameterView {
 public:
  /// \param config the model; \param free the names varied, in the order `with` takes their
  /// values. Throws as the free function `with` does for a name that is not a parameter.
  ParameterView(const SimulateConfig& config, const std::vector<std::string>& free);
  ~ParameterView();
  ParameterView(ParameterView&&) noexcept;
  ParameterView& operator=(ParameterView&&) noexcept;

  /// The free parameters' names, as given.
  const std::vector<std::string>& names() const noexcept { return names_; }
  /// The config, resolved (the free parameters at their values in it, the factors 1).
  const SimulateConfig& config() const noexcept { return config_; }
  /// The free parameters' values in config() (the factors 1).
  std::vector<double> values() const;
  /// config() with the free parameters set to `values` (one per name, in order; applied in
  /// order). Throws InvalidParameter naming a parameter whose value is not finite (a factor:
  /// not > 0), and ("values", size) when the count differs from names().
  SimulateConfig with(const std::vector<double>& values) const;

 private:
  struct Handles;
  SimulateConfig config_;
  std::vector<std::string> names_;
  std::unique_ptr<Handles> handles_;
};

/// The config (resolved) with these parameter values, applied in order (a factor multiplies the
/// profile's keys as they are when it is applied). Values are not range-checked here beyond
/// finiteness (and the factors > 0): building the model checks them, naming the key. Throws
/// InvalidParameter naming the parameter when the name is not a parameter of this model (with
/// the model's kind: "c_mu is not a parameter of this model (friction = uniform)", or a setting
/// "step is a solver setting, not a model parameter"), an index is out of range, or a value is
/// not finite.
SimulateConfig with_parameters(const SimulateConfig& config, const ParameterValues& values);

}  // namespace selfalign
