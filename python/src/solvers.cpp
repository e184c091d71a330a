// The two solvers one step below simulate(): the exact event-driven solver (its arcs, eqs.
// 12-24 and 42-47) and Moreau time-stepping (Sect. 4.1), each with an explicit state; and the
// period map every analysis iterates (PeriodMap: either solver over one table period).
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <variant>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "selfalign/special_values.hpp"
#include "bindings.hpp"
#include "selfalign/simulate/stick_slip_decision.hpp"
#include "selfalign/overloaded.hpp"
#include "matrix.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/period_map.hpp"
#include "selfalign/error.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign::python {

namespace {

// The exact solver's setup borrowed from a profile and a friction map.
ExactSetup exact_setup(const TableProfile& profile, const FrictionMap& friction) {
  const PiecewisePolynomialProfile* p = profile.piecewise_polynomial();
  if (!p)
    throw InvalidParameter("profile", profile.kind(),
                           "the exact solver needs a piecewise-constant or piecewise-linear table acceleration");
  const PiecewiseAffineFriction* f = friction.piecewise_affine();
  if (!f)
    throw InvalidParameter("friction", "not piecewise affine",
                           "the exact solver needs a piecewise-affine friction map");
  return {*p, *f};
}

// Columns of an arc's shape (NaN where the shape has no such parameter): parabolic/cubic x''
// at the start, harmonic/hyperbolic omega and centre.
double arc_alpha(const Arc& a) {
  return std::visit(Overloaded{[](const PolynomialArc& p) { return p.accel; },
                               [](const StickArc&) { return 0.0; },
                               [](const auto&) { return kNaN; }},
                    a.shape);
}
double arc_omega(const Arc& a) {
  return std::visit(Overloaded{[](const HarmonicArc& h) { return h.omega; },
                               [](const HyperbolicArc& h) { return h.omega; },
                               [](const auto&) { return 0.0; }},
                    a.shape);
}
double arc_center(const Arc& a) {
  return std::visit(Overloaded{[](const HarmonicArc& h) { return h.center; },
                               [](const HyperbolicArc& h) { return h.center; },
                               [](const auto&) { return 0.0; }},
                    a.shape);
}

// Collects arcs column-wise.
struct ArcColumns final : MotionObserver {
  std::vector<double> t0, t1, x0, xd0, x1, xd1, table_accel, bound0, slope, alpha, omega, center;
  std::vector<std::int8_t> kind, direction, end;
  std::vector<std::int64_t> segment, piece;
  void on_motion(const MotionInterval&, const Arc* arc) override { add(*arc); }
  void add(const Arc& a) {
    if (static_cast<double>(t0.size()) >= kMaxRecordedSamples)  // sized before it grows
      throw InvalidParameter("duration", a.t1,
                             "the run has more than 1e7 arcs to return: shorten duration");
    t0.push_back(a.t0), t1.push_back(a.t1), x0.push_back(a.x0), xd0.push_back(a.xd0);
    x1.push_back(a.x1), xd1.push_back(a.xd1), table_accel.push_back(a.table_accel);
    bound0.push_back(a.bound0), slope.push_back(a.slope), alpha.push_back(arc_alpha(a));
    omega.push_back(arc_omega(a)), center.push_back(arc_center(a));
    kind.push_back(static_cast<std::int8_t>(a.kind()));
    direction.push_back(a.direction);
    end.push_back(static_cast<std::int8_t>(a.end));
    segment.push_back(static_cast<std::int64_t>(a.segment));
    piece.push_back(static_cast<std::int64_t>(a.piece));
  }
  py::dict to_dict() && {
    py::dict d;
    d["t0"] = to_array(std::move(t0)), d["t1"] = to_array(std::move(t1));
    d["x0"] = to_array(std::move(x0)), d["xd0"] = to_array(std::move(xd0));
    d["x1"] = to_array(std::move(x1)), d["xd1"] = to_array(std::move(xd1));
    d["table_accel"] = to_array(std::move(table_accel));
    d["bound0"] = to_array(std::move(bound0)), d["slope"] = to_array(std::move(slope));
    d["alpha"] = to_array(std::move(alpha)), d["omega"] = to_array(std::move(omega));
    d["center"] = to_array(std::move(center));
    d["kind"] = to_array(std::move(kind)), d["direction"] = to_array(std::move(direction));
    d["end"] = to_array(std::move(end));
    d["segment"] = to_array(std::move(segment)), d["piece"] = to_array(std::move(piece));
    return d;
  }
};

void bind_exact(py::module_& m) {
  bind_int_enum<ArcKind>(m, "ArcKind", R"doc(
The closed form of one exact arc (an enum.IntEnum).
  stick      = 0  x' = 0, x constant (|y''| <= m(x))
  parabolic  = 1  constant friction: x'' = alpha (eqs. 12-24)
  harmonic   = 2  x'' = -omega^2 (x - x_e) (eqs. 42-47)
  hyperbolic = 3  x'' = +omega^2 (x - x_e) (backward slip on rising friction)
  driven     = 4  smooth (Fourier) table motion, constant friction: x'' = a - y''(t)
  driven_affine = 5  Fourier motion on an affine level: x'' = -kappa (x - x_e) - y''(t))doc",
                         {{"stick", ArcKind::stick},
                          {"parabolic", ArcKind::parabolic},
                          {"harmonic", ArcKind::harmonic},
                          {"hyperbolic", ArcKind::hyperbolic},
                          {"driven", ArcKind::driven},
                          {"driven_affine", ArcKind::driven_affine}});
  bind_int_enum<ArcEnd>(m, "ArcEnd", R"doc(
What ended an arc (an enum.IntEnum).
  acceleration_switch = 0  the table acceleration changed (segment end)
  velocity_zero       = 1  x' reached 0 (the stick/slip decision follows)
  friction_boundary   = 2  x reached the end of a friction piece (e.g. x_mu or x_mu + w)
  horizon             = 3  the requested end time
  stick_break         = 4  |y''| reached the static bound s m(x) inside a segment (finite jerk)
  time_step           = 5  one step of Moreau's time-stepping scheme ended
  part_contact        = 6  two parts of a row collided (the exact row solver))doc",
                        {{"acceleration_switch", ArcEnd::acceleration_switch},
                         {"velocity_zero", ArcEnd::velocity_zero},
                         {"friction_boundary", ArcEnd::friction_boundary},
                         {"horizon", ArcEnd::horizon},
                         {"stick_break", ArcEnd::stick_break},
                         {"time_step", ArcEnd::time_step},
                         {"part_contact", ArcEnd::part_contact}});

  py::class_<ExactState> state(m, "ExactState",
                               "Mutable state of the exact solver: the object state plus where "
                               "it is in the profile. Make it with make_exact_state.");
  state
      .def_readonly("object", &ExactState::object,
                    "t, x, x' [-] (read-only: make a new state with make_exact_state)")
      .def_readonly("segment", &ExactState::segment, "current acceleration segment (read-only)")
      .def_readonly("period_index", &ExactState::period_index, "floor(t / Δt) (read-only)")
      .def("__repr__", [](const ExactState& s) {
        return Repr("ExactState")("t", s.object.t)("x", s.object.x)("xd", s.object.xd)(
                   "segment", static_cast<long long>(s.segment))("period_index", s.period_index)
            .str();
      });
  def_record(state, field("object", &ExactState::object), field("segment", &ExactState::segment),
             field("period_index", &ExactState::period_index));

  m.def(
      "make_exact_state",
      [](const TableProfile& profile, const FrictionMap& friction, const ObjectState& object) {
        return make_exact_state(exact_setup(profile, friction), object);
      },
      py::arg("profile"), py::arg("friction"), py::arg("object") = ObjectState{},
      "Places an object state in a piecewise-constant profile (finds its period and segment).");
  m.def(
      "advance_exact",
      [](const TableProfile& profile, const FrictionMap& friction, ExactState& state,
         double t_end) {
        require_finite("t_end", t_end);
        if (t_end > state.object.t)
          require_simulatable_duration("t_end - state.object.t", t_end - state.object.t,
                                       profile.period());
        return advance_exact(exact_setup(profile, friction), state, t_end);
      },
      py::arg("profile"), py::arg("friction"), py::arg("state"), py::arg("t_end"),
      py::call_guard<py::gil_scoped_release>(), R"doc(
Advances `state` in place to time t_end (>= state.object.t) with the exact event-driven
solver; returns the number of arcs computed. Events (acceleration switches, x' = 0, friction
boundaries) are located in closed form; at x' = 0 the set-valued law decides: stick iff
|y''| <= m(x) (eqs. 2, 6). Raises InvalidParameter for a profile that is not piecewise
constant or a friction map that is not piecewise affine.)doc");
  m.def(
      "exact_arcs",
      [](const TableProfile& profile, const FrictionMap& friction, const ObjectState& initial,
         double duration) {
        require_simulatable_duration("duration", duration, profile.period());
        const ExactSetup setup = exact_setup(profile, friction);
        ArcColumns arcs;
        {
          py::gil_scoped_release release;
          ExactState state = make_exact_state(setup, initial);
          advance_exact(setup, state, initial.t + duration, &arcs);
        }
        return std::move(arcs).to_dict();
      },
      py::arg("profile"), py::arg("friction"), py::arg("initial") = ObjectState{},
      py::arg("duration") = 20.0, R"doc(
Every closed-form arc of an exact run from `initial` over `duration` [-], as a dict of 1-D
arrays (one entry per arc):
  float64: t0, t1 (start, end time), x0, xd0, x1, xd1 (state at t0, t1), table_accel (y''),
           bound0 (m(x0)), slope (k = dm/dx), alpha (parabolic x''), omega, center
           (harmonic/hyperbolic omega and x_e)
  int8:    kind (ArcKind), direction (slip direction +1/-1, 0 for stick), end (ArcEnd)
  int64:   segment (table-acceleration segment), piece (friction piece)
Between events x'' = -sigma m(x) - y'' has constant coefficients (eqs. 12-24, 42-47).)doc");

  m.def("decide_at_rest", &decide_at_rest, py::arg("table_accel"), py::arg("static_bound"),
        py::arg("breaking") = 0, py::arg("stalled") = false,
        R"doc(The stick/slip decision at a velocity zero, the one every 1-D solver uses
(simulate/stick_slip_decision.hpp): 0 when the object at rest relative to the table is held
(|y''| <= static_bound = s m(x), the set-valued law (2)), else the slip direction -sign(y'').
`breaking` (the direction of a stick that just broke) decides when nonzero; `stalled` (the
previous slip from rest lasted less than the resolution of t) holds the object.)doc");
}

