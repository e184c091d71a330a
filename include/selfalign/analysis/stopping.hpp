#pragma once
/// \file stopping.hpp
/// A stopping run (Sect. 7): the object walks into the friction transition region and stops.
///
/// The end position is where the object sticks for good, established by proof:
///  - permanent stick: at rest at x with m(x) >= max |y''| (eq. 40), nothing can move it again;
///    or, where no closed form proves it at the first rest (a time-stepped run), at rest through
///    a whole table period: the one stopping criterion of every stepper (final_stick.hpp), which
///    the planar stop uses too;
///  - accumulation: for three-phase profiles, at rest at x_n at phase t1 (the end of the rest
///    through [t0, t1]) where the stick positions provably rise to the fixed point
///    x_stick,min of eq. (59)/(60) (StickPositionMap::proves_accumulation_from: the stops of
///    eq. (59) hold and rise, or the slides back after them contract, as on the diagonal
///    y3'' = y2''); the end position is that limit, reached only as t -> infinity (Sect. 7.3).
/// The run looks at the object once per period: at phase t1 for three-phase profiles, at
/// phase 0 otherwise. Any profile: the stepper is the period map's (PeriodMap: the exact solver
/// for piecewise-polynomial profiles, the smooth exact one for Fourier profiles on
/// piecewise-constant levels, the slip integrator for velocity-dependent laws, Moreau's
/// time-stepping otherwise). T_p is the final stick's start (FinalStick::since): to the step h
/// for a time-stepped run.

#include <optional>
#include <vector>

#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

/// Observed accumulation: rest positions within this fraction of (x_stick,min - x_mu) of
/// x_stick,min, approached with shrinking steps, count as accumulated there (far above the
/// rounding of positions, 1e-16, far below any tolerance a process asks of a stop).
inline constexpr double kObservedAccumulationTol = 1e-9;

enum class StopKind {
  permanent_stick,  ///< stuck for good at end_position (eq. 40)
  accumulation,     ///< stick positions accumulate at end_position = x_stick,min (eq. 60)
  /// max_periods reached without a proof (e.g. the object never arrives), a periodic orbit
  /// that never rests, or never_stops: proven never to stop (x_stick,min = +inf)
  not_stopped
};

const char* to_string(StopKind kind);

struct StoppingOptions {
  int max_periods = 10'000;      ///< give up after this many table periods
  // A run also ends, not stopped, when the state at that once-per-period look repeats
  // exactly: the object is on a periodic orbit that never comes to rest.
  /// Fractions p for which the time to reach x_mu + p (x_stick,min - x_mu) for good is
  /// reported.
  std::vector<double> fractions{0.99, 0.999};
  /// Slip integrator tolerances (a Stribeck or viscous law); its events then time the entry
  /// and the targets (docs/slip-integrator.md).
  IntegratorOptions integrator{};
  /// Time-stepping (profiles or levels no closed-form solver takes, or asked for by method):
  /// h = Δt / steps_per_period.
  int steps_per_period = 4000;
  /// The stepper (StepperRequest::method); nullopt (the default): the best the problem allows.
  std::optional<Method> method{};
};

struct StoppingRun {
  StopKind kind = StopKind::not_stopped;
  Method method = Method::exact;  ///< the stepper that ran (the period map's choice)
  double end_position = 0;   ///< where the object stops [-]; NaN when not_stopped
  /// T_p: time the final stick starts [-]; +inf for accumulation; NaN when not_stopped.
  double process_time = 0;
  double entry_time = 0;     ///< first time x >= x_mu [-]; NaN if never
  double x_stick_min = 0;    ///< eq. (41) [-]
  /// not_stopped with a proof: no position holds the object (s m(x) < max |y''| everywhere,
  /// x_stick,min = +inf by eq. 41), so it never stops for good; the run ends as soon as the
  /// object has entered the rough region (entry_time known) instead of after max_periods.
  bool never_stops = false;
  /// For accumulation: true when proven by the map of eqs. (59), (60) (the two-region table,
  /// a three-phase profile, the paper's law); false when observed: the rest positions rose to
  /// within kObservedAccumulationTol of x_stick,min, each gap smaller than the one before
  /// (finite jerk, static > kinetic, other fields: no closed-form map exists).
  bool accumulation_proven = false;
  /// Successive positions where the object came to rest at x >= x_mu (x_1, x_2, ...) [-].
  std::vector<double> stick_positions;
  /// For each options.fractions[k]: the time from which x >= x_mu + p (x_stick,min - x_mu)
  /// for good [-] (the first crossing where the object only moves forward; after slides back,
  /// as on the diagonal y3'' = y2'', the last one), NaN if not reached within max_periods; and
  /// the number of table periods from entry to then.
  std::vector<double> time_to_fraction;
  std::vector<int> periods_to_fraction;
};

/// Runs the exact solver from `start` on `friction` under the paper's law (FrictionLaw{}) until
/// the object stops for good: the overload below with the unit law; on the paper's table
/// (two_region_friction) eqs. (41), (59), (60) as written.
StoppingRun stopping_run(const TableProfile& profile, const FrictionMap& friction,
                         const ObjectState& start, const StoppingOptions& options = {});
/// The same on any piecewise-affine friction level (a FieldFriction, several steps, ...)
/// under a Coulomb law. The paper's x_mu becomes the rise of the level (friction_rise), eq.
/// (40) becomes s m(x) >= peak and eq. (41) its smallest such x from which the level stays
/// high enough (stick_position_min of the pieces); the accumulation proof (eqs. 59, 60) is the
/// paper's and applies to the two-region table with a three-phase profile under the paper's
/// law only (elsewhere an accumulating run ends not_stopped, or, time-stepped, stops where its
/// discrete scheme sticks for a whole period). Throws InvalidParameter for a level that is not
/// piecewise affine, steps_per_period < 1, or a time-stepped run of more than 1e9 steps
/// (steps_per_period x max_periods; kMaxTimeSteps). A velocity-dependent law (Stribeck, viscous) runs on the
/// slip integrator, which locates the entry and the targets' crossings as events.
StoppingRun stopping_run(const TableProfile& profile, const FrictionMap& friction,
                         const FrictionLaw& law, const ObjectState& start,
                         const StoppingOptions& options = {});

}  // namespace selfalign
