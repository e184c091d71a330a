#pragma once
/// \file simulate_model.hpp
/// From a SimulateConfig to the model objects of one run, in dimensionless units (Sect. 3.2):
/// the table profile, the friction map, the initial state and the solver options
/// (SimulateModel), or the table profile alone for the analyses (ProfileModel).

#include <memory>
#include <optional>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/unit_system.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/profiles/three_phase.hpp"
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
  FrictionLaw law;                     ///< (mu_static, mu, mu_backward) / mu [-]
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

/// The run's friction law in model units: FrictionLaw(mu_static/mu, 1, mu_backward/mu),
/// the unit being mu = mu_1, the forward kinetic coefficient of the low-friction region, with
/// a Stribeck decay (stribeck_velocity, stribeck_exponent) and a viscous term (viscous) when
/// given (model units: pass a dimensionless config). Throws InvalidParameter naming mu_static
/// (< mu), mu_backward (> mu_static, <= 0), stribeck_velocity, stribeck_exponent or viscous.
FrictionLaw friction_law(const SimulateConfig& config);

/// The table profile of a run and its unit system, for the analyses of the uniform table
/// (steady state, Floquet multipliers, convergence, sweeps), which take no friction map,
/// initial state or solver settings: those keys are ignored (not validated).
struct ProfileModel {
  UnitSystem units;                        ///< the run's input/output unit system
  Scales scales;                           ///< L, mu, g (used for I/O only in SI runs)
  /// [-]; null only for a non-physical (case 0) three-phase request built with
  /// NonPhysicalProfile::allow.
  std::unique_ptr<TableProfile> profile;
  /// The three-phase parameters [-] when profile = three-phase (physical or not), else none.
  std::optional<ThreePhaseParameters> three_phase;
  /// The three-phase profile's jerk limit [-] when one is given (the profile is then the
  /// jerk-limited one, and the paper's jump-acceleration formulas do not apply), else none.
  std::optional<double> jerk;
  FrictionLaw law;                     ///< (mu_static, mu, mu_backward) / mu [-]
  /// The slip integrator's tolerances (relative_tolerance, absolute_tolerance): used when the
  /// law is speed-dependent (Stribeck, viscous).
  IntegratorOptions integrator{};

  /// Converts results back to the run's unit system.
  OutputUnits output_units() const {
    return units == UnitSystem::si ? OutputUnits(scales) : OutputUnits();
  }
  /// A value of dimension `d` given in the run's unit system, in dimensionless units [-].
  double to_model_units(Dimension d, double value) const {
    return InputUnits(units, scales)(d, value);
  }
  /// A dimensionless value of dimension `d` in the run's unit system.
  double from_model_units(Dimension d, double value) const {
    return units == UnitSystem::si ? to_si(d, value, scales) : value;
  }
};

/// What build_profile_model does with a three-phase request that has no solution (case 0).
enum class NonPhysicalProfile {
  reject,  ///< throw InvalidParameter naming "a2, a3", as build_simulate_model does
  allow    ///< return it as a value: profile null, three_phase set
};

/// Resolves defaults, converts SI inputs with one Scales and builds the table profile; errors
/// are reported like build_simulate_model's (SI values restated in SI).
ProfileModel build_profile_model(const SimulateConfig& config,
                                 NonPhysicalProfile non_physical = NonPhysicalProfile::reject);

/// The config's friction map alone (friction = two-region, uniform or field, with its keys), in
/// model units [-], checked as build_simulate_model checks it (SI values restated in SI): for
/// the analyses that take a table but build their own profiles (sweep positioning).
std::unique_ptr<FrictionMap> build_friction_map(const SimulateConfig& config);

}  // namespace selfalign
