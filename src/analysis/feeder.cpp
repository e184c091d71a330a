#include "selfalign/analysis/feeder.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "parallel_cells.hpp"
#include "selfalign/analysis/feeder_exact.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {

// The least K > 0 with K |slope| > rhs (docs/feeder.md): 0 when rhs <= 0 (violated at rest),
// +inf when the drive does not enter the inequality (slope 0).
double onset(double rhs, double slope) {
  if (rhs <= 0) return 0.0;
  return slope == 0 ? kInf : rhs / std::abs(slope);
}

}  // namespace

void require_feeder_angle(std::string_view name, double angle) {
  if (!(std::abs(angle) < 0.5 * std::numbers::pi))
    throw InvalidParameter(std::string(name), angle, "must be in (-pi/2, pi/2) rad");
}

void validate(const FeederDrive& d) {
  require_positive_moderate("amplitude", d.amplitude);
  require_positive_moderate("period", d.period);
  require_feeder_angle("vibration_angle", d.vibration_angle);
  require_feeder_angle("incline", d.incline);
  require_positive_moderate("g", d.g);
  if (!(d.harmonic_ratio >= 0 && d.harmonic_ratio <= 100))
    throw InvalidParameter("harmonic_ratio", d.harmonic_ratio, "must be in [0, 100]");
  if (!std::isfinite(d.harmonic_phase))
    throw InvalidParameter("harmonic_phase", d.harmonic_phase, "must be finite");
}

void require_feeder_track(double incline, double mu_static, double mu_kinetic, double g,
                          double period) {
  require_feeder_angle("incline", incline);
  require_positive_moderate("mu_static", mu_static);
  require_positive_moderate("mu_kinetic", mu_kinetic);
  if (mu_kinetic > mu_static)
    throw InvalidParameter("mu_kinetic", mu_kinetic, "must be <= mu_static");
  require_positive_moderate("g", g);
  require_positive_moderate("period", period);
}

double machine_number(const FeederDrive& d) {
  const double w = 2 * std::numbers::pi / d.period;
  return d.amplitude * w * w / d.g;
}

FeederShape feeder_shape(const FeederDrive& d) {
  validate(d);
  const double r = d.harmonic_ratio, p2 = d.harmonic_phase;
  if (r == 0) return {};
  const auto s = [&](double phi) { return std::sin(phi) + 4 * r * std::sin(2 * phi + p2); };
  const auto ds = [&](double phi) { return std::cos(phi) + 8 * r * std::cos(2 * phi + p2); };
  constexpr int kSamples = 4096;
  const double step = 2 * std::numbers::pi / kSamples;
  FeederShape out{-kInf, -kInf};
  for (int i = 0; i < kSamples; ++i) {
    double lo = i * step, hi = lo + step;
    const double a = ds(lo), b = ds(hi);
    if ((a > 0) == (b > 0)) continue;  // no extremum of s in this sample (s' keeps its sign)
    for (int k = 0; k < 200 && hi - lo > 1e-15 * (1 + hi); ++k) {
      const double mid = 0.5 * (lo + hi);
      ((ds(mid) > 0) == (a > 0) ? lo : hi) = mid;
    }
    const double v = s(0.5 * (lo + hi));
    out.peak_up = std::max(out.peak_up, v), out.peak_down = std::max(out.peak_down, -v);
  }
  return out;
}

double throw_number(const FeederDrive& d) {
  const FeederShape sh = feeder_shape(d);
  const double sp = std::sin(d.vibration_angle);
  return machine_number(d) * sp * (sp >= 0 ? sh.peak_up : sh.peak_down) / std::cos(d.incline);
}

