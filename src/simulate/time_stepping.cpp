#include "selfalign/simulate/time_stepping.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

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
// level read through `velocity` and `bound`: the same arithmetic whichever they are.
template <class Velocity, class Bound>
void moreau_steps(const Velocity& velocity, const Bound& bound, const FrictionLaw& law,
                  const TimeSteppingOptions& o, TimeSteppingState& state, long long steps,
                  MotionObserver* observer) {
  const double h = o.step, theta = o.theta;
  const double s = law.static_coefficient(), kf = law.kinetic_forward(),
               kb = law.kinetic_backward();
  const bool speed_dependent = law.velocity_dependent();
  double x = state.object.x, v = state.object.xd, yd = state.table_velocity;
  long long k = state.step_index;
  for (long long i = 0; i < steps; ++i) {
    ++k;
    const double t = state.t0 + static_cast<double>(k) * h;
    const double yd1 = velocity(t);
    const double x_mid = x + 0.5 * h * v;
    const double m = bound(x_mid);
    const double v_free = v - (yd1 - yd);  // velocity without friction
    // Largest friction impulses: static to hold or catch, kinetic while sliding on.
    const bool sliding_on = (v > 0 && v_free > 0) || (v < 0 && v_free < 0);
    double v1 = 0;
    if (!speed_dependent) {
      const double hold = h * ((sliding_on ? (v_free > 0 ? kf : kb) : s) * m);
      if (v_free > hold) v1 = v_free - h * (kf * m);
      else if (v_free < -hold) v1 = v_free + h * (kb * m);
    } else {  // mu_sigma(|v|) and c v at the step's start (explicit), the stick set-valued
      const int sigma = v_free > 0 ? 1 : -1;
      const double hold = h * ((sliding_on ? law.kinetic(sigma, std::abs(v)) : s) * m);
      const double drag = sliding_on ? h * law.viscous() * std::abs(v) : 0.0;
      if (std::abs(v_free) > hold + drag)
        v1 = v_free - sigma * (hold + drag);
      else if (!sliding_on && std::abs(v_free) > hold)
        v1 = v_free - sigma * h * law.kinetic(sigma, 0.0) * m;
    }
    const double x1 = x + h * ((1 - theta) * v + theta * v1);
    if (observer) {
      const auto direction = static_cast<std::int8_t>(v1 > 0 ? 1 : v1 < 0 ? -1 : 0);
      observer->on_motion({t - h, t, x, v, x1, v1, direction, ArcEnd::time_step}, nullptr);
    }
    x = x1;
    v = v1;
    yd = yd1;
  }
  state.object = {state.t0 + static_cast<double>(k) * h, x, v};
  state.step_index = k;
  state.table_velocity = yd;
  state.stick = v == 0;
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
    moreau_steps([pp](double t) { return pp->PiecewisePolynomialProfile::velocity(t); },
                 [level](double) { return level; }, law, o, state, steps, observer);
    return;
  }
  moreau_steps([&profile](double t) { return profile.velocity(t); },
               [&friction](double x) { return friction.bound(x); }, law, o, state, steps, observer);
}

}  // namespace selfalign
