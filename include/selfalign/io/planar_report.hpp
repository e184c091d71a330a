#pragma once
/// \file planar_report.hpp
/// The reports of a planar run (`selfalign planar ...`, and the WebAssembly core's `planar`,
/// wasm/api.cpp; docs/planar.md): the run's units, the header every planar report starts with,
/// a pose and a step census as JSON, and the one simulate run (its checks, the run, its report).

#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/io/planar_config.hpp"
#include "selfalign/planar/planar_run.hpp"

namespace selfalign {

/// SI views of a planar setup's dimensionless values (the identity in a dimensionless config).
struct PlanarUnits {
  const PlanarSetup& s;
  double length(double v) const { return s.si ? s.scales.length_to_si(v) : v; }
  double time(double v) const { return s.si ? s.scales.time_to_si(v) : v; }
  double velocity(double v) const { return s.si ? s.scales.velocity_to_si(v) : v; }
  double rate(double v) const { return s.si ? to_si(Dimension::rate, v, s.scales) : v; }
  /// `si` in an SI config, else `dimensionless` (unit labels and column suffixes).
  std::string u(const char* si, const char* dimensionless) const { return s.si ? si : dimensionless; }
};

/// The steps in stick, pivot and slip, and the stick fraction (null without steps).
nlohmann::json planar_census_json(const PlanarCensus& census);

/// x, y in the run's units and angle_rad; null where not finite.
nlohmann::json planar_pose_json(const PlanarPose& pose, const PlanarUnits& units);

/// What every planar report starts with: config, units, scales, contact points, inertia per
/// unit mass, step and steps per period.
nlohmann::json planar_report_header(const PlanarSetup& setup);

/// `planar simulate`: checks the run (run.periods' steps, run.every's rows, the method's
/// conditions: InvalidParameter naming the key) and runs simulate_planar for [run] periods,
/// recording every [run] every steps.
PlanarTrajectory planar_simulate_run(const PlanarSetup& setup, const PlanarRunProgress& progress = {});

/// The report of `planar simulate` (`--json`): the header, method, periods, end pose and twist,
/// census, the step solver's work and the integrator's provenance.
nlohmann::json planar_simulate_report_json(const PlanarSetup& setup, const PlanarTrajectory& run);

}  // namespace selfalign