namespace {

// The onsets of a shape with peaks up (S+) and down (S-): K s c > rhs is first met where s c is
// largest, K c S+ for c > 0 and K |c| S- for c < 0.
FeederOnsets shaped_onsets(double psi, double theta, double mu, const FeederShape& sh) {
  require_feeder_angle("vibration_angle", psi);
  require_feeder_angle("incline", theta);
  require_positive("static_friction", mu);
  // With a_x = -K g cos(psi) s, a_z = -K g sin(psi) s, s the shape (sin(w t) classically):
  //   forward:  K s (cos psi + mu sin psi) > sin theta + mu cos theta,
  //   backward: K s (mu sin psi - cos psi) > mu cos theta - sin theta,
  //   lift-off: K s sin psi > cos theta.
  const double c = std::cos(psi), s = std::sin(psi), ct = std::cos(theta), st = std::sin(theta);
  const auto peak = [&](double coefficient) {
    return coefficient * (coefficient >= 0 ? sh.peak_up : sh.peak_down);
  };
  return {onset(st + mu * ct, peak(c + mu * s)), onset(mu * ct - st, peak(mu * s - c)),
          onset(ct, peak(s))};
}

}  // namespace

FeederOnsets feeder_onsets(const FeederDrive& d, double mu) {
  return shaped_onsets(d.vibration_angle, d.incline, mu, feeder_shape(d));
}

FeederOnsets feeder_onsets(double psi, double theta, double mu) {
  return shaped_onsets(psi, theta, mu, FeederShape{});
}

FeederTable::FeederTable(const FeederDrive& drive) : drive_(drive) {
  validate(drive);
  const double psi = drive.vibration_angle, a0 = drive.amplitude;
  // a0 (sin w t + r sin(2 w t + phi2)) along the line: r sin(2 w t + phi2) = r cos(phi2)
  // sin(2 w t) + r sin(phi2) cos(2 w t)
  const double r = drive.harmonic_ratio;
  const auto line = [&](double scale) {
    if (r == 0)
      return std::make_shared<FourierProfile>(drive.period, std::vector<double>{0.0},
                                              std::vector<double>{scale});
    return std::make_shared<FourierProfile>(
        drive.period, std::vector<double>{0.0, scale * r * std::sin(drive.harmonic_phase)},
        std::vector<double>{scale, scale * r * std::cos(drive.harmonic_phase)});
  };
  along_ = line(a0 * std::cos(psi));
  if (std::sin(psi) != 0) normal_ = line(a0 * std::sin(psi));
  motion_.first = along_.get();
  motion_.normal = normal_.get();
  gravity_ = {drive.g, std::abs(drive.incline), drive.incline > 0 ? -1.0 : 1.0, 0.0};
}

namespace {

// feeder_model's body with the field given.
core::Model track_model(const FeederTable& table, const FrictionLaw& law, PlanarField field,
                        long long steps_per_period, bool flight, double restitution) {
  if (!(steps_per_period >= 2 && steps_per_period <= 100000000))
    throw InvalidParameter("steps_per_period", static_cast<double>(steps_per_period),
                           "must be in [2, 1e8]");
  core::Model model;
  model.motion = table.motion();
  model.field = std::move(field);
  model.bodies = {core::SliderBody{PointFootprint{}, law}};
  model.options = {table.drive().period / static_cast<double>(steps_per_period), 0.5};
  model.gravity = table.gravity();
  model.gravity->flight = flight;
  model.gravity->restitution = restitution;
  core::validate(model);
  return model;
}

}  // namespace

core::Model feeder_model(const FeederTable& table, const FrictionLaw& law, double level,
                         long long steps_per_period, bool flight, double restitution) {
  return track_model(table, law, UniformPlanarField{level}, steps_per_period, flight,
                     restitution);
}

core::Model feeder_model(const FeederTable& table, const FrictionLaw& law,
                         const FrictionField& field, long long steps_per_period, bool flight,
                         double restitution) {
  return track_model(table, law, AxisField{field}, steps_per_period, flight, restitution);
}

