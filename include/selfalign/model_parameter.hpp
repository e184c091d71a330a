#pragma once
/// \file model_parameter.hpp
/// A named parameter of a model, and parameter values by name: the one vocabulary of every
/// model's parameter view (the 1-D config's, io/parameter_view.hpp; the planar config's,
/// io/planar_config.hpp; the contact core's model, core/parameters.hpp).

#include <string>
#include <utility>
#include <vector>

#include "selfalign/units.hpp"

namespace selfalign {

/// One named parameter of a model.
struct ModelParameter {
  std::string name;     ///< "mu_static", "accelerations[2]", "amplitude_scale"
  double value;         ///< in the run's unit system; NaN when absent (no Stribeck decay)
  Dimension dimension;  ///< how it converts between SI and dimensionless units
  std::string unit;     ///< "[-]", or the SI unit in an SI run ("[m]", "[m/s^2]")
  std::string group;    ///< "law", "scales", "friction", "profile", "initial"
  std::string meaning;  ///< one line
};

/// Parameter values by name, applied in order.
using ParameterValues = std::vector<std::pair<std::string, double>>;

}  // namespace selfalign
