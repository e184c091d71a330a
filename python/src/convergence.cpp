// Convergence of two velocity responses (Sect. 6.2, Fig. 13; Lyapunov function eq. 35).
#include "selfalign/analysis/convergence.hpp"

#include <optional>

#include "arguments.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

void bind_convergence(py::module_& m) {
  py::class_<SignInterval> interval(m, "SignInterval",
                                    "A maximal time interval on which the selected friction "
                                    "forces are equal (v̂1 = v̂2, the paper's '=') or not ('≠').");
  interval
      .def_readonly("t_begin", &SignInterval::t_begin, "[-]")
      .def_readonly("t_end", &SignInterval::t_end, "[-]")
      .def_readonly("same", &SignInterval::same, "True: '=', False: '≠'")
      .def("__repr__", [](const SignInterval& s) {
        return Repr("SignInterval")("t_begin", s.t_begin)("t_end", s.t_end)("same", s.same).str();
      });
  def_record(interval, field("t_begin", &SignInterval::t_begin),
             field("t_end", &SignInterval::t_end), field("same", &SignInterval::same));

  py::class_<VelocityConvergence> cls(m, "VelocityConvergence", R"doc(
Two velocity responses v1, v2 of the same table motion and V = (v1 - v2)^2 / 2 (eq. 35). By
eq. (36) V is constant where v̂1 = v̂2 and decreases where v̂1 ≠ v̂2. Arrays are read-only
float64 views: samples on a uniform grid plus every event of either trajectory.)doc");
  def_array(cls, "t", &VelocityConvergence::t, "time [-]");
  def_array(cls, "v1", &VelocityConvergence::v1, "x'_1 [-]");
  def_array(cls, "v2", &VelocityConvergence::v2, "x'_2 [-]");
  def_array(cls, "lyapunov", &VelocityConvergence::lyapunov, "V = (v1 - v2)^2 / 2 [-] (eq. 35)");
  cls.def_property_readonly(
      "intervals",
      [](const VelocityConvergence& c) {
        py::list out;
        for (const SignInterval& s : c.intervals) out.append(s);
        return out;
      },
      "the '=' and '≠' intervals covering [t0, t0 + duration] (list of SignInterval)");
  cls.def_property_readonly(
      "interval_arrays",
      [](const VelocityConvergence& c) {
        std::vector<double> b, e;
        py::array_t<bool> same(static_cast<py::ssize_t>(c.intervals.size()));
        for (std::size_t i = 0; i < c.intervals.size(); ++i) {
          b.push_back(c.intervals[i].t_begin);
          e.push_back(c.intervals[i].t_end);
          same.mutable_data()[i] = c.intervals[i].same;
        }
        py::dict d;
        d["t_begin"] = to_array(std::move(b));
        d["t_end"] = to_array(std::move(e));
        d["same"] = same;
        return d;
      },
      "the intervals as a dict of 1-D arrays: t_begin, t_end (float64), same (bool)");
  const auto t_coincide = [](const VelocityConvergence& c) -> py::object {
    return c.t_coincide ? py::object(py::float_(*c.t_coincide)) : py::object(py::none());
  };
  cls.def_property_readonly(
      "t_coincide", t_coincide,
      "first time from which v1 = v2 for good (both stuck together) [-]; None if not reached");
  cls.def("__repr__", [t_coincide](const VelocityConvergence& c) {
    return Repr("VelocityConvergence")("samples", static_cast<long long>(c.t.size()))(
               "intervals", static_cast<long long>(c.intervals.size()))
        .raw("t_coincide", py::repr(t_coincide(c)))
        .str();
  });
  using C = VelocityConvergence;
  def_record(cls, field("t", &C::t), field("v1", &C::v1), field("v2", &C::v2),
             field("lyapunov", &C::lyapunov), field("intervals", &C::intervals),
             field("t_coincide", t_coincide, [](C& c, const py::object& t) {
               c.t_coincide =
                   t.is_none() ? std::optional<double>()
                               : std::optional(argument<double>(t, "t_coincide", "a float or None"));
             }));

  const ConvergenceOptions d;
  using O = ConvergenceOptions;
  py::class_<O> options(m, "ConvergenceOptions", "Options of velocity_convergence().");
  options
      .def(py::init([](double v1, double v2, double t0, double duration, int samples_per_period,
                       const IntegratorOptions& integrator) {
             return ConvergenceOptions{v1, v2, t0, duration, samples_per_period, integrator};
           }),
           py::kw_only(), py::arg("v1") = d.v1, py::arg("v2") = d.v2, py::arg("t0") = d.t0,
           py::arg("duration") = d.duration, py::arg("samples_per_period") = d.samples_per_period,
           py::arg("integrator") = d.integrator)
      .def_readwrite("v1", &ConvergenceOptions::v1, "initial velocity of trajectory 1 [-]")
      .def_readwrite("v2", &ConvergenceOptions::v2, "initial velocity of trajectory 2 [-]")
      .def_readwrite("t0", &ConvergenceOptions::t0, "common start time [-]")
      .def_readwrite("duration", &ConvergenceOptions::duration, "simulated time [-], > 0")
      .def_readwrite("samples_per_period", &ConvergenceOptions::samples_per_period,
                     "uniform samples per table period, >= 1")
      .def_readwrite("integrator", &ConvergenceOptions::integrator,
                     "IntegratorOptions: the slip integrator's tolerances (Stribeck, viscous "
                     "laws)")
      .def("__repr__", [](const ConvergenceOptions& o) {
        return Repr("ConvergenceOptions")("v1", o.v1)("v2", o.v2)("t0", o.t0)(
                   "duration", o.duration)("samples_per_period", o.samples_per_period)
            .raw("integrator", py::repr(py::cast(o.integrator)).cast<std::string>())
            .str();
      });
  def_record(options, field("v1", &O::v1), field("v2", &O::v2), field("t0", &O::t0),
             field("duration", &O::duration), field("samples_per_period", &O::samples_per_period),
             field("integrator", &O::integrator));

  m.def("velocity_convergence",
        py::overload_cast<const TableProfile&, const ConvergenceOptions&>(&velocity_convergence), py::arg("profile"),
        py::arg("options"), py::call_guard<py::gil_scoped_release>());
  m.def("velocity_convergence",
        py::overload_cast<const TableProfile&, const FrictionLaw&,
                          const ConvergenceOptions&>(&velocity_convergence),
        py::arg("profile"), py::arg("law") = FrictionLaw{},
        py::arg("options") = ConvergenceOptions{}, py::call_guard<py::gil_scoped_release>(),
        R"doc(
Runs two trajectories of the same piecewise-constant profile on the uniform table from
velocities options.v1 and options.v2 with the exact solver (Sect. 6.2, Fig. 13). Raises
InvalidParameter for other profiles or bad options. Runs without the GIL.)doc");
}

}  // namespace selfalign::python
