#pragma once
/// \file simulate_model.hpp
/// From a SimulateConfig to the model objects of one run, in dimensionless units (Sect. 3.2):
/// the table profile, the friction map, the initial state and the solver options.

#include <memory>

#include "selfalign/friction/friction_map.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/unit_system.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/object_state.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/units.hpp"

namespace selfalign {

/// Everything simulate() needs, validated, plus what output conversion needs.
struct SimulateModel {
  UnitSystem units;                        ///< the run's input/output unit system
  Scales scales;                           ///< L, mu, g (used for I/O only in SI runs)
  double mass;                             ///< [kg], reported only
  double periods;                          ///< number of table periods simulated [-]
  std::unique_ptr<TableProfile> profile;   ///< [-]
  std::unique_ptr<FrictionMap> friction;   ///< [-]
  ObjectState initial;                     ///< t0, x0, v0 [-]
  SimulationOptions options;               ///< [-]; duration = periods * Δt

  /// Converts results back to the run's unit system.
  OutputUnits output_units() const {
    return units == UnitSystem::si ? OutputUnits(scales) : OutputUnits();
  }
};

/// Resolves defaults (resolve_simulate_config), converts SI inputs with one Scales, and builds
/// the model. The library constructors validate the values and throw InvalidParameter naming
/// the parameter and its allowed range (e.g. "invalid width = -1: must be > 0"); a case-0
/// three-phase request throws naming "a2, a3". Keys the chosen profile or friction map does
/// not use are ignored.
SimulateModel build_simulate_model(const SimulateConfig& config);

}  // namespace selfalign
