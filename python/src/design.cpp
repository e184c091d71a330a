// selfalign design: from SI actuator limits to a recommended three-phase profile.
#include "selfalign/design/process_design.hpp"

#include <pybind11/stl.h>

#include <limits>
#include <optional>

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "selfalign/design/actuator_samples.hpp"

#include "arguments.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

void bind_design(py::module_& m) {
  const DesignRequest d;
  py::class_<DesignRequest> request(m, "DesignRequest", R"doc(
A design request in SI units (design_process): the object (mass [kg], width [m], mu [-],
c_mu [-], g [m/s^2]), the distance to travel [m], the actuator limits (stroke_max [m],
frequency_min/frequency_max [Hz], velocity_max [m/s], acceleration_max [m/s^2]), the
positioning requirement (tolerance [m]; 0 requires accumulation, Δx_d = 0) and the search
resolution (acceleration_grid, period_grid, stroke_grid, entries).)doc");
  // One constructor only: pybind11 retries an overloaded function with conversions (int ->
  // float) only for positional arguments, so a second overload would refuse mass=1.
  request.def(py::init([](double mass, double width, double mu, double c_mu, double gravity,
                       double distance, double stroke_max, double frequency_min,
                       double frequency_max, double velocity_max, double acceleration_max,
                       double tolerance, int acceleration_grid, int period_grid, int stroke_grid,
                       int entries, double jerk_max, std::optional<double> mu_static,
                       std::optional<double> mu_backward) {
             DesignRequest q;
             q.mass = mass, q.width = width, q.mu = mu, q.c_mu = c_mu, q.gravity = gravity;
             q.distance = distance, q.stroke_max = stroke_max;
             q.frequency_min = frequency_min, q.frequency_max = frequency_max;
             q.velocity_max = velocity_max, q.acceleration_max = acceleration_max;
             q.tolerance = tolerance, q.acceleration_grid = acceleration_grid;
             q.period_grid = period_grid, q.stroke_grid = stroke_grid, q.entries = entries;
             q.jerk_max = jerk_max, q.mu_static = mu_static, q.mu_backward = mu_backward;
             return q;
           }),
           py::kw_only(), py::arg("mass") = d.mass, py::arg("width") = d.width,
           py::arg("mu") = d.mu, py::arg("c_mu") = d.c_mu, py::arg("gravity") = d.gravity,
           py::arg("distance") = d.distance, py::arg("stroke_max") = d.stroke_max,
           py::arg("frequency_min") = d.frequency_min, py::arg("frequency_max") = d.frequency_max,
           py::arg("velocity_max") = d.velocity_max,
           py::arg("acceleration_max") = d.acceleration_max, py::arg("tolerance") = d.tolerance,
           py::arg("acceleration_grid") = d.acceleration_grid,
           py::arg("period_grid") = d.period_grid, py::arg("stroke_grid") = d.stroke_grid,
           py::arg("entries") = d.entries, py::arg("jerk_max") = d.jerk_max,
           py::arg("mu_static") = py::none(), py::arg("mu_backward") = py::none())
      .def_readwrite("jerk_max", &DesignRequest::jerk_max,
                     "table jerk limit [m/s^3] (inf: jump accelerations)")
      .def_readwrite("mu_static", &DesignRequest::mu_static,
                     "static friction coefficient [-], absolute like mu, >= mu (None: equal to "
                     "mu; NaN is refused)")
      .def_readwrite("mu_backward", &DesignRequest::mu_backward,
                     "kinetic coefficient of backward slip [-], absolute like mu (None: equal "
                     "to mu; NaN is refused)")
      .def_readwrite("mass", &DesignRequest::mass, "object mass [kg]")
      .def_readwrite("width", &DesignRequest::width, "object width [m]")
      .def_readwrite("mu", &DesignRequest::mu, "low-friction coefficient mu_1 [-]")
      .def_readwrite("c_mu", &DesignRequest::c_mu, "mu_2/mu_1 [-]")
      .def_readwrite("gravity", &DesignRequest::gravity, "g [m/s^2]")
      .def_readwrite("distance", &DesignRequest::distance, "end position from the start [m]")
      .def_readwrite("stroke_max", &DesignRequest::stroke_max, "stroke limit [m]")
      .def_readwrite("frequency_min", &DesignRequest::frequency_min, "[Hz]")
      .def_readwrite("frequency_max", &DesignRequest::frequency_max, "[Hz]")
      .def_readwrite("velocity_max", &DesignRequest::velocity_max, "|y'| limit [m/s]")
      .def_readwrite("acceleration_max", &DesignRequest::acceleration_max, "|y''| limit [m/s^2]")
      .def_readwrite("tolerance", &DesignRequest::tolerance, "allowed Δx_d [m]; 0: accumulation")
      .def_readwrite("acceleration_grid", &DesignRequest::acceleration_grid, "per axis, >= 2")
      .def_readwrite("period_grid", &DesignRequest::period_grid, "candidate periods, >= 1")
      .def_readwrite("stroke_grid", &DesignRequest::stroke_grid, "candidate strokes, >= 1")
      .def_readwrite("entries", &DesignRequest::entries, "steady entries per candidate, >= 2");

  using Q = DesignRequest;
  def_record(request, field("mass", &Q::mass), field("width", &Q::width), field("mu", &Q::mu),
             field("c_mu", &Q::c_mu), field("gravity", &Q::gravity),
             field("distance", &Q::distance), field("stroke_max", &Q::stroke_max),
             field("frequency_min", &Q::frequency_min), field("frequency_max", &Q::frequency_max),
             field("velocity_max", &Q::velocity_max),
             field("acceleration_max", &Q::acceleration_max), field("jerk_max", &Q::jerk_max),
             field("mu_static", &Q::mu_static), field("mu_backward", &Q::mu_backward),
             field("tolerance", &Q::tolerance), field("acceleration_grid", &Q::acceleration_grid),
             field("period_grid", &Q::period_grid), field("stroke_grid", &Q::stroke_grid),
             field("entries", &Q::entries));
  request.def("__repr__", [](const DesignRequest& q) {
    return Repr("DesignRequest")("mass", q.mass)("width", q.width)("mu", q.mu)("c_mu", q.c_mu)(
               "distance", q.distance)("tolerance", q.tolerance)("stroke_max", q.stroke_max)(
               "frequency_max", q.frequency_max)("acceleration_max", q.acceleration_max)
        .str();
  });

  py::class_<DesignResult> result(m, "DesignResult", R"doc(
The recommended three-phase profile (SI: period [s], stroke [m], a2/a3 [m/s^2], t1..t3 [s],
y_ini [m], y_dot_ini and velocity_peak [m/s]), its motion case, and the predictions: v_bar
[m/s], x_mu (where the high-friction region starts) [m], end_position and error_band [m],
process_time T_p [s], stop kind, and the limits it sits on. feasible = False with a message
naming the binding limit;
its numbers are then NaN (absent, never 0).)doc");
  result.def_readonly("feasible", &DesignResult::feasible, "a design was found")
      .def_readonly("message", &DesignResult::message, "why not, naming the binding limit")
      .def_readonly("period", &DesignResult::period, "Δt [s]")
      .def_readonly("stroke", &DesignResult::stroke, "Δy [m]")
      .def_readonly("a2", &DesignResult::a2, "y2'' [m/s^2]")
      .def_readonly("a3", &DesignResult::a3, "y3'' [m/s^2]")
      .def_readonly("t1", &DesignResult::t1, "[s]")
      .def_readonly("t2", &DesignResult::t2, "[s]")
      .def_readonly("t3", &DesignResult::t3, "[s]")
      .def_readonly("y_ini", &DesignResult::y_ini, "[m]")
      .def_readonly("y_dot_ini", &DesignResult::y_dot_ini, "[m/s]")
      .def_readonly("velocity_peak", &DesignResult::velocity_peak, "max |y'| [m/s]")
      .def_readonly("motion_case", &DesignResult::motion_case, "Table 1 case")
      .def_readonly("v_bar", &DesignResult::v_bar, "steady average velocity [m/s]")
      .def_readonly("x_mu", &DesignResult::x_mu, "start of the high-friction region [m]")
      .def_readonly("end_position", &DesignResult::end_position, "predicted end position [m]")
      .def_readonly("error_band", &DesignResult::error_band, "half-width of the band [m]")
      .def_readonly("process_time", &DesignResult::process_time, "T_p [s]")
      .def_readonly("stop", &DesignResult::stop, "how the object stops")
      .def_readonly("candidates", &DesignResult::candidates, "profiles examined")
      .def_readonly("feasible_candidates", &DesignResult::feasible_candidates,
                    "profiles meeting the requirement")
      .def_readonly("limits", &DesignResult::limits,
                    "the request limits the profile sits on, e.g. 'frequency at frequency_min "
                    "= 5 Hz (the default)'; empty inside the grid")
      .def_readonly("dimensionless", &DesignResult::dimensionless,
                    "the profile in model units (L = width)")
      .def_readonly("x_mu_dimensionless", &DesignResult::x_mu_dimensionless, "x_mu [-]")
      .def_readonly("jerk", &DesignResult::jerk, "jerk limit [m/s^3] (inf: jump accelerations)")
      .def_readonly("jerk_dimensionless", &DesignResult::jerk_dimensionless, "[-]");
  using R = DesignResult;
  def_record(result, field("feasible", &R::feasible), field("message", &R::message),
             field("period", &R::period), field("stroke", &R::stroke), field("a2", &R::a2),
             field("a3", &R::a3), field("t1", &R::t1), field("t2", &R::t2), field("t3", &R::t3),
             field("y_ini", &R::y_ini), field("y_dot_ini", &R::y_dot_ini),
             field("velocity_peak", &R::velocity_peak), field("motion_case", &R::motion_case),
             field("v_bar", &R::v_bar), field("x_mu", &R::x_mu),
             field("end_position", &R::end_position), field("error_band", &R::error_band),
             field("process_time", &R::process_time), field("stop", &R::stop),
             field("candidates", &R::candidates),
             field("feasible_candidates", &R::feasible_candidates),
             field("limits", &R::limits), field("dimensionless", &R::dimensionless), field("jerk", &R::jerk),
             field("jerk_dimensionless", &R::jerk_dimensionless),
             field("x_mu_dimensionless", &R::x_mu_dimensionless));
  result.def("__repr__", [](const DesignResult& r) {
    return Repr("DesignResult")("feasible", r.feasible)("period", r.period)("stroke", r.stroke)(
               "a2", r.a2)("a3", r.a3)("x_mu", r.x_mu)("end_position", r.end_position)(
               "process_time", r.process_time)
        .str();
  });

  m.def(
      "actuator_samples",
      [](const DesignRequest& q, const DesignResult& d, double sample_rate,
         const py::object& moving_mass) {
        ActuatorSamples s = actuator_samples(
            q, d, sample_rate,
            moving_mass.is_none()
                ? std::numeric_limits<double>::quiet_NaN()
                : argument<double>(moving_mass, "moving_mass", "a float [kg] or None"));
        py::dict out;
        out["t_s"] = to_array(std::move(s.t));
        out["y_m"] = to_array(std::move(s.y));
        out["y_dot_m_per_s"] = to_array(std::move(s.y_dot));
        out["y_ddot_m_per_s2"] = to_array(std::move(s.y_ddot));
        out["y_dddot_m_per_s3"] = to_array(std::move(s.y_dddot));
        out["force_n"] = s.force.empty() ? py::object(py::none()) : py::object(to_array(std::move(s.force)));
        out["sample_rate_hz"] = s.sample_rate;
        out["requested_sample_rate_hz"] = s.requested_rate;
        out["samples_per_period"] = s.samples_per_period;
        return out;
      },
      py::arg("request"), py::arg("design"), py::arg("sample_rate"), py::kw_only(),
      py::arg("moving_mass") = py::none(), R"doc(
One period of a feasible design's profile for a motion controller, SI: a dict with 't_s',
'y_m', 'y_dot_m_per_s', 'y_ddot_m_per_s2', 'y_dddot_m_per_s3' (float64 arrays; jerk 0 on a
jump profile's plateaus, +-jerk on the ramps), 'force_n' (moving_mass x y'' [N], None without a
moving mass), 'sample_rate_hz' (n / period: the rate adjusted so that one period is n =
round(period x sample_rate) samples, t_i = i period / n, no repeated endpoint: it loops
seamlessly), 'requested_sample_rate_hz', 'samples_per_period'.)doc");

  m.def(
      "design_process",
      [](const DesignRequest& request, int threads, const py::object& progress_in) {
        const PythonProgress progress(progress_in);
        const SweepOptions sweep = sweep_options(threads, progress);
        return progress.run([&] { return design_process(request, sweep); });
      },
      py::arg("request"), py::kw_only(), py::arg("threads") = 0,
      py::arg("progress") = py::none(),
      R"doc(Recommend the three-phase profile minimising the process time T_p subject to
accumulation (tolerance = 0) or the tolerance, within the actuator limits (SI in and out).
Returns a DesignResult; an infeasible request has feasible = False and a message.)doc");
}

}  // namespace selfalign::python
