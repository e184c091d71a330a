#include "selfalign/simulate/simulate.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/stepper.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {

Method parse_method(const std::string& text) {
  if (text == "exact") return Method::exact;
  if (text == "time-stepping") return Method::time_stepping;
  if (text == "integrator") return Method::integrator;
  throw InvalidParameter("method", text, "must be one of: exact, time-stepping, integrator");
}

std::string to_string(Method method) {
  switch (method) {
    case Method::exact: return "exact";
    case Method::time_stepping: return "time-stepping";
    case Method::integrator: return "integrator";
  }
  return "?";
}

double require_simulatable_duration(const std::string& name, double duration, double period) {
  require_positive(name, duration);
  if (!(duration <= kMaxSimulatedPeriods * period))
    throw InvalidParameter(name, duration,
                           "must be <= 1e8 table periods (" +
                               format_number(kMaxSimulatedPeriods * period) + ")");
  return duration;
}

SimulationResult simulate(const TableProfile& profile, const FrictionMap& friction,
                          const ObjectState& initial, const SimulationOptions& o) {
  return simulate(profile, friction, FrictionLaw{}, initial, o);
}

SimulationResult simulate(const TableProfile& profile, const FrictionMap& friction,
                          const FrictionLaw& law, const ObjectState& initial,
                          const SimulationOptions& o) {
  require_simulatable_duration("duration", o.duration, profile.period());
  require_non_negative("output_step", o.output_step);
  if (!(std::abs(initial.t) <= kMaxSimulatedPeriods * profile.period()))
    throw InvalidParameter("t0", initial.t,
                           "must be within 1e8 table periods of 0 (|t0| <= " +
                               format_number(kMaxSimulatedPeriods * profile.period()) + ")");
  TimeSteppingOptions ts{o.step, o.theta};
  if (o.method == Method::time_stepping) {
    validate(ts);
    if (o.step > profile.period())
      throw InvalidParameter("step", o.step,
                             "must be <= the table period " + format_number(profile.period()) +
                                 " (a longer step skips the table's motion)");
    if (!(o.duration / o.step <= kMaxTimeSteps))
      throw InvalidParameter("step", o.step,
                             "the run would take " + format_number(std::ceil(o.duration / o.step)) +
                                 " steps (at most 1e9): raise step or shorten the run");
    // Whole steps fill the run exactly: h' = duration / ceil(duration / h) <= h, so the run ends
    // at t0 + duration, not up to h/2 beside it (1e-9: a ratio that is whole up to rounding).
    ts.step = o.duration / std::ceil(o.duration / o.step - 1e-9);
  }
  StepperRequest request;
  request.method = o.method;
  request.integrator = o.integrator;
  request.stepping = ts;
  const Stepper stepper = choose_stepper(profile, friction, law, request);
  const Method method = method_of(stepper);
  double grid = o.output_step;
  if (method == Method::time_stepping) {
    if (grid == 0) grid = ts.step;
    grid = std::max(1.0, std::round(grid / ts.step)) * ts.step;  // a whole number of steps
  } else if (grid == 0) {
    grid = profile.period() / 200;
  }
  // Sized before anything is allocated: the samples at t0 + j grid, plus the two ends.
  const double recorded = std::floor(o.duration / grid) + 2;
  if (o.record && !(recorded <= kMaxRecordedSamples))
    throw InvalidParameter("output_step", grid,
                           "the trajectory would have " + format_number(recorded) +
                               " samples (at most 1e7): raise output_step or shorten the run");

  SimulationResult r;
  const double t0 = initial.t, t_end = initial.t + o.duration, P = profile.period();
  const long long samples = o.record ? static_cast<long long>(std::floor(o.duration / grid)) : 0;
  auto push = [&](const ObjectState& s) {
    const TableState y = profile.state(s.t);
    r.trajectory.push(s.t, s.x, s.xd, y.y, y.yd, y.ydd, s.xd == 0);
  };
  if (o.record) {
    r.trajectory.reserve(static_cast<std::size_t>(samples) + 2);
    push(initial);
  }
  const double t_last_period = t_end - P;
  double x_last_period = std::numeric_limits<double>::quiet_NaN();
  bool have_last_period = t_last_period < t0 ? false : (t_last_period == t0);
  if (have_last_period) x_last_period = initial.x;
  StepperState state = make_state(stepper, initial);
  std::size_t work = 0;
  IntegratorStatistics statistics;
  auto advance_to = [&](double t) -> const ObjectState& {
    work += advance(stepper, state, t, nullptr, &statistics);
    return object_of(state);
  };
  ObjectState s = initial;
  for (long long j = 1; j <= samples; ++j) {
    const double t = t0 + static_cast<double>(j) * grid;
    if (t >= t_end) break;
    if (!have_last_period && t_last_period > t0 && t >= t_last_period) {
      x_last_period = advance_to(t_last_period).x;
      have_last_period = true;
    }
    s = advance_to(t);
    push(s);
  }
  if (!have_last_period && t_last_period > t0) x_last_period = advance_to(t_last_period).x;
  s = advance_to(t_end);
  if (o.record) push(s);
  r.final_state = s;
  r.method = method;
  r.work = work;
  r.integrator = statistics;
  r.mean_velocity_last_period = (s.x - x_last_period) / P;
  r.stick_fraction = std::numeric_limits<double>::quiet_NaN();  // nothing recorded
  if (o.record && r.trajectory.size() > 0) {
    std::size_t stuck = 0;
    for (unsigned char c : r.trajectory.stick) stuck += c;
    r.stick_fraction = static_cast<double>(stuck) / static_cast<double>(r.trajectory.size());
  }
  return r;
}

}  // namespace selfalign
