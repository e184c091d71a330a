#include "selfalign/simulate/time_stepping.hpp"

#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

void validate(const TimeSteppingOptions& o) {
  require_positive("step", o.step);
  if (!(o.theta >= 0 && o.theta <= 1)) throw InvalidParameter("theta", o.theta, "must be in [0, 1]");
}

TimeSteppingState make_time_stepping_state(const TableProfile& profile, const ObjectState& object) {
  require_finite("t0", object.t);
  require_moderate("x0", object.x);
  require_moderate("v0", object.xd);
  TimeSteppingState s;
  s.object = object;
  s.t0 = object.t;
  s.table_velocity = profile.velocity(object.t);
  s.stick = object.xd == 0;
  return s;
}

void advance_time_stepping(const TableProfile& profile, const FrictionMap& friction,
                           const TimeSteppingOptions& o, TimeSteppingState& state,
                           long long steps, StepSink* sink) {
  const double h = o.step, theta = o.theta;
  double x = state.object.x, v = state.object.xd, yd = state.table_velocity;
  long long k = state.step_index;
  for (long long i = 0; i < steps; ++i) {
    ++k;
    const double t = state.t0 + static_cast<double>(k) * h;
    const double yd1 = profile.velocity(t);
    const double x_mid = x + 0.5 * h * v;
    const double impulse = h * friction.bound(x_mid);  // largest friction impulse
    const double v_free = v - (yd1 - yd);              // velocity without friction
    double v1 = 0;
    if (v_free > impulse) v1 = v_free - impulse;
    else if (v_free < -impulse) v1 = v_free + impulse;
    x += h * ((1 - theta) * v + theta * v1);
    v = v1;
    yd = yd1;
    if (sink) {
      state.object = {t, x, v};
      state.step_index = k;
      state.table_velocity = yd;
      state.stick = v == 0;
      sink->on_step(state);
    }
  }
  state.object = {state.t0 + static_cast<double>(k) * h, x, v};
  state.step_index = k;
  state.table_velocity = yd;
  state.stick = v == 0;
}

}  // namespace selfalign