const char* feeder_event_name(FeederEvent event) noexcept {
  switch (event) {
    case FeederEvent::none: return "none";
    case FeederEvent::forward_slip: return "forward slip";
    case FeederEvent::backward_slip: return "backward slip";
    case FeederEvent::lift_off: return "lift-off";
  }
  return "none";
}

namespace {

// Watches a feeder run step by step: the first event, and the census of the counted steps.
struct FeederWatch final : MotionObserver {
  FeederRun& run;
  bool counting = false, was_flying = false;
  double period_start = 0;     // of the counted period
  double first_lift = NAN;     // the counted period's first lift-off (end of its step)
  long long sticks = 0, flights = 0;
  explicit FeederWatch(FeederRun& r) : run(r) {}
  void on_step(const core::State& state) override {
    const core::BodyState& b = state.bodies[0];
    const bool flying = b.height > 0 || b.normal_velocity > 0;
    const double u = b.twist.ux;
    if (run.first_event == FeederEvent::none) {
      if (flying) run.first_event = FeederEvent::lift_off, run.first_event_time = state.t;
      else if (u != 0)
        run.first_event = u > 0 ? FeederEvent::forward_slip : FeederEvent::backward_slip,
        run.first_event_time = state.t;
    }
    run.lifted_off = run.lifted_off || flying;
    if (counting) {
      sticks += !flying && u == 0, flights += flying;
      if (flying && !was_flying && std::isnan(first_lift)) first_lift = state.t - period_start;
    }
    was_flying = flying;
  }
};

}  // namespace

namespace {

// The model's steps in one period (InvalidParameter naming "period" unless it is a whole number
// of them).
long long steps_in(const core::Model& model, double period) {
  require_positive("period", period);
  const double n = period / model.options.step;
  if (!(std::abs(n - std::round(n)) <= 1e-9 * n) || n < 1)
    throw InvalidParameter("period", period, "must be a whole number of the model's steps");
  return std::llround(n);
}

}  // namespace

FeederRun feeder_run(const core::Model& model, double period, long long periods) {
  core::validate(model);
  if (model.bodies.size() != 1 || !std::holds_alternative<core::SliderBody>(model.bodies[0]))
    throw InvalidParameter("bodies", static_cast<double>(model.bodies.size()),
                           "the feeder run takes one 1-D part (SliderBody)");
  if (periods < 1) throw InvalidParameter("periods", static_cast<double>(periods), "must be >= 1");
  const long long per_period = steps_in(model, period);
  const std::vector<PlanarPose> poses(1);
  const std::vector<PlanarTwist> twists(1);
  core::State state = core::make_state(model, 0.0, poses, twists);
  FeederRun run;
  run.first_event_time = NAN;
  FeederWatch watch(run);
  double x_last = 0;
  for (long long p = 0; p < periods; ++p) {
    watch.counting = p + 1 == periods;
    if (watch.counting) x_last = state.bodies[0].pose.x, watch.period_start = state.t;
    core::step(model, state, per_period, &watch);
    if (state.status == core::StepStatus::lift_off) {  // no flight: the run stops there
      run.lifted_off = true;
      if (run.first_event == FeederEvent::none)
        run.first_event = FeederEvent::lift_off, run.first_event_time = state.t;
      run.velocity = run.stick_fraction = run.flight_fraction = NAN;
      return run;
    }
  }
  run.velocity = (state.bodies[0].pose.x - x_last) / period;
  run.stick_fraction = static_cast<double>(watch.sticks) / static_cast<double>(per_period);
  run.flight_fraction = static_cast<double>(watch.flights) / static_cast<double>(per_period);
  if (watch.flights > 0) {
    run.flight_angle = 2 * std::numbers::pi * run.flight_fraction;
    // a flight that carries over from the period before starts the period off the track
    run.lift_off_phase = 2 * std::numbers::pi / period *
                         (std::isnan(watch.first_lift) ? 0.0 : watch.first_lift);
  }
  return run;
}

