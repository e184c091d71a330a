// Where and how the object stops in the friction transition region (Sect. 7.2, 7.3):
// eqs. (40), (41), the stick-position map (59)-(60) and stopping runs.
#include "selfalign/analysis/stopping.hpp"

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/stick_position.hpp"

namespace selfalign::python {

namespace {

void bind_stick_position(py::module_& m) {
  m.def(
      "sticks_permanently",
      [](const FrictionMap& friction, double peak_acceleration, const py::object& x) {
        return map_elementwise<bool>(
            x, [&](double v) { return sticks_permanently(friction, peak_acceleration, v); });
      },
      py::arg("friction"), py::arg("peak_acceleration"), py::arg("x"),
      "eq. (40): True where an object at rest at x [-] is held by friction whatever the table "
      "does, i.e. m(x) >= max |y''| (bool, or a bool ndarray shaped like x).");
  m.def("stick_position_min",
        py::overload_cast<const TwoRegionTable&, double>(&stick_position_min),
        py::arg("table"),
        py::arg("peak_acceleration"), R"doc(
eq. (41) [-] on the paper's table (a TwoRegionTable; a friction map built by
two_region_friction gives its own as .two_region): x_stick,min = x_mu + w (max|y''| - 1)/(c_mu - 1), the smallest x >= x_mu at
which eq. (40) holds; x_mu when the peak acceleration is <= 1, +inf when it exceeds c_mu (the
object never stops for good).)doc");

  py::class_<PeriodStickPositionMap>(m, "PeriodStickPositionMap", R"doc(
The stick-position map of any piecewise-affine level under a Coulomb law, by the exact solver:
where an object at rest at x_n at the look phase (three-phase: t1, the start of its -a2
segment; other profiles: 0) is at rest one period later; NaN where it is moving then. On the
paper's table under the paper's law it is StickPositionMap.next_stick_position (eq. 59 and the
slide back); on other levels (a field, several steps) it is the map itself: its fixed points
are where s m(x) >= max|y''| (eq. 40), the lowest the general eq. (41), where stops below
accumulate. Calling it works elementwise on floats and ndarrays.)doc")
      .def(py::init<const TableProfile&, const FrictionMap&, const FrictionLaw&>(),
           py::arg("profile"), py::arg("friction"), py::arg("law") = FrictionLaw{},
           py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
           "profile: piecewise constant or linear in acceleration; friction: a piecewise-affine "
           "level; law: velocity-independent (the exact solver).")
      .def(
          "__call__",
          [](const PeriodStickPositionMap& map, const py::object& x_n) {
            return map_elementwise<double>(x_n, [&](double v) { return map(v); });
          },
          py::arg("x_n"), "x_{n+1} [-]: at rest one period after rest at x_n at the look; NaN "
                          "where moving then (float or ndarray)")
      .def_property_readonly("look_phase", &PeriodStickPositionMap::look_phase,
                             "the phase of the looks [-]");

