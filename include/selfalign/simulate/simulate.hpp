#pragma once
/// \file simulate.hpp
/// One front door to both solvers: simulate a run and sample its trajectory on a uniform grid.

#include <cstddef>
#include <string>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/simulate/object_state.hpp"
#include "selfalign/simulate/slip_integrator.hpp"

namespace selfalign {

/// The longest run a front door accepts, in table periods. At t = 1e8 Δt the rounding of time
/// is 1.5e-8 Δt, still far below every event spacing of a profile resolved in double precision.
inline constexpr double kMaxSimulatedPeriods = 1e8;
/// The most samples (or arcs) a run keeps in memory: about 0.5 GB of trajectory and 1 GB of CSV.
inline constexpr double kMaxRecordedSamples = 1e7;
/// The most time steps one time-stepping run may take (tens of seconds).
inline constexpr double kMaxTimeSteps = 1e9;

/// Throws InvalidParameter(name, duration, ...) unless 0 < duration <= kMaxSimulatedPeriods
/// table periods of length `period`; returns duration.
double require_simulatable_duration(const std::string& name, double duration, double period);

struct SimulationOptions {
  Method method = Method::exact;
  double duration = 20;     ///< simulated time after t0 [-], > 0
  /// time-stepping step h [-], in (0, Δt] (unused by the exact solver); shortened to
  /// duration / ceil(duration / h) so that whole steps end the run exactly at t0 + duration
  double step = 1e-4;
  double theta = 0.5;       ///< time-stepping theta, in [0, 1]
  double output_step = 0;   ///< spacing of recorded samples [-]; 0: h (time-stepping) or Δt/200
  bool record = true;       ///< false: only the summary (no trajectory): far cheaper
  /// tolerances of the slip integrator (method integrator, or exact under a velocity-dependent law)
  IntegratorOptions integrator{};
};

struct SimulationResult {
  Trajectory trajectory;           ///< samples at t0 + j*output_step, and at the end time
  ObjectState final_state;         ///< state at t0 + duration [-]
  Method method = Method::exact;   ///< the solver that produced the result
  std::size_t work = 0;            ///< arcs (exact, integrator) or steps (time-stepping) computed
  IntegratorStatistics integrator; ///< the integrator's steps, rejections, events (else zeros)
  double mean_velocity_last_period = 0;  ///< (x(t_end) - x(t_end - Δt))/Δt [-]; NaN if shorter
  double stick_fraction = 0;       ///< fraction of recorded samples in stick [-]; NaN if none
};

/// Simulates from `initial` over options.duration. Throws InvalidParameter on bad options
/// (duration beyond kMaxSimulatedPeriods periods; a recorded trajectory of more than
/// kMaxRecordedSamples samples, naming output_step; more than kMaxTimeSteps steps or a step
/// longer than the period, naming step), or when method = exact is asked of a profile that is
/// not piecewise constant or a friction map that is not piecewise affine. Every size is checked
/// before anything is allocated.
SimulationResult simulate(const TableProfile& profile, const FrictionMap& friction,
                          const ObjectState& initial, const SimulationOptions& options);
/// The same under a friction law: static >= kinetic (direction-dependent) coefficients, and a
/// velocity-dependent law (Stribeck, viscous), which has no closed form: method exact then runs
/// the slip integrator (result.method says so), as does method integrator for any law. So
/// does method exact for a smooth motion that is not a Fourier series on a friction map with
/// sloped pieces (a Fourier series is closed-form there too).
SimulationResult simulate(const TableProfile& profile, const FrictionMap& friction,
                          const FrictionLaw& law, const ObjectState& initial,
                          const SimulationOptions& options);

}  // namespace selfalign
