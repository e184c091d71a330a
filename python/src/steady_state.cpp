// Motion cases (Table 1, Sect. 5.1) and the steady state on the uniform table (Sect. 4.3, 5.1,
// 6.2): v̄ (eq. 10) and the objective f (eq. 11).
#include "selfalign/analysis/steady_state.hpp"

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/three_phase_steady_state.hpp"

namespace selfalign::python {

namespace {

void bind_cases(py::module_& m) {
  bind_int_enum<StickSlipCase>(m, "StickSlipCase", R"doc(
The motion cases of Table 1 (Sect. 5.1) plus the non-physical case 0.

An enum.IntEnum: a member equals the paper's case number (StickSlipCase.slip_slip == 4), and
the case arrays of the sweeps hold these ints (StickSlipCase(a[i, j]) names one).
  non_physical        = 0  no three-phase profile with this stroke exists
  stick_slip_forward  = 1  stick-slip with x' >= 0 (desirable)
  stick_slip_backward = 2  stick-slip with x' <= 0 (undesirable)
  general_stick_slip  = 3  stick-slip in both directions
  slip_slip           = 4  never sticks
  pure_stick          = 5  no relative motion)doc",
                               {{"non_physical", StickSlipCase::non_physical},
                                {"stick_slip_forward", StickSlipCase::stick_slip_forward},
                                {"stick_slip_backward", StickSlipCase::stick_slip_backward},
                                {"general_stick_slip", StickSlipCase::general_stick_slip},
                                {"slip_slip", StickSlipCase::slip_slip},
                                {"pure_stick", StickSlipCase::pure_stick}});

  m.def("describe", &describe, py::arg("case"),
        "Table 1's description of a case, e.g. \"stick-slip x' >= 0\".");
  m.def("predict_case", py::overload_cast<const ThreePhaseParameters&>(&predict_case),
        py::arg("parameters"), R"doc(
A priori case of the three-phase profile (the rules of the paper's flow chart, Fig. 8,
derived in docs/motion-cases.md). With a = a2, b = a3 and T1 = t1, T2 = t2 - t1, T3 = t3 - t2:
  not physical -> 0;  a <= 1, b <= 1 -> 5;  a > 1, b <= 1 -> 1;  a <= 1, b > 1 -> 2;
  a > 1, b > 1: with the object at rest at t1 it stops in [t2, t3] after
  tau_s = (a - 1) T2 / (1 + b) and slides back to x'(t3) = -(b - 1)(T3 - tau_s);
  |x'(t3)| < T1 -> 3, otherwise -> 4.
Raises InvalidParameter on non-positive or NaN parameters.)doc");
}

void bind_steady_options(py::module_& m) {
  const SteadyStateOptions d;
  using O = SteadyStateOptions;
  py::class_<O> cls(m, "SteadyStateOptions", "Options of steady_state().");
  cls
      .def(py::init([](int max_periods, double velocity_tol, int steps_per_period, double theta,
                       double stepping_tol, const IntegratorOptions& integrator,
                       double initial_velocity, double initial_slope) {
             SteadyStateOptions o;
             o.initial_slope = initial_slope;
             o.integrator = integrator;
             o.initial_velocity = initial_velocity;
             o.max_periods = max_periods;
             o.velocity_tol = velocity_tol;
             o.steps_per_period = steps_per_period;
             o.theta = theta;
             o.stepping_tol = stepping_tol;
             return o;
           }),
           py::kw_only(), py::arg("max_periods") = d.max_periods,
           py::arg("velocity_tol") = d.velocity_tol,
           py::arg("steps_per_period") = d.steps_per_period, py::arg("theta") = d.theta,
           py::arg("stepping_tol") = d.stepping_tol, py::arg("integrator") = d.integrator,
           py::arg("initial_velocity") = d.initial_velocity,
           py::arg("initial_slope") = d.initial_slope)
      .def_readwrite("initial_slope", &SteadyStateOptions::initial_slope,
                     "g'(v) = lambda - 1 of a nearby profile's map (its SteadyState.slope), < 0; "
                     "NaN: unknown. With initial_velocity the first step is a secant step")
      .def_readwrite("initial_velocity", &SteadyStateOptions::initial_velocity,
                     "x'_0 of the search's first period [-] (0: from rest); a nearby profile's "
                     "x'_0s saves periods")
      .def_readwrite("integrator", &SteadyStateOptions::integrator,
                     "IntegratorOptions (speed-dependent laws); velocity_tol is then at least 10 "
                     "relative_tolerance")
      .def_readwrite("max_periods", &SteadyStateOptions::max_periods,
                     "periods simulated at most before giving up (>= 2)")
      .def_readwrite("velocity_tol", &SteadyStateOptions::velocity_tol,
                     "estimated error |x'_0s - v*| = |P(v) - v| / (1 - λ) accepted as steady, "
                     "relative to 1 + |v| [-] (exact solver)")
      .def_readwrite("steps_per_period", &SteadyStateOptions::steps_per_period,
                     "time-stepping (profiles the exact solver cannot take): h = Δt / this")
      .def_readwrite("theta", &SteadyStateOptions::theta, "time-stepping theta")
      .def_readwrite("stepping_tol", &SteadyStateOptions::stepping_tol,
                     "time-stepping: velocity_tol's role [-]; 0: 10 h")
      .def("__repr__", [](const SteadyStateOptions& o) {
        return Repr("SteadyStateOptions")("max_periods", o.max_periods)(
                   "velocity_tol", o.velocity_tol)("steps_per_period", o.steps_per_period)(
                   "theta", o.theta)("stepping_tol", o.stepping_tol)
            .str();
      });
  def_record(cls, field("max_periods", &O::max_periods), field("velocity_tol", &O::velocity_tol),
             field("steps_per_period", &O::steps_per_period), field("theta", &O::theta),
             field("stepping_tol", &O::stepping_tol), field("integrator", &O::integrator),
             field("initial_velocity", &O::initial_velocity),
             field("initial_slope", &O::initial_slope));
}

}  // namespace