  py::class_<StickPositionMap>(m, "StickPositionMap", R"doc(
The stick-position map of eq. (59) for a three-phase profile on a two-region table:
  x_{n+1} = c2 + sqrt((K + d cos θ)^2 + (d sin θ)^2),   d = x_n - c1,
  c1 = (b2 + a2)/b1,  c2 = (b2 - a3)/b1,  K = (a2 + a3)/b1,  θ = sqrt(b1) (t2 - t1),
with fixed point c1 (eq. 60) and slope cos θ there (docs/accumulation.md). Calling the map
works elementwise on floats and ndarrays. next_stick_position adds the slide back that follows
a stop where friction cannot hold the object (m < a3; on the diagonal a3 = a2 at every stop
below x_stick,min).)doc")
      .def(py::init<const ThreePhaseProfile&, const TwoRegionTable&>(), py::arg("profile"),
           py::arg("table"),
           "profile: the three-phase table motion; table: the paper's TwoRegionTable (a map "
           "built by two_region_friction gives its own as .two_region).")
      .def(
          "__call__",
          [](const StickPositionMap& map, const py::object& x_n) {
            return map_elementwise<double>(x_n, [&](double v) { return map(v); });
          },
          py::arg("x_n"), "x_{n+1} of eq. (59) [-] (float or ndarray)")
      .def("fixed_point", &StickPositionMap::fixed_point, "eq. (60): (b2 + a2)/b1 [-]")
      .def("slope_at_fixed_point", &StickPositionMap::slope_at_fixed_point,
           "d x_{n+1}/d x_n at the fixed point: cos θ [-]")
      .def("basin_lower_bound", &StickPositionMap::basin_lower_bound,
           "x_{n+1}(x) < fixed point iff x > this bound (for x < fixed point) [-]")
      .def(
          "next_stick_position",
          [](const StickPositionMap& map, const py::object& x_n) {
            return map_elementwise<double>(x_n,
                                           [&](double v) { return map.next_stick_position(v); });
          },
          py::arg("x_n"),
          "Where an object at rest at x_n through [t0, t1] rests at the next t1 [-]: the stop of "
          "eq. (59) where m there >= a3, else that stop followed by the slide back; NaN where "
          "the motion leaves these arcs (float or ndarray).")
      .def("contraction_at_fixed_point", &StickPositionMap::contraction_at_fixed_point,
           "d next_stick_position/d x_n at the fixed point [-]: cos θ for a3 < a2, "
           "cos θ cosh(sqrt(b1)(t3 - t2)) on the diagonal a3 = a2; NaN where the fixed point is "
           "not x_stick,min.")
      .def("accumulates_for_every_entry", &StickPositionMap::accumulates_for_every_entry,
           "Sect. 7.3: accumulation for every entry iff x_{n+1}(x_mu) < x_stick,min; None where "
           "the condition's derivation does not hold (accumulation_condition_reason says why).")
      .def(
          "accumulation_condition_applies",
          [](const StickPositionMap& map) { return map.every_entry_accumulation().applies; },
          "Whether Sect. 7.3's condition for every entry applies here (docs/accumulation.md).")
      .def(
          "accumulation_condition_reason",
          [](const StickPositionMap& map) { return map.every_entry_accumulation().reason; },
          "Why the condition does not apply (the failing assumption); '' where it applies.")
      .def("proves_accumulation_from", &StickPositionMap::proves_accumulation_from, py::arg("x_n"),
           "Whether an object at rest at x_n through [t0, t1] provably accumulates to the fixed "
           "point: the stops of eq. (59) hold and rise, or the slides back after them contract "
           "(the conditions then hold along the whole sequence).")
      .def(
          "slip_duration",
          [](const StickPositionMap& map, const py::object& x_n) {
            return map_elementwise<double>(x_n, [&](double v) { return map.slip_duration(v); });
          },
          py::arg("x_n"), "Time from t1 to the stop x_{n+1}: (t2 - t1) + eq. (58)'s arc time [-].");
}

void bind_stopping_run(py::module_& m) {
  py::enum_<StopKind> stop_kind(m, "StopKind", "How a stopping run ended.");
  stop_kind
      .value("permanent_stick", StopKind::permanent_stick,
             "stuck for good at end_position (eq. 40)")
      .value("accumulation", StopKind::accumulation,
             "stick positions accumulate at end_position = x_stick,min (eq. 60)")
      .value("not_stopped", StopKind::not_stopped,
             "max_periods reached without a proof (e.g. the object never arrives), a periodic "
             "orbit that never rests, or never_stops (proven)");
  refuse_unknown_values(stop_kind, "StopKind", 3);

  const StoppingOptions d;
  py::class_<StoppingOptions> options(m, "StoppingOptions", "Options of stopping_run().");
  options
      .def(py::init([](int max_periods, const py::object& fractions,
                       const IntegratorOptions& integrator, int steps_per_period,
                       std::optional<Method> method) {
             StoppingOptions o;
             o.max_periods = max_periods;
             o.integrator = integrator;
             o.fractions = to_vector(fractions, "fractions");
             o.steps_per_period = steps_per_period;
             o.method = method;
             return o;
           }),
           py::kw_only(), py::arg("max_periods") = d.max_periods,
           py::arg("fractions") = to_array(std::vector(d.fractions)),
           py::arg("integrator") = d.integrator,
           py::arg("steps_per_period") = d.steps_per_period, py::arg("method") = py::none())
      .def_readwrite("method", &StoppingOptions::method,
                     "the stepper asked for (a Method or its name); None (the default): the "
                     "best the problem allows (exact, smooth exact, integrator, then "
                     "time-stepping)")
      .def_readwrite("steps_per_period", &StoppingOptions::steps_per_period,
                     "time-stepping (a profile or level no closed-form solver takes): h = "
                     "period / steps_per_period, >= 1")
      .def_readwrite("integrator", &StoppingOptions::integrator,
                     "IntegratorOptions: tolerances of the slip integrator (Stribeck, viscous "
                     "laws), which locates the entry and the targets as events")
      .def_readwrite("max_periods", &StoppingOptions::max_periods,
                     "give up after this many table periods (a run also ends, not stopped, "
                     "when the state at a period start repeats exactly)")
      .def_property(
          "fractions", [](const StoppingOptions& o) { return to_array(std::vector(o.fractions)); },
          [](StoppingOptions& o, const py::object& v) { o.fractions = to_vector(v, "fractions"); },
          "fractions p in [0, 1]: the time to reach x_mu + p (x_stick,min - x_mu) for good is "
          "reported")
      .def("__repr__", [](const StoppingOptions& o) {
        std::string fractions;
        for (double p : o.fractions)
          fractions += (fractions.empty() ? "" : ", ") + format_number(p);
        return Repr("StoppingOptions")("max_periods", o.max_periods)
            .raw("fractions", "[" + fractions + "]")("steps_per_period", o.steps_per_period)
            .str();
      });
  def_record(options, field("max_periods", &StoppingOptions::max_periods),
             field("fractions", &StoppingOptions::fractions),
             field("integrator", &StoppingOptions::integrator),
             field("steps_per_period", &StoppingOptions::steps_per_period),
             field("method", &StoppingOptions::method));

  py::class_<StoppingRun> run(m, "StoppingRun", "The outcome of stopping_run().");
  run.def_readonly("kind", &StoppingRun::kind, "how the run ended")
      .def_readonly("method", &StoppingRun::method,
                    "the stepper that ran (Method.exact: the exact or smooth exact solver; "
                    "Method.integrator; Method.time_stepping)")
      .def_readonly("end_position", &StoppingRun::end_position,
                    "where the object stops [-]; NaN when it did not stop (not_stopped)")
      .def_readonly("process_time", &StoppingRun::process_time,
                    "T_p: time the final stick starts [-]; +inf for accumulation; NaN when "
                    "not_stopped")
      .def_readonly("entry_time", &StoppingRun::entry_time,
                    "first time x >= x_mu [-]; NaN if never")
      .def_readonly("x_stick_min", &StoppingRun::x_stick_min, "eq. (41) [-]")
      .def_readonly("accumulation_proven", &StoppingRun::accumulation_proven,
                    "for accumulation: True when proven by the map of eqs. (59), (60) (two-region "
                    "table, three-phase profile, the paper's law), False when observed (the rest "
                    "positions rose to within 1e-9 of x_stick,min, each gap smaller than the one "
                    "before)")
      .def_readonly("never_stops", &StoppingRun::never_stops,
                    "not_stopped with a proof: no position holds the object (x_stick,min = "
                    "inf, eq. 41); the run ended once the object had entered the rough region");
  def_array(run, "stick_positions", &StoppingRun::stick_positions,
            "successive positions where the object came to rest at x >= x_mu [-]");
  def_array(run, "time_to_fraction", &StoppingRun::time_to_fraction,
            "per options.fractions[k]: the time from which x >= x_mu + p (x_stick,min - x_mu) "
            "for good [-] (the first crossing where the object only moves forward, the last "
            "after slides back as on the diagonal a2 = a3); NaN if not reached");
  def_array(run, "periods_to_fraction", &StoppingRun::periods_to_fraction,
            "per options.fractions[k]: table periods from entry to then (int)");
  run.def("__repr__", [](const StoppingRun& r) {
    return Repr("StoppingRun")
        .raw("kind", enum_name(r.kind))("end_position", r.end_position)(
            "process_time", r.process_time)("entry_time", r.entry_time)
        .str();
  });
  using R = StoppingRun;
  def_record(run, field("kind", &R::kind), field("method", &R::method),
             field("end_position", &R::end_position),
             field("process_time", &R::process_time), field("entry_time", &R::entry_time),
             field("x_stick_min", &R::x_stick_min),
             field("accumulation_proven", &R::accumulation_proven),
             field("never_stops", &R::never_stops),
             field("stick_positions", &R::stick_positions),
             field("time_to_fraction", &R::time_to_fraction),
             field("periods_to_fraction", &R::periods_to_fraction));

  m.def(
      "stopping_run",
      [](const TableProfile& profile, const FrictionMap& friction, const ObjectState& start,
         const StoppingOptions& options, const FrictionLaw& law) {
        return stopping_run(profile, friction, law, start, options);
      },
      py::arg("profile"), py::arg("friction"), py::arg("start"),
      py::arg("options") = StoppingOptions{}, py::kw_only(), py::arg("law") = FrictionLaw{},
      py::call_guard<py::gil_scoped_release>(), R"doc(
Runs the object from `start` until it provably stops for good (Sect. 7): a permanent stick
(eq. 40: static m(x) >= max|y''|; or, where no closed form proves it, at rest through a whole
table period, the one stopping criterion of every stepper and of planar_stop), or, for
three-phase profiles on the two-region table under the paper's law, stick positions that the
map of eq. (59) drives to its fixed point x_stick,min (accumulation, Sect. 7.3). Any
piecewise-affine friction level, FrictionLaw law and profile: the exact solver for piecewise
constant or linear accelerations, the smooth exact one for Fourier profiles on piecewise
constant levels, the slip integrator for velocity-dependent laws, Moreau's time-stepping
(options.steps_per_period) otherwise; run.method says which. T_p is when the final stick began
(to the step for a time-stepped run). Raises InvalidParameter for a level that is not piecewise
affine or bad options. Runs without the GIL.)doc");
}

}  // namespace

void bind_stopping(py::module_& m) {
  bind_stick_position(m);
  bind_stopping_run(m);
}

}  // namespace selfalign::python