namespace {

// The exact solver's track for the table's drive (the stopping run adds its field).
FeederTrack exact_track(const FeederTable& table, const FrictionLaw& law, double level,
                        double restitution) {
  const FeederDrive& d = table.drive();
  FeederTrack track{table.motion().first, table.motion().normal, d.g, d.incline, level, law};
  track.restitution = restitution;
  return track;
}

void require_feeder_method(Method method) {
  if (method != Method::exact && method != Method::time_stepping)
    throw InvalidParameter("method", to_string(method), "must be exact or time-stepping");
}

}  // namespace

FeederRun feeder_run_exact(const FeederTable& table, const FrictionLaw& law, double level,
                           long long periods, double restitution, bool flight) {
  if (periods < 1) throw InvalidParameter("periods", static_cast<double>(periods), "must be >= 1");
  const FeederDrive& d = table.drive();
  const FeederTrack track = exact_track(table, law, level, restitution);
  validate(track);
  FeederRun run;
  FeederExactState state;
  FeederExactStatistics all, last;
  double x_last = 0;
  for (long long p = 0; p < periods; ++p) {
    const bool counting = p + 1 == periods;
    if (counting) x_last = state.x;
    FeederExactStatistics now;
    advance_feeder_exact(track, state, static_cast<double>(p + 1) * d.period, &now);
    if (std::isnan(all.first_lift_off)) all.first_lift_off = now.first_lift_off;
    if (std::isnan(all.first_slip))
      all.first_slip = now.first_slip, all.first_slip_direction = now.first_slip_direction;
    all.lift_offs += now.lift_offs;
    if (counting) last = now;
    if (!flight && all.lift_offs > 0) break;
  }
  const bool lifts = !std::isnan(all.first_lift_off);
  const bool slips = !std::isnan(all.first_slip);
  run.first_event_time = NAN;
  if (lifts && (!slips || all.first_lift_off < all.first_slip))
    run.first_event = FeederEvent::lift_off, run.first_event_time = all.first_lift_off;
  else if (slips)
    run.first_event = all.first_slip_direction > 0 ? FeederEvent::forward_slip
                                                   : FeederEvent::backward_slip,
    run.first_event_time = all.first_slip;
  run.lifted_off = lifts;
  if (!flight && lifts) {  // as feeder_run without the model's flight: the run stops there
    run.velocity = run.stick_fraction = run.flight_fraction = NAN;
    return run;
  }
  run.velocity = (state.x - x_last) / d.period;
  // fractions of the counted window as the solver's times cover it (a period held throughout
  // is a stick fraction of exactly 1)
  const double window = static_cast<double>(periods) * d.period -
                        static_cast<double>(periods - 1) * d.period;
  run.stick_fraction = last.stick_time / window;
  run.flight_fraction = last.flight_time / window;
  if (last.flight_time > 0) {
    run.flight_angle = 2 * std::numbers::pi * run.flight_fraction;
    // a flight that carries over from the period before starts the period off the track
    const double start = static_cast<double>(periods - 1) * d.period;
    run.lift_off_phase = 2 * std::numbers::pi / d.period *
                         (std::isnan(last.first_lift_off) ? 0.0 : last.first_lift_off - start);
  }
  return run;
}

