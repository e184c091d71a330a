#include "selfalign/simulate/stepper.hpp"

#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

namespace {

TimeSteppingSetup time_stepping_setup(const TableProfile& profile, const FrictionMap& friction,
                                      const FrictionLaw& law, const StepperRequest& r) {
  TimeSteppingOptions o = r.stepping;
  if (!(o.step > 0)) {
    if (r.steps_per_period < 1)
      throw InvalidParameter("steps_per_period", r.steps_per_period, "must be >= 1");
    o.step = profile.period() / r.steps_per_period;
  }
  validate(o);
  return {profile, friction, law, o};
}

}  // namespace

// Exact where a closed form exists: piecewise-polynomial acceleration on a piecewise-affine
// level, or a smooth motion on a level the smooth solver takes; the slip integrator for a
// velocity-dependent law (piecewise-polynomial or smooth profiles on piecewise-affine levels)
// and for a smooth motion other than a Fourier series on a level with slopes; time-stepping
// otherwise, or where asked for.
Stepper choose_stepper(const TableProfile& profile, const FrictionMap& friction,
                       const FrictionLaw& law, const StepperRequest& r) {
  const PiecewisePolynomialProfile* pwp = profile.piecewise_polynomial();
  const SmoothMotion* motion = profile.smooth();
  const PiecewiseAffineFriction* affine = friction.piecewise_affine();
  const bool closed_form = !law.velocity_dependent();
  const bool smooth_applies = motion && affine && smooth_solver_applies(*motion, *affine);

  if (!r.method) {  // the best the problem allows
    if (closed_form && pwp && affine) return ExactSetup{*pwp, *affine, law};
    if (closed_form && smooth_applies) return SmoothSetup{*motion, *affine, law};
    if (affine && integrable_profile(profile)) {
      validate(r.integrator);
      return IntegratorSetup{profile, *affine, law, r.integrator};
    }
    return time_stepping_setup(profile, friction, law, r);
  }

  Method method = *r.method;
  // No closed form: a speed-dependent law, or a smooth motion the smooth solver cannot take.
  if (method == Method::exact && (!closed_form || (!pwp && motion && affine && !smooth_applies)))
    method = Method::integrator;
  if (method == Method::integrator) {
    validate(r.integrator);
    if (!integrable_profile(profile))
      throw InvalidParameter("method", to_string(*r.method),
                             "the slip integrator needs a piecewise-polynomial or smooth profile (" +
                                 profile.kind() + " here); use time-stepping");
    if (!affine)
      throw InvalidParameter("method", to_string(*r.method),
                             "the slip integrator needs a piecewise-affine friction map; use "
                             "time-stepping");
    return IntegratorSetup{profile, *affine, law, r.integrator};
  }
  if (method == Method::exact) {
    if (!pwp && smooth_applies) return SmoothSetup{*motion, *affine, law};
    if (!pwp)
      throw InvalidParameter("method", "exact",
                             "needs a piecewise-constant or piecewise-linear acceleration, or a "
                             "smooth profile on a piecewise-constant friction map (" +
                                 profile.kind() + " here); use time-stepping");
    if (!affine)
      throw InvalidParameter("method", "exact",
                             "needs a piecewise-affine friction map; use time-stepping");
    return ExactSetup{*pwp, *affine, law};
  }
  return time_stepping_setup(profile, friction, law, r);
}

Method method_of(const Stepper& stepper) noexcept {
  return std::visit(Overloaded{[](const IntegratorSetup&) { return Method::integrator; },
                               [](const TimeSteppingSetup&) { return Method::time_stepping; },
                               [](const auto&) { return Method::exact; }},
                    stepper);
}

bool has_arcs(const Stepper& stepper) noexcept {
  return std::holds_alternative<ExactSetup>(stepper) ||
         std::holds_alternative<SmoothSetup>(stepper);
}

StepperState make_state(const Stepper& stepper, const ObjectState& start) {
  return std::visit(
      Overloaded{[&](const ExactSetup& s) { return StepperState{make_exact_state(s, start)}; },
                 [&](const TimeSteppingSetup& s) {
                   return StepperState{make_time_stepping_state(s.profile, start)};
                 },
                 [&](const auto&) { return StepperState{start}; }},
      stepper);
}

const ObjectState& object_of(const StepperState& state) noexcept {
  return std::visit(Overloaded{[](const ExactState& s) -> const ObjectState& { return s.object; },
                               [](const TimeSteppingState& s) -> const ObjectState& {
                                 return s.object;
                               },
                               [](const ObjectState& s) -> const ObjectState& { return s; }},
                    state);
}

std::size_t advance(const Stepper& stepper, StepperState& state, double t_end,
                    MotionObserver* observer, IntegratorStatistics* stats,
                    std::span<const double> watch) {
  if (!watch.empty() && !std::holds_alternative<IntegratorSetup>(stepper))
    throw InvalidParameter("method", to_string(method_of(stepper)),
                           "watched crossings come from the slip integrator only");
  return std::visit(
      Overloaded{
          [&](const ExactSetup& s) -> std::size_t {
            return advance_exact(s, std::get<ExactState>(state), t_end, observer);
          },
          [&](const SmoothSetup& s) -> std::size_t {
            return advance_smooth(s, std::get<ObjectState>(state), t_end, observer);
          },
          [&](const IntegratorSetup& s) -> std::size_t {
            return advance_integrated(s, std::get<ObjectState>(state), t_end, observer, stats,
                                      watch);
          },
          [&](const TimeSteppingSetup& s) -> std::size_t {
            TimeSteppingState& ts = std::get<TimeSteppingState>(state);
            const long long target = std::llround((t_end - ts.t0) / s.options.step);
            if (target <= ts.step_index) return 0;
            const long long steps = target - ts.step_index;
            advance_time_stepping(s.profile, s.friction, s.law, s.options, ts, steps, observer);
            return static_cast<std::size_t>(steps);
          }},
      stepper);
}

}  // namespace selfalign
