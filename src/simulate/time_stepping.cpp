#include "selfalign/simulate/time_stepping.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "../profiles/tracked_velocity.hpp"
#include "moreau_slider_step.hpp"

namespace selfalign {

void validate(const TimeSteppingOptions& o) {
  require_positive("step", o.step);
  if (!(o.theta >= 0 && o.theta <= 1)) throw InvalidParameter("theta", o.theta, "must be in [0, 1]");
}

TimeSteppingState make_time_stepping_state(const TableProfile& profile, const ObjectState& object) {
  validate(object);
  TimeSteppingState s;
  s.object = object;
  s.t0 = object.t;
  s.table_velocity = profile.velocity(object.t);
  s.stick = object.xd == 0;
  return s;
}

namespace {

// Moreau's step (time_stepping.hpp) over `steps` steps, the table velocity and the friction
// level read through `velocity` and `bound`: the same arithmetic whichever they are. The law's
// speed dependence and the observer's presence are template arguments, so the common loop
// (Coulomb, unobserved) carries neither test nor call.
template <bool kSpeedDependent, bool kObserved, class Velocity, class Bound>
void moreau_loop(const Velocity& velocity, const Bound& bound, const FrictionLaw& law,
                 const TimeSteppingOptions& o, TimeSteppingState& state, long long steps,
                 MotionObserver* observer) {
  const double h = o.step, theta = o.theta, t0 = state.t0;
  const detail::SliderCoefficients c(law);
  double x = state.object.x, v = state.object.xd, yd = state.table_velocity;
  const long long k0 = state.step_index;
  for (long long i = 1; i <= steps; ++i) {
    const double t = t0 + static_cast<double>(k0 + i) * h;
    const double yd1 = velocity(t);
    const double m = bound(x + 0.5 * h * v);  // the level at the step's midpoint
    double x1;
    const double v1 = detail::moreau_slider_step<kSpeedDependent>(law, c, h, theta, m, x, v,
                                                                  v - (yd1 - yd), x1, h);
    if constexpr (kObserved) {
      const auto direction = static_cast<std::int8_t>(v1 > 0 ? 1 : v1 < 0 ? -1 : 0);
      observer->on_motion({t - h, t, x, v, x1, v1, direction, ArcEnd::time_step}, nullptr);
    }
    x = x1;
    v = v1;
    yd = yd1;
  }
  const long long k = k0 + steps;
  state.object = {t0 + static_cast<double>(k) * h, x, v};
  state.step_index = k;
  state.table_velocity = yd;
  state.stick = v == 0;
}

template <class Velocity, class Bound>
void moreau_steps(const Velocity& velocity, const Bound& bound, const FrictionLaw& law,
                  const TimeSteppingOptions& o, TimeSteppingState& state, long long steps,
                  MotionObserver* observer) {
  const bool speed = law.velocity_dependent();
  if (observer) {
    if (speed) moreau_loop<true, true>(velocity, bound, law, o, state, steps, observer);
    else moreau_loop<false, true>(velocity, bound, law, o, state, steps, observer);
  } else {
    if (speed) moreau_loop<true, false>(velocity, bound, law, o, state, steps, observer);
    else moreau_loop<false, false>(velocity, bound, law, o, state, steps, observer);
  }
}

}  // namespace

void advance_time_stepping(const TableProfile& profile, const FrictionMap& friction,
                           const FrictionLaw& law, const TimeSteppingOptions& o,
                           TimeSteppingState& state, long long steps,
                           MotionObserver* observer) {
  // The common case of every sweep: a piecewise-polynomial profile on a uniform level. Its
  // velocity is called without virtual dispatch (inlined) and the level read once; the
  // numbers are the general loop's, bit for bit (the same functions, the same arithmetic).
  const PiecewisePolynomialProfile* pp = profile.piecewise_polynomial();
  const UniformFriction* uniform = friction.uniform();
  if (pp && uniform) {
    const double level = uniform->level();
    const auto constant_level = [level](double) { return level; };
    if (pp->piecewise_constant()) {  // velocity() without its jerk test: the same numbers
      moreau_steps(detail::TrackedVelocity(*pp), constant_level, law, o, state, steps, observer);
      return;
    }
    moreau_steps([pp](double t) { return pp->PiecewisePolynomialProfile::velocity(t); },
                 constant_level, law, o, state, steps, observer);
    return;
  }
  moreau_steps([&profile](double t) { return profile.velocity(t); },
               [&friction](double x) { return friction.bound(x); }, law, o, state, steps, observer);
}

}  // namespace selfalign