void bind_time_stepping(py::module_& m) {
  const TimeSteppingOptions d;
  py::class_<TimeSteppingOptions> options(m, "TimeSteppingOptions",
                                          "Options of Moreau's time-stepping.");
  options
      .def(py::init([](double step, double theta) {
             return TimeSteppingOptions{step, theta};
           }),
           py::kw_only(), py::arg("step") = d.step, py::arg("theta") = d.theta)
      .def_readwrite("step", &TimeSteppingOptions::step, "step size h [-], > 0")
      .def_readwrite("theta", &TimeSteppingOptions::theta,
                     "theta of the position update, in [0, 1]")
      .def(
          "validate", [](const TimeSteppingOptions& o) { validate(o); },
          "Raises InvalidParameter unless 0 < step and 0 <= theta <= 1.")
      .def("__repr__", [](const TimeSteppingOptions& o) {
        return Repr("TimeSteppingOptions")("step", o.step)("theta", o.theta).str();
      });
  def_record(options, field("step", &TimeSteppingOptions::step),
             field("theta", &TimeSteppingOptions::theta));

  using S = TimeSteppingState;
  py::class_<S> state(m, "TimeSteppingState",
                      "Mutable state of the stepper (step times are t0 + k h). Make it with "
                      "make_time_stepping_state.");
  state
      .def_readwrite("object", &TimeSteppingState::object, "t, x, x' [-]")
      .def_readwrite("t0", &TimeSteppingState::t0, "time of step 0 [-]")
      .def_readwrite("step_index", &TimeSteppingState::step_index, "k")
      .def_readwrite("table_velocity", &TimeSteppingState::table_velocity, "y'(t_k) [-]")
      .def_readwrite("stick", &TimeSteppingState::stick, "whether the last step ended in stick")
      .def("__repr__", [](const TimeSteppingState& s) {
        return Repr("TimeSteppingState")("t", s.object.t)("x", s.object.x)("xd", s.object.xd)(
                   "step_index", s.step_index)("stick", s.stick)
            .str();
      });
  def_record(state, field("object", &S::object), field("t0", &S::t0),
             field("step_index", &S::step_index), field("table_velocity", &S::table_velocity),
             field("stick", &S::stick));

  m.def("make_time_stepping_state", &make_time_stepping_state, py::arg("profile"),
        py::arg("object") = ObjectState{}, "Starts a stepper at an object state.");
  m.def(
      "advance_time_stepping",
      [](const TableProfile& profile, const FrictionMap& friction,
         const TimeSteppingOptions& options, TimeSteppingState& state, long long steps) {
        validate(options);
        if (steps < 0 || static_cast<double>(steps) > kMaxTimeSteps)
          throw InvalidParameter("steps", static_cast<double>(steps), "must be in [0, 1e9]");
        advance_time_stepping(profile, friction, options, state, steps);
      },
      py::arg("profile"), py::arg("friction"), py::arg("options"), py::arg("state"),
      py::arg("steps"), py::call_guard<py::gil_scoped_release>(), R"doc(
Advances `state` in place by `steps` Moreau steps (Sect. 4.1). One step t_k -> t_k + h:
  x_M      = x_k + (h/2) x'_k                         (where friction is read)
  x'_{k+1} = x'_k - (y'(t_{k+1}) - y'(t_k)) - h m(x_M) s,   s ∈ Sign(x'_{k+1})
  x_{k+1}  = x_k + h ((1 - theta) x'_k + theta x'_{k+1})
solved in closed form (a projection: stick iff |v*| <= h m(x_M)). Any profile and friction
map. Raises InvalidParameter on bad options or steps outside [0, 1e9].)doc");
}

// Every arc of `arcs` as the column dict of exact_arcs.
py::dict arc_dict(const std::vector<Arc>& arcs) {
  ArcColumns columns;
  for (const Arc& a : arcs) columns.add(a);
  return std::move(columns).to_dict();
}

void bind_period_map(py::module_& m) {
  const PeriodMapOptions d;
  py::class_<PeriodMap>(m, "PeriodMap", R"doc(
The map P: (x, x') at phase 0 -> (x, x') one table period Δt later [-], for a table profile,
a friction level m(x) (FrictionMap; the uniform m = 1 without one) and a friction law
(FrictionLaw). Integrated by an exact solver when the profile's acceleration is
piecewise polynomial (constant or finite jerk) or a Fourier series and the level piecewise
affine, by the slip integrator (tolerances `integrator`, IntegratorOptions) under a Stribeck or
viscous law, by Moreau time-stepping (h = Δt/steps_per_period) otherwise. Every analysis (steady state, Floquet,
convergence, stopping, positioning, sweeps) iterates this map. The map keeps its profile and
friction alive.)doc")
      .def(py::init([](const TableProfile& profile, const FrictionLaw& law,
                       int steps_per_period, double theta, const IntegratorOptions& integrator) {
             return std::make_unique<PeriodMap>(
                 profile, law, PeriodMapOptions{steps_per_period, theta, integrator});
           }),
           py::arg("profile"), py::arg("law") = FrictionLaw{}, py::kw_only(),
           py::arg("steps_per_period") = d.steps_per_period, py::arg("theta") = d.theta,
           py::arg("integrator") = d.integrator, py::keep_alive<1, 2>(), "The uniform low-friction table (m = 1) under `law`.")
      .def(py::init([](const TableProfile& profile, const FrictionMap& friction,
                       const FrictionLaw& law, int steps_per_period, double theta,
                       const IntegratorOptions& integrator) {
             return std::make_unique<PeriodMap>(
                 profile, friction, law, PeriodMapOptions{steps_per_period, theta, integrator});
           }),
           py::arg("profile"), py::arg("friction"), py::arg("law") = FrictionLaw{},
           py::kw_only(), py::arg("steps_per_period") = d.steps_per_period,
           py::arg("theta") = d.theta, py::arg("integrator") = d.integrator,
           py::keep_alive<1, 2>(), py::keep_alive<1, 3>(), R"doc(
A table whose friction level is `friction` under `law`. steps_per_period (>= 1) and theta (in
[0, 1]) apply to time-stepping only; raises InvalidParameter for them out of range when the
map time-steps.)doc")
      .def_property_readonly("profile", &PeriodMap::profile, "the table profile")
      .def_property_readonly("friction", &PeriodMap::friction,
                             "the friction level (UniformFriction(1) when none was given)")
      .def_property_readonly("law", &PeriodMap::law, "the friction law")
      .def_property_readonly("method", &PeriodMap::method,
                             "Method.exact, Method.integrator or Method.time_stepping (see the "
                             "class doc)")
      .def_property_readonly("period", &PeriodMap::period, "Δt [-]")
      .def_property_readonly("step", &PeriodMap::step,
                             "time-stepping step h = Δt/steps_per_period [-]; 0 when exact")
      .def(
          "__call__",
          [](const PeriodMap& map, double x0, double v0) {
            require_finite("x0", x0), require_finite("v0", v0);
            py::gil_scoped_release release;
            return map(x0, v0);
          },
          py::arg("x0"), py::arg("v0"),
          "P(x0, v0): the ObjectState (t = Δt, x, x') one period after (x0, x'0 = v0) at "
          "phase 0 [-]. Raises InvalidParameter for non-finite x0, v0. Runs without the GIL.")
      .def(
          "arcs",
          [](const PeriodMap& map, double x0, double v0) {
            require_finite("x0", x0), require_finite("v0", v0);
            std::vector<Arc> arcs;
            {
              py::gil_scoped_release release;
              arcs = map.arcs(x0, v0);
            }
            return arc_dict(arcs);
          },
          py::arg("x0"), py::arg("v0"),
          "The closed-form arcs of one period from (x0, v0) at phase 0, as the dict of 1-D "
          "arrays exact_arcs returns. Exact maps only: raises InvalidParameter for a "
          "time-stepping map or non-finite x0, v0.")
      .def(
          "saltation_monodromy",
          [](const PeriodMap& map, double x0, double v0) {
            require_finite("x0", x0), require_finite("v0", v0);
            Eigen::Matrix2d a;
            {
              py::gil_scoped_release release;
              a = map.saltation_monodromy(x0, v0);
            }
            return matrix_array(a);
          },
          py::arg("x0"), py::arg("v0"), R"doc(
dP/d(x, x') at (x0, v0) as a 2x2 float64 ndarray [-]: the arcs' transition matrices coupled by
the saltation matrices of their events (Leine & Nijmeijer). Exact maps only: raises
InvalidParameter for a time-stepping map or non-finite x0, v0.)doc")
      .def(
          "finite_difference_monodromy",
          [](const PeriodMap& map, double x0, double v0, double h) {
            require_finite("x0", x0), require_finite("v0", v0);
            if (!(std::isfinite(h) && h > 0 && h <= 0.1))
              throw InvalidParameter("h", h, "must be in (0, 0.1]");
            Eigen::Matrix2d a;
            {
              py::gil_scoped_release release;
              a = map.finite_difference_monodromy(x0, v0, h);
            }
            return matrix_array(a);
          },
          py::arg("x0"), py::arg("v0"), py::arg("h") = 1e-7, R"doc(
dP/d(x, x') at (x0, v0) by central differences of step h in x and in x' [-] (h in (0, 0.1]),
as a 2x2 float64 ndarray; either method. Raises InvalidParameter for h out of range or
non-finite x0, v0.)doc")
      .def("__repr__", [](const PeriodMap& map) {
        return "<PeriodMap profile='" + map.profile().kind() +
               "' period=" + format_number(map.period()) + " method=" +
               enum_name(map.method()) + " law=" +
               Repr("FrictionLaw")("static", map.law().static_coefficient())(
                   "kinetic_forward", map.law().kinetic_forward())(
                   "kinetic_backward", map.law().kinetic_backward())
                   .str() +
               ">";
      });
}

}  // namespace

void bind_solvers(py::module_& m) {
  bind_exact(m);
  bind_time_stepping(m);
  bind_period_map(m);
}

}  // namespace selfalign::python
