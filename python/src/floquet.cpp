// Floquet multipliers of the steady state (Sect. 6.1), three ways.
#include "selfalign/analysis/floquet.hpp"

#include <complex>

#include "arrays.hpp"
#include "bindings.hpp"
#include "matrix.hpp"
#include "repr.hpp"
#include "selfalign/error.hpp"

namespace selfalign::python {

namespace {

Eigen::Matrix2d matrix_from(const py::object& obj) {
  const auto a = DoubleArray::ensure(obj);
  if (!a || a.ndim() != 2 || a.shape(0) != 2 || a.shape(1) != 2)
    throw InvalidParameter("matrix", "not 2x2", "must be a 2x2 array of floats");
  const auto r = a.unchecked<2>();
  Eigen::Matrix2d m;
  m << r(0, 0), r(0, 1), r(1, 0), r(1, 1);
  return m;
}

}  // namespace

void bind_floquet(py::module_& m) {
  py::class_<Monodromy>(m, "Monodromy", R"doc(
A monodromy matrix Φ(t0 + Δt, t0) acting on (Δx, Δx') and its eigenvalues (the Floquet
multipliers). The multiplier 1 belongs to the freedom in position (eigenvector [1, 0]).)doc")
      .def_property_readonly(
          "matrix", [](const Monodromy& d) { return matrix_array(d.matrix); },
          "Φ as a 2x2 float64 ndarray (a copy)")
      .def_property_readonly(
          "multipliers",
          [](const Monodromy& d) {
            return to_array(
                std::vector<std::complex<double>>(d.multipliers.begin(), d.multipliers.end()));
          },
          "the two multipliers, largest modulus first (complex128 ndarray)")
      .def_readonly("available", &Monodromy::available,
                    "False where the method does not apply (analytic: non-three-phase)")
      .def("__repr__", [](const Monodromy& d) {
        const auto c = [](std::complex<double> z) {
          return "(" + format_number(z.real()) + (z.imag() < 0 ? "-" : "+") +
                 format_number(std::abs(z.imag())) + "j)";
        };
        return Repr("Monodromy")("available", d.available)
            .raw("multipliers", "[" + c(d.multipliers[0]) + ", " + c(d.multipliers[1]) + "]")
            .str();
      });

  m.def(
      "make_monodromy",
      [](const py::object& matrix) { return make_monodromy(matrix_from(matrix)); },
      py::arg("matrix"), "A Monodromy of a 2x2 matrix: its eigenvalues, largest modulus first.");

  const FloquetOptions d;
  py::class_<FloquetOptions>(m, "FloquetOptions", "Options of floquet_multipliers().")
      .def(py::init([](double fd_step, const SteadyStateOptions& steady) {
             return FloquetOptions{fd_step, steady};
           }),
           py::kw_only(), py::arg("fd_step") = d.fd_step, py::arg("steady") = d.steady)
      .def_readwrite("fd_step", &FloquetOptions::fd_step,
                     "finite-difference perturbation of x0 and x'_0s [-], > 0")
      .def_readwrite("steady", &FloquetOptions::steady, "the steady-state search")
      .def("__repr__", [](const FloquetOptions& o) {
        return Repr("FloquetOptions")("fd_step", o.fd_step)
            .raw("steady", py::repr(py::cast(o.steady)))
            .str();
      });

  py::class_<FloquetAnalysis>(m, "FloquetAnalysis", "The three Floquet analyses of one profile.")
      .def_readonly("steady", &FloquetAnalysis::steady, "the periodic solution analysed")
      .def_readonly("analytic", &FloquetAnalysis::analytic,
                    "linearised period map, eqs. (25)-(33) (three-phase profiles only): "
                    "[[1, 0], [0, 0]] when the response sticks (eq. 30), [[1, m12], [0, λ2]] "
                    "in slip-slip (eq. 33)")
      .def_readonly("saltation", &FloquetAnalysis::saltation,
                    "fundamental solutions of the arcs coupled by saltation matrices")
      .def_readonly("finite_difference", &FloquetAnalysis::finite_difference,
                    "central differences of the exact period map")
      .def_readonly("spread", &FloquetAnalysis::spread,
                    "largest distance between corresponding multipliers of the available "
                    "methods [-]");

  const char* doc = R"doc(
Floquet analysis (Sect. 6.1) of a profile whose acceleration is piecewise constant: the
monodromy matrix of the steady state three ways (analytic eqs. 25-33 for a ThreePhaseProfile;
saltation matrices; finite differences). Raises InvalidParameter for other profiles or bad
options. Runs without the GIL.)doc";
  m.def("floquet_multipliers",
        py::overload_cast<const ThreePhaseProfile&, const FloquetOptions&>(&floquet_multipliers),
        py::arg("profile"), py::arg("options") = FloquetOptions{},
        py::call_guard<py::gil_scoped_release>(), doc);
  m.def("floquet_multipliers",
        py::overload_cast<const TableProfile&, const FloquetOptions&>(&floquet_multipliers),
        py::arg("profile"), py::arg("options") = FloquetOptions{},
        py::call_guard<py::gil_scoped_release>(), doc);
  m.def("floquet_multipliers",
        py::overload_cast<const TableProfile&, const FrictionLaw&, const FloquetOptions&>(
            &floquet_multipliers),
        py::arg("profile"), py::arg("law"), py::arg("options") = FloquetOptions{},
        py::call_guard<py::gil_scoped_release>(),
        "Saltation and finite-difference monodromy of the steady state under a FrictionLaw "
        "law (any piecewise-polynomial profile, finite jerk included).");

  m.def(
      "slip_slip_multiplier",
      [](const py::object& a2, const py::object& a3) -> py::object {
        if (is_scalar(a2) && is_scalar(a3))
          return py::float_(
              slip_slip_multiplier(scalar_value(a2, "a2"), scalar_value(a3, "a3")));
        const py::tuple pair = py::module_::import("numpy").attr("broadcast_arrays")(a2, a3);
        const auto x = DoubleArray::ensure(pair[0]), y = DoubleArray::ensure(pair[1]);
        if (!x || !y) throw py::type_error("a2, a3: expected floats or array-likes of floats");
        py::array_t<double> out(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()));
        double* o = out.mutable_data();
        for (py::ssize_t i = 0; i < x.size(); ++i)
          o[i] = slip_slip_multiplier(x.data()[i], y.data()[i]);
        return out;
      },
      py::arg("a2"), py::arg("a3"),
      "λ2 of the slip-slip case, eq. (33): ((a2-1)(a3-1)) / ((a2+1)(a3+1)) (floats or "
      "broadcastable arrays).");
}

}  // namespace selfalign::python