void bind_steady_state(py::module_& m) {
  bind_cases(m);
  bind_steady_options(m);

  using S = SteadyState;
  py::class_<S> cls(m, "SteadyState", "The periodic velocity response on the uniform table.");
  cls
      .def_readonly("converged", &SteadyState::converged,
                    "False: max_periods reached (the fields hold the last iterate)")
      .def_readonly("method", &SteadyState::method, "the solver used")
      .def_readonly("x_dot_0s", &SteadyState::x_dot_0s,
                    "steady-state x' at the profile's t0 (phase 0) [-]")
      .def_readonly("x_dot_0s_error", &SteadyState::x_dot_0s_error,
                    "estimated |x'_0s - v*|: the residual |P(v) - v| (at least the period "
                    "map's rounding) over 1 - λ, λ the map's secant slope [-]; inf when not "
                    "converged")
      .def_readonly("phase", &SteadyState::phase,
                    "phase of the steady-state initial condition in [0, Δt) [-]")
      .def_readonly("v_bar", &SteadyState::v_bar,
                    "average velocity over a steady period, eq. (10) [-]")
      .def_readonly("f", &SteadyState::f, "objective of eq. (11) [-]; +inf when v̄ = 0")
      .def_readonly("displacement", &SteadyState::displacement,
                    "x(t0 + Δt) - x(t0) over a steady period [-]")
      .def_readonly("periods", &SteadyState::periods, "periods simulated to find it")
      .def_readonly("motion_case", &SteadyState::motion_case,
                    "a posteriori Table 1 case of the steady period")
      .def_readonly("pattern", &SteadyState::pattern,
                    "the steady period's stick/slip sequence, e.g. 'stick,forward,backward'")
      .def_readonly("slope", &SteadyState::slope,
                    "the search's last estimate of g'(v) = lambda - 1 at the fixed point; NaN "
                    "when none was measured")
      .def_readonly("integrator", &SteadyState::integrator,
                    "IntegratorStatistics of the slip integrator (zeros for other methods)")
      .def("__repr__", [](const SteadyState& s) {
        return Repr("SteadyState")("converged", s.converged)("x_dot_0s", s.x_dot_0s)(
                   "v_bar", s.v_bar)("f", s.f)
            .raw("motion_case", enum_name(s.motion_case))("periods", s.periods)
            .str();
      });
  def_record(cls, field("converged", &S::converged), field("method", &S::method),
             field("x_dot_0s", &S::x_dot_0s), field("x_dot_0s_error", &S::x_dot_0s_error),
             field("phase", &S::phase), field("v_bar", &S::v_bar), field("f", &S::f),
             field("displacement", &S::displacement), field("periods", &S::periods),
             field("motion_case", &S::motion_case), field("pattern", &S::pattern),
             field("slope", &S::slope), field("integrator", &S::integrator));

  m.def("steady_state",
        py::overload_cast<const TableProfile&, const SteadyStateOptions&>(&steady_state), py::arg("profile"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>());
  m.def("steady_state",
        py::overload_cast<const TableProfile&, const FrictionLaw&, const SteadyStateOptions&>(
            &steady_state),
        py::arg("profile"), py::arg("law") = FrictionLaw{},
        py::arg("options") = SteadyStateOptions{}, py::call_guard<py::gil_scoped_release>(),
        R"doc(
Steady state on the uniform table (friction bound 1): the unique periodic velocity response
(Sect. 6.2), found by iterating the period map P(v) = x'(t0 + Δt) and secant steps on
P(v) - v, stopped on the estimated error |P(v) - v| / (1 - λ) (x_dot_0s_error), not on the
residual; its average velocity v̄ (eq. 10), objective f (eq. 11) and a posteriori case.
law: the friction law (FrictionLaw: static >= kinetic, optionally direction-dependent
kinetic coefficients); the paper's static = kinetic = 1 by default.
Exact solver where the table acceleration is piecewise polynomial (constant or finite jerk),
time-stepping otherwise. Raises InvalidParameter on bad options. Runs without the GIL.)doc");

  using T = ThreePhaseSteadyState;
  py::class_<T> tcls(m, "ThreePhaseSteadyState",
                     "The closed-form steady state of one three-phase profile "
                     "(three_phase_steady_state).");
  tcls.def_readonly("motion_case", &T::motion_case,
                    "Table 1 case of the steady period (0: the profile does not exist)")
      .def_readonly("x_dot_0s", &T::x_dot_0s, "steady-state x' at t0 [-]; NaN for case 0")
      .def_readonly("displacement", &T::displacement,
                    "x(t0 + Δt) - x(t0) over a steady period [-]; NaN for case 0")
      .def_readonly("v_bar", &T::v_bar, "eq. (10) [-]; NaN for case 0")
      .def_readonly("f", &T::f, "eq. (11) [-]; +inf for v̄ = 0, NaN for case 0")
      .def_readonly("slope", &T::slope,
                    "dP/dv at the fixed point: 0 where it sticks, c4 of eq. (32) in slip-slip; "
                    "NaN for case 0")
      .def("__repr__", [](const T& s) {
        return Repr("ThreePhaseSteadyState")
            .raw("motion_case", enum_name(s.motion_case))("x_dot_0s", s.x_dot_0s)(
                "v_bar", s.v_bar)("f", s.f)("slope", s.slope)
            .str();
      });
  def_record(tcls, field("motion_case", &T::motion_case), field("x_dot_0s", &T::x_dot_0s),
             field("displacement", &T::displacement), field("v_bar", &T::v_bar),
             field("f", &T::f), field("slope", &T::slope));
  m.def("three_phase_steady_state",
        py::overload_cast<const ThreePhaseParameters&, const FrictionLaw&>(
            &three_phase_steady_state),
        py::arg("parameters"), py::arg("law") = FrictionLaw{}, R"doc(
The steady state of the three-phase profile (jump accelerations) in closed form, every case
of Table 1 (docs/three-phase-steady-state.md; eqs. (12)-(24) for case 1): no period is
simulated. law: a Coulomb FrictionLaw (static >= kinetic, direction-dependent kinetic
coefficients allowed); the paper's by default. Returns a ThreePhaseSteadyState; a profile
that does not exist is case 0 with NaN numbers. Raises InvalidParameter on bad parameters or
a velocity-dependent law (named "law").)doc");

  m.attr("OBJECTIVE_SCALE") = kObjectiveScale;
  m.def(
      "objective_f",
      [](const py::object& v_bar, double c) {
        return map_elementwise<double>(v_bar, [c](double v) { return objective_f(v, c); },
                                       "v_bar");
      },
      py::arg("v_bar"), py::arg("c") = kObjectiveScale,
      "Objective f = 1/(c v̄^2) of eq. (11) (float or ndarray); +inf where v̄ = 0.");
}

}  // namespace selfalign::python