FeederStop feeder_stop_exact(const FeederTable& table, const FrictionLaw& law,
                             const FrictionField& field, double start, long long max_periods,
                             double restitution) {
  if (!std::isfinite(start)) throw InvalidParameter("start", start, "must be finite");
  if (max_periods < 1)
    throw InvalidParameter("max_periods", static_cast<double>(max_periods), "must be >= 1");
  const FieldFriction level(field, PointFootprint{});
  if (!level.piecewise_affine())
    throw InvalidParameter("field", "ramps", "must be piecewise constant (steps)");
  const FeederDrive& d = table.drive();
  FeederTrack track = exact_track(table, law, d.g, restitution);
  track.field = level.piecewise_affine();
  FeederExactState state;
  state.x = start;
  FeederStop out;
  double last_motion = NAN;
  for (long long p = 0; p < max_periods; ++p) {
    FeederExactStatistics now;
    advance_feeder_exact(track, state, static_cast<double>(p + 1) * d.period, &now);
    out.periods = p + 1;
    out.lifted_off = out.lifted_off || now.lift_offs > 0;
    if (!std::isnan(now.last_motion)) last_motion = now.last_motion;
    // held through the whole period, at rest on the track at its start and end
    if (now.slip_time == 0 && now.flight_time == 0 && now.lift_offs == 0 &&
        state.mode == FeederMode::stick && state.u == 0 && state.h == 0) {
      out.stopped = true;
      out.end_position = state.x;
      out.stop_time = std::isnan(last_motion) ? 0.0 : last_motion;
      return out;
    }
  }
  return out;
}

namespace {

// Watches a stopping run step by step: whether the counted period moved, and the end of the
// last step that moved.
struct FeederStopWatch final : MotionObserver {
  bool moved = false, lifted = false;
  double last_motion = NAN;
  void on_step(const core::State& state) override {
    const core::BodyState& b = state.bodies[0];
    const bool flying = b.height > 0 || b.normal_velocity > 0;
    if (flying || b.twist.ux != 0) moved = true, last_motion = state.t;
    lifted = lifted || flying;
  }
};

}  // namespace

FeederStop feeder_stop(const core::Model& model, double period, double start,
                       long long max_periods) {
  core::validate(model);
  if (model.bodies.size() != 1 || !std::holds_alternative<core::SliderBody>(model.bodies[0]))
    throw InvalidParameter("bodies", static_cast<double>(model.bodies.size()),
                           "the feeder run takes one 1-D part (SliderBody)");
  if (!std::isfinite(start)) throw InvalidParameter("start", start, "must be finite");
  if (max_periods < 1)
    throw InvalidParameter("max_periods", static_cast<double>(max_periods), "must be >= 1");
  const long long per_period = steps_in(model, period);
  std::vector<PlanarPose> poses(1);
  poses[0].x = start;
  const std::vector<PlanarTwist> twists(1);
  core::State state = core::make_state(model, 0.0, poses, twists);
  FeederStop out;
  FeederStopWatch watch;
  for (long long p = 0; p < max_periods; ++p) {
    watch.moved = false;
    core::step(model, state, per_period, &watch);
    out.periods = p + 1;
    out.lifted_off = watch.lifted;
    if (state.status != core::StepStatus::ok) return out;  // stopped at a lift-off
    if (!watch.moved) {
      out.stopped = true;
      out.end_position = state.bodies[0].pose.x;
      out.stop_time = std::isnan(watch.last_motion) ? 0.0 : watch.last_motion;
      return out;
    }
  }
  return out;
}

FeederRun feeder_run(const FeederTable& table, const FrictionLaw& law, double level,
                     long long periods, const FeederSolver& solver) {
  require_feeder_method(solver.method);
  if (solver.method == Method::exact)
    return feeder_run_exact(table, law, level, periods, solver.restitution, solver.flight);
  return feeder_run(feeder_model(table, law, level, solver.steps_per_period, solver.flight,
                                 solver.restitution),
                    table.drive().period, periods);
}

FeederStop feeder_stop(const FeederTable& table, const FrictionLaw& law,
                       const FrictionField& field, double start, long long max_periods,
                       const FeederSolver& solver) {
  require_feeder_method(solver.method);
  if (solver.method == Method::exact)
    return feeder_stop_exact(table, law, field, start, max_periods, solver.restitution);
  return feeder_stop(feeder_model(table, law, field, solver.steps_per_period, solver.flight,
                                  solver.restitution),
                     table.drive().period, start, max_periods);
}

