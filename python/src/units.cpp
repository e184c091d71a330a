// Scales: SI <-> dimensionless (Sect. 3.2, eq. 4).
#include "selfalign/units.hpp"

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

namespace {
// Binds a vectorised conversion method. NaN and +-inf pass through (NaN stays NaN, inf stays
// inf): the library's own values for "absent" and "unbounded"/"accumulates".
template <class PyClass>
void def_conversion(PyClass& cls, const char* name, double (Scales::*f)(double) const noexcept,
                    const char* doc) {
  cls.def(
      name,
      [f](const Scales& s, const py::object& v) {
        return map_elementwise<double>(v, [&](double x) { return (s.*f)(x); }, "value",
                                       NonFinite::pass);
      },
      py::arg("value"), doc);
}
}  // namespace

void bind_units(py::module_& m) {
  py::class_<Scales> cls(m, "Scales", R"doc(
Characteristic scales of the dimensionless model (Sect. 3.2).

Dimensionless variables (eq. 4): x = x~/L, y = y~/L, t = t~/T with the time scale
T = sqrt(L / (mu g)). Accelerations scale with L/T^2 = mu g, velocities with
L/T = sqrt(L mu g). Everything else in selfalign is dimensionless; these conversions are the
one place SI appears. The conversion methods accept floats or NumPy arrays; NaN (absent) stays
NaN and +-inf (unbounded, e.g. no jerk limit, or a process time that accumulates) stays +-inf.)doc");
  cls.def(py::init<double, double, double>(), py::arg("length_m"), py::arg("mu"),
          py::arg("gravity") = 9.81, R"doc(
length_m: characteristic length L~ [m], > 0
mu:       low-friction Coulomb coefficient mu = mu_1 [-], > 0
gravity:  gravitational acceleration g~ [m/s^2], > 0
Raises InvalidParameter naming the offending argument.)doc");
  cls.def_property_readonly("length", &Scales::length, "L~ [m]")
      .def_property_readonly("mu", &Scales::mu, "mu_1 [-]")
      .def_property_readonly("gravity", &Scales::gravity, "g~ [m/s^2]")
      .def_property_readonly("time", &Scales::time, "T~ = sqrt(L~/(mu g~)) [s]")
      .def_property_readonly("velocity", &Scales::velocity, "L~/T~ [m/s]")
      .def_property_readonly("acceleration", &Scales::acceleration, "L~/T~^2 = mu g~ [m/s^2]")
      .def_property_readonly("jerk", &Scales::jerk, "L~/T~^3 = mu g~/T~ [m/s^3]");
  def_conversion(cls, "length_from_si", &Scales::length_from_si, "metres -> [-]");
  def_conversion(cls, "time_from_si", &Scales::time_from_si, "seconds -> [-]");
  def_conversion(cls, "velocity_from_si", &Scales::velocity_from_si, "m/s -> [-]");
  def_conversion(cls, "acceleration_from_si", &Scales::acceleration_from_si, "m/s^2 -> [-]");
  def_conversion(cls, "jerk_from_si", &Scales::jerk_from_si, "m/s^3 -> [-]");
  def_conversion(cls, "length_to_si", &Scales::length_to_si, "[-] -> metres");
  def_conversion(cls, "time_to_si", &Scales::time_to_si, "[-] -> seconds");
  def_conversion(cls, "velocity_to_si", &Scales::velocity_to_si, "[-] -> m/s");
  def_conversion(cls, "acceleration_to_si", &Scales::acceleration_to_si, "[-] -> m/s^2");
  def_conversion(cls, "jerk_to_si", &Scales::jerk_to_si, "[-] -> m/s^3");
  cls.def("__repr__", [](const Scales& s) {
    return Repr("Scales")("length_m", s.length())("mu", s.mu())("gravity", s.gravity()).str();
  });
  def_record(
      cls, [](double length, double mu, double gravity) { return Scales(length, mu, gravity); },
      field("length", &Scales::length), field("mu", &Scales::mu),
      field("gravity", &Scales::gravity));
}

}  // namespace selfalign::python
