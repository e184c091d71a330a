// The vibratory feeder (analysis/feeder.hpp, docs/feeder.md): the drive, its closed-form
// onsets, and runs of the contact core.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/feeder.hpp"
#include "selfalign/design/feeder_drive.hpp"
#include "selfalign/error.hpp"

namespace selfalign::python {

void bind_feeder(py::module_& m) {
  py::class_<FeederDrive> drive(m, "FeederDrive", R"doc(
The sinusoidal feeder drive on an inclined track (docs/feeder.md): x = a0 cos(psi) sin(w t)
along the track, z = a0 sin(psi) sin(w t) along its normal, w = 2 pi / period, the track
inclined by `incline` (> 0: rising along +x), gravity `g` in model units (1/mu_1 in the
paper's; any consistent units, e.g. SI with g = 9.81). Raises InvalidParameter naming
amplitude, period, vibration_angle (|psi| >= pi/2), incline (|theta| >= pi/2) or g.)doc");
  drive
      .def(py::init([](double amplitude, double period, double vibration_angle, double incline,
                       double g, double harmonic_ratio, double harmonic_phase) {
             FeederDrive d{amplitude,       period,        vibration_angle, incline, g,
                           harmonic_ratio, harmonic_phase};
             validate(d);
             return d;
           }),
           py::arg("amplitude"), py::arg("period") = 1.0, py::arg("vibration_angle") = 0.0,
           py::arg("incline") = 0.0, py::arg("g") = 1.0, py::arg("harmonic_ratio") = 0.0,
           py::arg("harmonic_phase") = 0.0)
      .def_readonly("amplitude", &FeederDrive::amplitude, "a0 along the vibration line [-]")
      .def_readonly("period", &FeederDrive::period, "2 pi / w [-]")
      .def_readonly("vibration_angle", &FeederDrive::vibration_angle, "psi [rad]")
      .def_readonly("incline", &FeederDrive::incline, "theta [rad]")
      .def_readonly("g", &FeederDrive::g, "gravity in model units [-]")
      .def_readonly("harmonic_ratio", &FeederDrive::harmonic_ratio,
                    "r: the second harmonic's amplitude over a0 [-] (0: the classic sinusoid)")
      .def_readonly("harmonic_phase", &FeederDrive::harmonic_phase, "phi2 [rad]")
      .def("__repr__", [](const FeederDrive& d) {
        return Repr("FeederDrive")("amplitude", d.amplitude)("period", d.period)(
                   "vibration_angle", d.vibration_angle)("incline", d.incline)("g", d.g)(
                   "harmonic_ratio", d.harmonic_ratio)("harmonic_phase", d.harmonic_phase)
            .str();
      });
  def_record(
      drive,
      [](double a, double p, double psi, double theta, double g, double r, double phase) {
        FeederDrive d{a, p, psi, theta, g, r, phase};
        validate(d);
        return d;
      },
      field("amplitude", &FeederDrive::amplitude), field("period", &FeederDrive::period),
      field("vibration_angle", &FeederDrive::vibration_angle),
      field("incline", &FeederDrive::incline), field("g", &FeederDrive::g),
      field("harmonic_ratio", &FeederDrive::harmonic_ratio),
      field("harmonic_phase", &FeederDrive::harmonic_phase));
  m.def("machine_number", &machine_number, py::arg("drive"),
        "K = a0 w^2 / g: the drive's peak acceleration over g.");
  m.def("throw_number", &throw_number, py::arg("drive"),
        "Gamma = K S sin(psi) / cos(theta), S the shape's peak away from the track (1 for the "
        "classic sinusoid): the part lifts off where |Gamma| > 1.");

  using O = FeederOnsets;
  py::class_<O> onsets(m, "FeederOnsets", R"doc(
The onsets as critical machine numbers K (feeder_onsets): +inf never, 0 not held even at rest.)doc");
  onsets.def_readonly("forward_slip", &O::forward_slip, "K of the first forward slip")
      .def_readonly("backward_slip", &O::backward_slip, "K of the first backward slip")
      .def_readonly("lift_off", &O::lift_off, "K of the lift-off (Gamma = 1)")
      .def("__repr__", [](const O& o) {
        return Repr("FeederOnsets")("forward_slip", o.forward_slip)(
                   "backward_slip", o.backward_slip)("lift_off", o.lift_off)
            .str();
      });
  def_record(onsets, field("forward_slip", &O::forward_slip),
             field("backward_slip", &O::backward_slip), field("lift_off", &O::lift_off));
  m.def("feeder_onsets",
        py::overload_cast<double, double, double>(&feeder_onsets), py::arg("vibration_angle"),
        py::arg("incline"), py::arg("static_friction"), R"doc(
The closed-form onsets (docs/feeder.md) of a part at rest on the track under the sinusoidal
drive: the least machine number K at which it first slips forward, slips backward, or lifts
off. static_friction: the absolute static coefficient mu_s (s m / g in model units). Returns
FeederOnsets. Raises InvalidParameter naming vibration_angle, incline or static_friction.)doc");
  m.def("feeder_onsets",
        py::overload_cast<const FeederDrive&, double>(&feeder_onsets), py::arg("drive"),
        py::arg("static_friction"), R"doc(
The onsets of the drive's own shape (a two-frequency drive: each inequality first met at the
shape's peak on its side, feeder_shape), as machine numbers K of its fundamental.)doc");
  py::class_<FeederShape> shape(m, "FeederShape",
                                "The drive's acceleration shape's peaks (feeder_shape).");
  shape.def_readonly("peak_up", &FeederShape::peak_up, "max of s(phi) [-]")
      .def_readonly("peak_down", &FeederShape::peak_down, "max of -s(phi) [-]")
      .def("__repr__", [](const FeederShape& v) {
        return Repr("FeederShape")("peak_up", v.peak_up)("peak_down", v.peak_down).str();
      });
  def_record(shape, field("peak_up", &FeederShape::peak_up),
             field("peak_down", &FeederShape::peak_down));
  m.def("feeder_shape", &feeder_shape, py::arg("drive"), R"doc(
The drive's acceleration shape along the vibration line, s(phi) = sin(phi) + 4 r sin(2 phi +
phi2) (the acceleration is -a0 w^2 s(w t)): its largest value and the largest of -s (both 1 for
the classic sinusoid).)doc");

  bind_int_enum<FeederEvent>(m, "FeederEvent", "The first thing that happens to a part at rest on the track.",
                             {{"none", FeederEvent::none},
                              {"forward_slip", FeederEvent::forward_slip},
                              {"backward_slip", FeederEvent::backward_slip},
                              {"lift_off", FeederEvent::lift_off}});
  using R = FeederRun;
  py::class_<R> run(m, "FeederRun", "A run of a part on the feeder track (feeder_run).");
  run.def_readonly("first_event", &R::first_event, "FeederEvent")
      .def_readonly("first_event_time", &R::first_event_time,
                    "the instant it happened (exact) or the end of its step (time-stepping) "
                    "[-]; NaN for none")
      .def_readonly("lifted_off", &R::lifted_off,
                    "the part left the track (without flight the run stopped there)")
      .def_readonly("velocity", &R::velocity,
                    "mean velocity along the track over the last period [-]; NaN if the run "
                    "stopped at a lift-off (flight=False)")
      .def_readonly("stick_fraction", &R::stick_fraction,
                    "of the last period's time (steps when time-stepping): held on the track "
                    "(NaN if the run stopped)")
      .def_readonly("flight_fraction", &R::flight_fraction,
                    "of the last period's time (steps when time-stepping): off the track (NaN "
                    "if the run stopped)")
      .def_readonly("lift_off_phase", &R::lift_off_phase,
                    "w (t - period start) of the last period's first lift-off [rad]; NaN "
                    "without a flight")
      .def_readonly("flight_angle", &R::flight_angle,
                    "2 pi flight_fraction: w times the time off the track [rad]; NaN without a "
                    "flight")
      .def("__repr__", [](const R& r) {
        return Repr("FeederRun")
            .raw("first_event", std::string("FeederEvent.") + feeder_event_name(r.first_event))(
                "first_event_time", r.first_event_time)("lifted_off", r.lifted_off)(
                "velocity", r.velocity)("stick_fraction", r.stick_fraction)(
                "flight_fraction", r.flight_fraction)
            .str();
      });
  def_record(run, field("first_event", &R::first_event),
             field("first_event_time", &R::first_event_time),
             field("lifted_off", &R::lifted_off), field("velocity", &R::velocity),
             field("stick_fraction", &R::stick_fraction),
             field("flight_fraction", &R::flight_fraction),
             field("lift_off_phase", &R::lift_off_phase),
             field("flight_angle", &R::flight_angle));
  m.def(
      "feeder_run",
      [](const FeederDrive& drive, const FrictionLaw& law, double level,
         long long steps_per_period, long long periods, bool flight, Method method,
         double restitution) {
        return feeder_run(FeederTable(drive), law, level, periods,
                          {method, steps_per_period, flight, restitution});
      },
      py::arg("drive"), py::arg("law") = FrictionLaw{}, py::kw_only(), py::arg("level") = 1.0,
      py::arg("steps_per_period") = 2000, py::arg("periods") = 20, py::arg("flight") = true,
      py::arg("method") = Method::exact, py::arg("restitution") = 0.0,
      py::call_guard<py::gil_scoped_release>(), R"doc(
A part at rest at x = 0, t = 0 on the drive's track (one 1-D part, the uniform friction level
`level`, `law`) for `periods` periods: the first event, the mean conveying velocity of the last
period, its stick and flight fractions, lift-off phase and flight angle (FeederRun). The
friction bound is law coefficient x level x (g cos theta + z'') / g, so the absolute
coefficient is s level / g. method=Method.exact (the default; "exact"): the exact feeder
solver (closed-form arcs, events by the certified scan, exact event times); 
method=Method.time_stepping ("time-stepping"): the contact core's Moreau step with
`steps_per_period` steps, flight by Moreau-Jean. Landings with Newton's `restitution` e in
[0, 1] (0: plastic) and a tangential impulse within the kinetic cone. flight=False: a run that
reaches lift-off stops there (lifted_off, velocity NaN). Raises InvalidParameter naming the bad
argument. Runs without the GIL.)doc");

  using S = FeederStop;
  py::class_<S> stop(m, "FeederStop",
                     "A stopping run on a feeder track with a friction step (feeder_stop).");
  stop.def_readonly("stopped", &S::stopped,
                    "held through a whole period: it stays (the drive is periodic)")
      .def_readonly("end_position", &S::end_position,
                    "where it rests on the track [-]; NaN when it did not stop")
      .def_readonly("stop_time", &S::stop_time,
                    "the instant it last moved, from the release [-]; NaN when it did not stop")
      .def_readonly("periods", &S::periods, "periods run (the stopping one included)")
      .def_readonly("lifted_off", &S::lifted_off, "it left the track at some time")
      .def("__repr__", [](const S& r) {
        return Repr("FeederStop")("stopped", r.stopped)("end_position", r.end_position)(
                   "stop_time", r.stop_time)("periods", r.periods)("lifted_off", r.lifted_off)
            .str();
      });
  def_record(stop, field("stopped", &S::stopped), field("end_position", &S::end_position),
             field("stop_time", &S::stop_time), field("periods", &S::periods),
             field("lifted_off", &S::lifted_off));
  m.def(
      "feeder_stop",
      [](const FeederDrive& drive, const FrictionLaw& law, double step_position, double c_mu,
         double start, long long max_periods, double level, Method method,
         long long steps_per_period, bool flight, double restitution) {
        require_finite("step_position", step_position);
        if (!(c_mu > 0 && c_mu <= 1e6)) throw InvalidParameter("c_mu", c_mu, "must be in (0, 1e6]");
        require_positive_moderate("level", level);
        const FrictionField field = FrictionField::steps({step_position}, {level, c_mu * level});
        return feeder_stop(FeederTable(drive), law, field, start, max_periods,
                           {method, steps_per_period, flight, restitution});
      },
      py::arg("drive"), py::arg("law") = FrictionLaw{}, py::kw_only(), py::arg("step_position"),
      py::arg("c_mu") = 2.5, py::arg("start") = 0.0, py::arg("max_periods") = 1000,
      py::arg("level") = 1.0, py::arg("method") = Method::exact,
      py::arg("steps_per_period") = 2000, py::arg("flight") = true,
      py::arg("restitution") = 0.0, py::call_guard<py::gil_scoped_release>(), R"doc(
Stopping at a friction step on a vibrating feeder track (docs/feeder.md): the part, released at
rest at `start` on the drive's track, the friction level `level` before `step_position` and
c_mu x level from it on, runs period by period until it is held through a whole period (then
it stays: the drive is periodic). Returns FeederStop: stopped, end_position and stop_time (NaN
when it still moved after `max_periods` periods: a result, not an error), periods, lifted_off.
method="exact" (the default: the exact feeder solver) or "time-stepping" (the contact core with
`steps_per_period`; flight=False stops the run at a lift-off). In SI: g = 9.81 in the drive and
level = 9.81, so the law's coefficients are the absolute ones. Raises InvalidParameter naming
the bad argument. Runs without the GIL.)doc");

  bind_int_enum<FeederRegime>(m, "FeederRegime",
                              "The regime the closed-form onsets give (feeder_regime_chart).",
                              {{"stick", FeederRegime::stick},
                               {"forward", FeederRegime::forward},
                               {"backward", FeederRegime::backward},
                               {"both", FeederRegime::both},
                               {"hopping", FeederRegime::hopping}});
  m.def(
      "feeder_regime_chart",
      [](const py::object& angles_in, const py::object& ks_in, double incline, double mu_static,
         double mu_kinetic, double g, double period, long long periods,
         long long steps_per_period, bool flight, Method method, double restitution, int threads,
         const py::object& progress_in) {
        const std::vector<double> angles = to_vector(angles_in, "vibration_angles"),
                                  ks = to_vector(ks_in, "machine_numbers");
        const PythonProgress progress(progress_in);
        FeederChartOptions o;
        o.incline = incline, o.mu_static = mu_static, o.mu_kinetic = mu_kinetic, o.g = g;
        o.period = period, o.periods = periods, o.steps_per_period = steps_per_period;
        o.flight = flight, o.threads = threads, o.progress = progress.callback();
        o.method = method, o.restitution = restitution;
        const std::vector<FeederChartCell> cells =
            progress.run([&] { return feeder_regime_chart(angles, ks, o); });
        const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(angles.size()),
                                             static_cast<py::ssize_t>(ks.size())};
        py::array_t<double> psi(shape), K(shape), gamma(shape), v(shape), speed(shape),
            stick(shape), flight_f(shape);
        py::array_t<std::int8_t> regime(shape), first(shape);
        py::array_t<bool> lifted(shape), failed(shape);
        for (std::size_t i = 0; i < cells.size(); ++i) {
          const FeederChartCell& c = cells[i];
          psi.mutable_data()[i] = c.vibration_angle, K.mutable_data()[i] = c.machine_number;
          gamma.mutable_data()[i] = c.throw_number;
          regime.mutable_data()[i] = static_cast<std::int8_t>(c.regime);
          first.mutable_data()[i] = static_cast<std::int8_t>(c.run.first_event);
          v.mutable_data()[i] = c.run.velocity, speed.mutable_data()[i] = c.dimensionless_speed;
          stick.mutable_data()[i] = c.run.stick_fraction;
          flight_f.mutable_data()[i] = c.run.flight_fraction;
          lifted.mutable_data()[i] = c.run.lifted_off, failed.mutable_data()[i] = !c.failure.empty();
        }
        py::dict d;
        d["vibration_angles"] = to_array(std::vector(angles));
        d["machine_numbers"] = to_array(std::vector(ks));
        d["vibration_angle"] = psi, d["machine_number"] = K, d["throw_number"] = gamma;
        d["regime"] = regime, d["first_event"] = first, d["velocity"] = v;
        d["dimensionless_speed"] = speed, d["stick_fraction"] = stick;
        d["flight_fraction"] = flight_f, d["lifted_off"] = lifted, d["failed"] = failed;
        return d;
      },
      py::arg("vibration_angles"), py::arg("machine_numbers"), py::kw_only(),
      py::arg("incline") = 0.0, py::arg("mu_static") = 0.5, py::arg("mu_kinetic") = 0.4,
      py::arg("g") = 1.0, py::arg("period") = 1.0, py::arg("periods") = 10,
      py::arg("steps_per_period") = 200, py::arg("flight") = true,
      py::arg("method") = Method::exact, py::arg("restitution") = 0.0, py::arg("threads") = 0,
      py::arg("progress") = py::none(), R"doc(
The feeder's regime chart (docs/feeder.md) over vibration angles [rad] x machine numbers K
(array-likes): per cell the closed-form regime (FeederRegime from feeder_onsets) and a run from
rest of `periods` periods (amplitude K g / w^2; the part at the friction level g, so the bound
is mu (g cos(incline) + z'')): by the exact feeder solver (method=Method.exact, the default) or
the contact core with Moreau-Jean flight and `steps_per_period` steps
(Method.time_stepping); landings with Newton's `restitution`. Returns a dict of NumPy arrays shaped (angles, machine numbers):
vibration_angle, machine_number, throw_number, regime (int8 FeederRegime), first_event (int8
FeederEvent), velocity (mean over the last period), dimensionless_speed (velocity /
(a0 w cos psi)), stick_fraction, flight_fraction, lifted_off, failed; and the two axes.
`progress(done, total)` as the other studies'; Ctrl-C stops it. Runs without the GIL.)doc");

  m.def(
      "design_feeder_drive",
      [](double target_speed, double period, double incline, double mu_static, double mu_kinetic,
         double g, double max_flight_angle, const py::object& angles_in, double k_max,
         int k_samples, double k_tolerance, long long periods, double restitution, int threads,
         const py::object& progress_in) {
        FeederDriveOptions o;
        o.target_speed = target_speed, o.period = period, o.incline = incline;
        o.mu_static = mu_static, o.mu_kinetic = mu_kinetic, o.g = g;
        o.max_flight_angle = max_flight_angle, o.k_max = k_max, o.k_samples = k_samples;
        o.k_tolerance = k_tolerance, o.periods = periods, o.restitution = restitution;
        o.threads = threads;
        if (!angles_in.is_none()) o.vibration_angles = to_vector(angles_in, "vibration_angles");
        const PythonProgress progress(progress_in);
        o.progress = progress.callback();
        const FeederDriveDesign d = progress.run([&] { return design_feeder_drive(o); });
        const auto one = [](const FeederDriveCandidate& c) {
          py::dict r;
          r["vibration_angle"] = c.vibration_angle, r["feasible"] = c.feasible;
          r["machine_number"] = c.machine_number, r["amplitude"] = c.amplitude;
          r["throw_number"] = c.throw_number, r["speed"] = c.speed;
          r["flight_angle"] = c.flight_angle;
          r["reason"] = c.reason.empty() ? py::object(py::none()) : py::str(c.reason);
          return r;
        };
        const auto n = static_cast<py::ssize_t>(d.candidates.size());
        py::array_t<double> psi(n), K(n), a0(n), gamma(n), v(n), flight(n);
        py::array_t<bool> ok(n);
        py::list reasons;
        for (py::ssize_t i = 0; i < n; ++i) {
          const FeederDriveCandidate& c = d.candidates[static_cast<std::size_t>(i)];
          psi.mutable_data()[i] = c.vibration_angle, K.mutable_data()[i] = c.machine_number;
          a0.mutable_data()[i] = c.amplitude, gamma.mutable_data()[i] = c.throw_number;
          v.mutable_data()[i] = c.speed, flight.mutable_data()[i] = c.flight_angle;
          ok.mutable_data()[i] = c.feasible;
          reasons.append(c.reason.empty() ? py::object(py::none()) : py::str(c.reason));
        }
        py::dict out;
        out["feasible"] = d.feasible;
        out["best"] = one(d.best);
        py::dict cands;
        cands["vibration_angle"] = psi, cands["feasible"] = ok, cands["machine_number"] = K;
        cands["amplitude"] = a0, cands["throw_number"] = gamma, cands["speed"] = v;
        cands["flight_angle"] = flight, cands["reason"] = reasons;
        out["candidates"] = cands;
        return out;
      },
      py::arg("target_speed"), py::kw_only(), py::arg("period") = 1.0, py::arg("incline") = 0.0,
      py::arg("mu_static") = 0.5, py::arg("mu_kinetic") = 0.4, py::arg("g") = 1.0,
      py::arg("max_flight_angle") = 0.0, py::arg("vibration_angles") = py::none(),
      py::arg("k_max") = 10.0, py::arg("k_samples") = 48, py::arg("k_tolerance") = 1e-10,
      py::arg("periods") = 20, py::arg("restitution") = 0.0, py::arg("threads") = 0,
      py::arg("progress") = py::none(), R"doc(
The least feeder drive for a target conveying speed (docs/feeder.md, "Choosing the drive"): at
the drive `period`, for each candidate vibration angle (default 0.1, 0.2, ..., 1.0 rad) the least
machine number K = a0 w^2 / g whose steady speed by the exact feeder solver (the last of
`periods` periods from rest) reaches `target_speed`, with no lift-off (max_flight_angle=0) or a
flight angle at most max_flight_angle [rad] per period. Returns a dict: feasible, best (the
candidate with the least K, a dict: vibration_angle, feasible, machine_number, amplitude,
throw_number, speed, flight_angle, reason) and candidates (NumPy arrays of the same per angle;
reason a list, None where feasible). An unreachable target is a result (feasible False, NaN),
not an error. In SI: g=9.81, period in s, target in m/s. Raises InvalidParameter naming the bad
option. Runs without the GIL; progress(done, total) per angle.)doc");
}

}  // namespace selfalign::python
