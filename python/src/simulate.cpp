// One run of either solver: ObjectState, Method, SimulationOptions, simulate() and its
// sampled trajectory as NumPy columns.
#include "selfalign/simulate/simulate.hpp"

#include <algorithm>

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

namespace {

void bind_object_state(py::module_& m) {
  py::class_<ObjectState> cls(m, "ObjectState", R"doc(
State of the object at one time [-]: x is its position relative to the table (its leading
edge, for the friction map), xd = x' its velocity relative to the table.)doc");
  cls
      .def(py::init([](double t, double x, double xd) {
             return ObjectState{t, x, xd};
           }),
           py::arg("t") = 0.0, py::arg("x") = 0.0, py::arg("xd") = 0.0)
      .def_readwrite("t", &ObjectState::t, "time [-]")
      .def_readwrite("x", &ObjectState::x, "position relative to the table [-]")
      .def_readwrite("xd", &ObjectState::xd, "relative velocity x' [-]")
      .def("__repr__", [](const ObjectState& s) {
        return Repr("ObjectState")("t", s.t)("x", s.x)("xd", s.xd).str();
      });
  def_record(cls, field("t", &ObjectState::t), field("x", &ObjectState::x),
             field("xd", &ObjectState::xd));
}

void bind_trajectory(py::module_& m) {
  py::class_<Trajectory> cls(m, "Trajectory", R"doc(
A sampled trajectory [-]: equal-length read-only NumPy columns t, x, xd, y, yd, ydd (float64)
and stick (bool). The arrays are views into the result (kept alive by it); copy them to modify.)doc");
  def_array(cls, "t", &Trajectory::t, "time [-]");
  def_array(cls, "x", &Trajectory::x, "object position relative to the table [-]");
  def_array(cls, "xd", &Trajectory::xd, "object velocity relative to the table x' [-]");
  def_array(cls, "y", &Trajectory::y, "table position y [-]");
  def_array(cls, "yd", &Trajectory::yd, "table velocity y' [-]");
  def_array(cls, "ydd", &Trajectory::ydd, "table acceleration y'' [-]");
  cls.def_property_readonly(
      "stick",
      [](const py::object& self) {
        return readonly_bool_view(self.cast<const Trajectory&>().stick, self);
      },
      "True where the object sticks (x' = 0, no slip)");
  cls.def("__len__", &Trajectory::size);
  cls.def("__repr__", [](const Trajectory& t) {
    return "<Trajectory: " + std::to_string(t.size()) + " samples>";
  });
  def_record(
      cls, field("t", &Trajectory::t), field("x", &Trajectory::x), field("xd", &Trajectory::xd),
      field("y", &Trajectory::y), field("yd", &Trajectory::yd), field("ydd", &Trajectory::ydd),
      field(
          "stick",
          [](const Trajectory& t) {
            py::array_t<bool> stick(static_cast<py::ssize_t>(t.stick.size()));
            std::copy(t.stick.begin(), t.stick.end(), stick.mutable_data());
            return stick;
          },
          [](Trajectory& t, const py::array_t<bool, py::array::forcecast>& stick) {
            t.stick.assign(stick.data(), stick.data() + stick.size());
          }));
  cls.def(
      "as_dict",
      [](const py::object& self) {
        py::dict d;
        for (const char* c : {"t", "x", "xd", "y", "yd", "ydd", "stick"}) d[c] = self.attr(c);
        return d;
      },
      "The columns as a dict name -> array (e.g. for numpy.savetxt or pandas.DataFrame).");
}

void bind_method(py::module_& m) {
  py::enum_<Method> method(m, "Method",
                           "Solver choice; also accepted as the strings 'exact', "
                           "'time-stepping' and 'integrator'.");
  method
      .value("exact", Method::exact,
             "event-driven closed form: piecewise-constant y'', piecewise-affine m(x)")
      .value("time_stepping", Method::time_stepping,
             "Moreau time-stepping (Sect. 4.1): any profile and friction map")
      .value("integrator", Method::integrator,
             "exact sticks, slips by Dormand-Prince with event location (speed-dependent laws)")
      .def(py::init(&parse_method), py::arg("text"));
  refuse_unknown_values(method, "Method", 3);
  py::implicitly_convertible<py::str, Method>();
}

void bind_integrator(py::module_& m) {
  const IntegratorOptions d;
  py::class_<IntegratorOptions> options(
      m, "IntegratorOptions",
      "Tolerances of the slip integrator (Odeint's dense-output Dormand-Prince 5(4): per step "
      "|err| <= abs + rel (|x| + dt |x'|)).");
  options
      .def(py::init([](double relative_tolerance, double absolute_tolerance,
                       double max_steps_per_period) {
             IntegratorOptions o{relative_tolerance, absolute_tolerance, max_steps_per_period};
             validate(o);
             return o;
           }),
           py::kw_only(), py::arg("relative_tolerance") = d.relative_tolerance,
           py::arg("absolute_tolerance") = d.absolute_tolerance,
           py::arg("max_steps_per_period") = d.max_steps_per_period,
           "Tolerances in (0, 1); max_steps_per_period, the work budget, in [1, 1e9]: Runge-Kutta "
           "step attempts (and stick/slip intervals) per table period of a call. Raises "
           "InvalidParameter naming the parameter otherwise. A run that needs more steps (a stiff "
           "slip: a large viscous rate or a steep Stribeck curve; unreachable tolerances) raises "
           "InvalidParameter naming viscous, stribeck_velocity or relative_tolerance.")
      .def_readwrite("relative_tolerance", &IntegratorOptions::relative_tolerance, "in (0, 1)")
      .def_readwrite("absolute_tolerance", &IntegratorOptions::absolute_tolerance,
                     "in (0, 1) [-]")
      .def_readwrite("max_steps_per_period", &IntegratorOptions::max_steps_per_period,
                     "work budget per table period, in [1, 1e9]")
      .def("__repr__", [](const IntegratorOptions& o) {
        return Repr("IntegratorOptions")("relative_tolerance", o.relative_tolerance)(
                   "absolute_tolerance", o.absolute_tolerance)(
                   "max_steps_per_period", o.max_steps_per_period)
            .str();
      });
  def_record(options, field("relative_tolerance", &IntegratorOptions::relative_tolerance),
             field("absolute_tolerance", &IntegratorOptions::absolute_tolerance),
             field("max_steps_per_period", &IntegratorOptions::max_steps_per_period));

  using S = IntegratorStatistics;
  py::class_<S> statistics(m, "IntegratorStatistics",
                           "What the slip integrator did (zeros for other methods).");
  statistics
      .def_readonly("steps", &IntegratorStatistics::steps, "accepted Runge-Kutta steps")
      .def_readonly("rejected", &IntegratorStatistics::rejected, "rejected (retried) steps")
      .def_readonly("rhs_evaluations", &IntegratorStatistics::rhs_evaluations,
                    "right-hand-side evaluations")
      .def_readonly("events", &IntegratorStatistics::events,
                    "located events: x' = 0, friction boundaries, stick breaks")
      .def_readonly("slips", &IntegratorStatistics::slips, "slip intervals integrated")
      .def_readonly("sticks", &IntegratorStatistics::sticks, "stick intervals held exactly")
      .def_readonly("pivots", &IntegratorStatistics::pivots,
                    "pivots (the planar patch integrator only)")
      .def("__repr__", [](const IntegratorStatistics& s) {
        return Repr("IntegratorStatistics")("steps", s.steps)("rejected", s.rejected)(
                   "rhs_evaluations", s.rhs_evaluations)("events", s.events)
            .str();
      });
  def_record(statistics, field("steps", &S::steps), field("rejected", &S::rejected),
             field("rhs_evaluations", &S::rhs_evaluations), field("events", &S::events),
             field("slips", &S::slips), field("sticks", &S::sticks), field("pivots", &S::pivots));
}

void bind_simulation_options(py::module_& m) {
  const SimulationOptions d;
  using O = SimulationOptions;
  py::class_<O> cls(m, "SimulationOptions", "Options of simulate().");
  cls
      .def(py::init([](Method method, double duration, double step, double theta,
                       double output_step, bool record, const IntegratorOptions& integrator) {
             SimulationOptions o;
             o.integrator = integrator;
             o.method = method;
             o.duration = duration;
             o.step = step;
             o.theta = theta;
             o.output_step = output_step;
             o.record = record;
             return o;
           }),
           py::kw_only(), py::arg("method") = d.method, py::arg("duration") = d.duration,
           py::arg("step") = d.step, py::arg("theta") = d.theta,
           py::arg("output_step") = d.output_step, py::arg("record") = d.record,
           py::arg("integrator") = d.integrator)
      .def_readwrite("method", &SimulationOptions::method,
                     "Method.exact, Method.time_stepping or Method.integrator (exact under a "
                     "speed-dependent law runs the integrator)")
      .def_readwrite("integrator", &SimulationOptions::integrator,
                     "IntegratorOptions: the slip integrator's tolerances")
      .def_readwrite("duration", &SimulationOptions::duration, "simulated time after t0 [-], > 0")
      .def_readwrite("step", &SimulationOptions::step,
                     "time-stepping step h [-], > 0 (unused by the exact solver)")
      .def_readwrite("theta", &SimulationOptions::theta, "time-stepping theta, in [0, 1]")
      .def_readwrite("output_step", &SimulationOptions::output_step,
                     "spacing of recorded samples [-]; 0: h (time-stepping) or Δt/200 (exact)")
      .def_readwrite("record", &SimulationOptions::record,
                     "False: only the summary (empty trajectory)")
      .def("__repr__", [](const SimulationOptions& o) {
        return Repr("SimulationOptions")
            .raw("method", enum_name(o.method))("duration", o.duration)("step", o.step)(
                "theta", o.theta)("output_step", o.output_step)("record", o.record)
            .str();
      });
  def_record(cls, field("method", &O::method), field("duration", &O::duration),
             field("step", &O::step), field("theta", &O::theta),
             field("output_step", &O::output_step), field("record", &O::record),
             field("integrator", &O::integrator));
}

}  // namespace

void bind_simulate(py::module_& m) {
  bind_object_state(m);
  bind_trajectory(m);
  bind_method(m);
  bind_integrator(m);
  bind_simulation_options(m);

  using R = SimulationResult;
  py::class_<R> result(m, "SimulationResult", "The outcome of simulate().");
  result
      .def_readonly("trajectory", &SimulationResult::trajectory,
                    "samples at t0 + j*output_step and at the end time (NumPy columns)")
      .def_readonly("final_state", &SimulationResult::final_state, "state at t0 + duration [-]")
      .def_readonly("method", &SimulationResult::method, "the solver that produced the result")
      .def_readonly("integrator", &SimulationResult::integrator,
                    "IntegratorStatistics of the slip integrator (zeros for other methods)")
      .def_readonly("work", &SimulationResult::work,
                    "arcs (exact, integrator) or steps (time-stepping) computed")
      .def_readonly("mean_velocity_last_period", &SimulationResult::mean_velocity_last_period,
                    "(x(t_end) - x(t_end - Δt))/Δt [-]; NaN if the run is shorter than a period")
      .def_readonly("stick_fraction", &SimulationResult::stick_fraction,
                    "fraction of recorded samples in stick [-]")
      .def("__repr__", [](const SimulationResult& r) {
        return Repr("SimulationResult")
            .raw("final_state", py::repr(py::cast(r.final_state)))(
                "samples", static_cast<long long>(r.trajectory.size()))(
                "work", static_cast<long long>(r.work))(
                "mean_velocity_last_period", r.mean_velocity_last_period)("stick_fraction",
                                                                          r.stick_fraction)
            .str();
      });
  def_record(result, field("trajectory", &R::trajectory), field("final_state", &R::final_state),
             field("method", &R::method), field("integrator", &R::integrator),
             field("work", &R::work),
             field("mean_velocity_last_period", &R::mean_velocity_last_period),
             field("stick_fraction", &R::stick_fraction));

  m.def(
      "simulate",
      [](const TableProfile& profile, const FrictionMap& friction, const ObjectState& initial,
         const SimulationOptions& options, const FrictionLaw& law) {
        return simulate(profile, friction, law, initial, options);
      },
      py::arg("profile"), py::arg("friction"), py::arg("initial") = ObjectState{},
      py::arg("options") = SimulationOptions{}, py::kw_only(), py::arg("law") = FrictionLaw{},
      py::call_guard<py::gil_scoped_release>(), R"doc(
Simulates eq. (6), -Sign(x') ∋ x'' + y'', with friction level m(x) from `initial` over
options.duration, with the exact event-driven solver or Moreau time-stepping, under the
friction law `law` (FrictionLaw: static >= kinetic, optionally direction-dependent kinetic;
the paper's law by default). Raises InvalidParameter on bad options, or when Method.exact is
asked of a profile that is not piecewise constant or piecewise linear in acceleration, or a
friction map that is not piecewise affine. Runs without the GIL.)doc");
}

}  // namespace selfalign::python