const char* feeder_regime_name(FeederRegime regime) noexcept {
  switch (regime) {
    case FeederRegime::stick: return "stick";
    case FeederRegime::forward: return "forward";
    case FeederRegime::backward: return "backward";
    case FeederRegime::both: return "both";
    case FeederRegime::hopping: return "hopping";
  }
  return "stick";
}

FeederRegime feeder_regime(const FeederOnsets& o, double K) {
  if (K >= o.lift_off) return FeederRegime::hopping;
  const bool forward = K > o.forward_slip, backward = K > o.backward_slip;
  return forward && backward ? FeederRegime::both
         : forward           ? FeederRegime::forward
         : backward          ? FeederRegime::backward
                             : FeederRegime::stick;
}

std::vector<FeederChartCell> feeder_regime_chart(const std::vector<double>& angles,
                                                 const std::vector<double>& ks,
                                                 const FeederChartOptions& o) {
  require_feeder_track(o.incline, o.mu_static, o.mu_kinetic, o.g, o.period);
  if (o.periods < 1) throw InvalidParameter("periods", static_cast<double>(o.periods), "must be >= 1");
  if (angles.empty() || ks.empty())
    throw InvalidParameter(angles.empty() ? "vibration_angles" : "machine_numbers", "empty",
                           "needs at least one value");
  for (double a : angles) require_feeder_angle("vibration_angles", a);
  for (double k : ks) require_positive_moderate("machine_numbers", k);
  if (!(static_cast<double>(angles.size()) * static_cast<double>(ks.size()) <= 1e8))
    throw InvalidParameter("machine_numbers", static_cast<double>(ks.size()),
                           "the chart must have at most 1e8 cells");
  if (!(o.restitution >= 0 && o.restitution <= 1))
    throw InvalidParameter("restitution", o.restitution, "must be in [0, 1]");
  require_feeder_method(o.method);
  // One run's model, checked once (steps_per_period names itself).
  const FrictionLaw law(o.mu_static, o.mu_kinetic);
  const double w = 2 * std::numbers::pi / o.period;
  {
    const FeederTable probe({1.0, o.period, angles[0], o.incline, o.g});
    (void)feeder_model(probe, law, o.g, o.steps_per_period, o.flight);
  }
  std::vector<FeederChartCell> out(angles.size() * ks.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    FeederChartCell& c = out[i];
    c.vibration_angle = angles[i / ks.size()], c.machine_number = ks[i % ks.size()];
    c.throw_number = c.machine_number * std::sin(c.vibration_angle) / std::cos(o.incline);
    c.regime = feeder_regime(feeder_onsets(c.vibration_angle, o.incline, o.mu_static),
                             c.machine_number);
  }
  SweepOptions so;
  so.threads = o.threads;
  so.progress = o.progress;
  detail::parallel_cells(
      out.size(), so,
      [&](std::size_t i) {
        FeederChartCell& c = out[i];
        const double a0 = c.machine_number * o.g / (w * w);
        if (c.regime == FeederRegime::stick) {
          // Proven by the onsets: the part at rest is held at every instant, so the run is
          // known without stepping it (no event, velocity 0, every step a stick).
          c.run.first_event = FeederEvent::none, c.run.first_event_time = NAN;
          c.run.lifted_off = false, c.run.velocity = 0, c.run.stick_fraction = 1;
          c.run.flight_fraction = 0;
          c.dimensionless_speed = 0;
          return;
        }
        const FeederTable table({a0, o.period, c.vibration_angle, o.incline, o.g});
        c.run = feeder_run(table, law, o.g, o.periods,
                           {o.method, o.steps_per_period, o.flight, o.restitution});
        c.dimensionless_speed = c.run.velocity / (a0 * w * std::cos(c.vibration_angle));
      },
      [&](std::size_t i, const std::string& why) {
        out[i].run.velocity = out[i].run.stick_fraction = out[i].run.flight_fraction = NAN;
        out[i].dimensionless_speed = NAN;
        out[i].failure = why;
      });
  return out;
}

}  // namespace selfalign
