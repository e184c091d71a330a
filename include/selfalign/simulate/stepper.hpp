#pragma once
/// \file stepper.hpp
/// The 1-D steppers behind one concept, and the one dispatcher that chooses among them.
///
/// A stepper is a solver's immutable setup; its state is made by make_state() and moved on by
/// advance(), whatever the solver:
///   Stepper s = choose_stepper(profile, friction, law, request);
///   StepperState st = make_state(s, start);
///   advance(s, st, t_end, observer);        // object_of(st) is the state at t_end
/// The closed set of steppers (a std::variant, visited; no if-chains over pointers):
///   ExactSetup        piecewise-polynomial y'' on a piecewise-affine level (exact.hpp)
///   SmoothSetup       smooth motion on a level the smooth solver takes (smooth_exact.hpp)
///   IntegratorSetup   velocity-dependent laws; exact sticks, dopri5 slips (slip_integrator.hpp)
///   TimeSteppingSetup Moreau time-stepping, any profile and level (time_stepping.hpp)
/// PeriodMap (analysis/period_map.hpp) and simulate() (simulate.hpp) both take their solver
/// from choose_stepper(): the choice is made in one place.

#include <cstddef>
#include <optional>
#include <span>
#include <variant>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/simulate/motion_observer.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {

/// Moreau time-stepping's setup: the profile and level it reads (borrowed), the law, the step.
struct TimeSteppingSetup {
  const TableProfile& profile;
  const FrictionMap& friction;
  FrictionLaw law{};
  TimeSteppingOptions options{};
};

using Stepper = std::variant<ExactSetup, SmoothSetup, IntegratorSetup, TimeSteppingSetup>;

/// A stepper's mutable state: ExactState for ExactSetup, TimeSteppingState for
/// TimeSteppingSetup, the plain ObjectState for the smooth solver and the integrator.
using StepperState = std::variant<ExactState, ObjectState, TimeSteppingState>;

/// What the caller asks of the dispatcher.
struct StepperRequest {
  /// nullopt: the best the problem allows: exact (piecewise-polynomial, then smooth) where a
  /// closed form exists, else the slip integrator, else time-stepping (PeriodMap's choice).
  /// exact: a closed form, or the integrator where the law is velocity-dependent or the smooth
  /// solver cannot take the motion's level; InvalidParameter naming "method" when neither can.
  /// integrator / time_stepping: that method, or InvalidParameter naming "method".
  std::optional<Method> method;
  IntegratorOptions integrator{};
  /// Time-stepping: options.step > 0 is used as given; step == 0 means
  /// period / steps_per_period (steps_per_period >= 1, checked only when time-stepping is
  /// chosen).
  TimeSteppingOptions stepping{0.0, 0.5};
  int steps_per_period = 4000;
};

/// The one solver dispatcher. The returned setup borrows profile and friction (they must
/// outlive it). Throws InvalidParameter as described in StepperRequest, and for invalid
/// integrator or time-stepping options.
Stepper choose_stepper(const TableProfile& profile, const FrictionMap& friction,
                       const FrictionLaw& law, const StepperRequest& request);

/// The method a stepper implements (exact for both closed-form steppers).
Method method_of(const Stepper& stepper) noexcept;
/// True for the closed-form steppers, which deliver arcs.
bool has_arcs(const Stepper& stepper) noexcept;

/// The stepper's state at `start` (its time, position and velocity).
StepperState make_state(const Stepper& stepper, const ObjectState& start);
/// The object's state held in a stepper state.
const ObjectState& object_of(const StepperState& state) noexcept;

/// Advances `state` to t_end (time-stepping: the step nearest t_end). Every piece of the motion
/// goes to observer (motion_observer.hpp: arcs with their closed form, the integrator's
/// intervals, time steps); the integrator's work is added to stats (if any). `watch` (sorted
/// positions) asks the slip integrator to report their crossings to observer->on_crossing; a
/// non-empty watch given to another stepper throws InvalidParameter naming "method". Returns the
/// arcs, intervals or steps computed.
std::size_t advance(const Stepper& stepper, StepperState& state, double t_end,
                    MotionObserver* observer = nullptr, IntegratorStatistics* stats = nullptr,
                    std::span<const double> watch = {});

}  // namespace selfalign
