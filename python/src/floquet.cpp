// Floquet multipliers of the steady state (Sect. 6.1), three ways.
#include "selfalign/analysis/floquet.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <complex>
#include <limits>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "matrix.hpp"
#include "record.hpp"
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


// What Python sees of a monodromy: NaN matrix and multipliers where the method does not apply
// (the library leaves the identity and zeros there).
Eigen::Matrix2d shown_matrix(const Monodromy& d) {
  return d.available ? d.matrix : Eigen::Matrix2d::Constant(kNaN);
}
std::vector<std::complex<double>> shown_multipliers(const Monodromy& d) {
  if (!d.available) return {{kNaN, kNaN}, {kNaN, kNaN}};
  return {d.multipliers.begin(), d.multipliers.end()};
}

}  // namespace

void bind_floquet(py::module_& m) {
  py::class_<Monodromy> monodromy(m, "Monodromy", R"doc(
A monodromy matrix Φ(t0 + Δt, t0) acting on (Δx, Δx') and its eigenvalues (the Floquet
multipliers). The multiplier 1 belongs to the freedom in position (eigenvector [1, 0]).)doc");
  monodromy
      .def_property_readonly(
          "matrix", [](const Monodromy& d) { return matrix_array(shown_matrix(d)); },
          "Φ as a 2x2 float64 ndarray (a copy); NaN where not available")
      .def_property_readonly(
          "multipliers", [](const Monodromy& d) { return to_array(shown_multipliers(d)); },
          "the two multipliers, largest modulus first (complex128 ndarray); NaN where not "
          "available")
      .def_readonly("available", &Monodromy::available,
                    "False where the method does not apply (analytic: non-three-phase)")
      .def("__repr__", [](const Monodromy& d) {
        const auto c = [](std::complex<double> z) {
          return "(" + format_number(z.real()) + (z.imag() < 0 ? "-" : "+") +
                 format_number(std::abs(z.imag())) + "j)";
        };
        const auto z = shown_multipliers(d);
        return Repr("Monodromy")("available", d.available)
            .raw("multipliers", "[" + c(z[0]) + ", " + c(z[1]) + "]")
            .str();
      });
  def_record(
      monodromy,
      field(
          "matrix", [](const Monodromy& d) { return matrix_array(d.matrix); },
          [](Monodromy& d, const py::object& matrix) { d.matrix = matrix_from(matrix); }),
      field(
          "multipliers",
          [](const Monodromy& d) {
            return to_array(
                std::vector<std::complex<double>>(d.multipliers.begin(), d.multipliers.end()));
          },
          [](Monodromy& d, const py::object& multipliers) {
            using Complex = py::array_t<std::complex<double>, py::array::c_style |
                                                                   py::array::forcecast>;
            const auto z = Complex::ensure(multipliers);
            if (!z || z.size() != 2) throw py::value_error("pickle state: expected 2 multipliers");
            std::copy(z.data(), z.data() + 2, d.multipliers.begin());
          }),
      field("available", &Monodromy::available));

  m.def(
      "make_monodromy",
      [](const py::object& matrix) { return make_monodromy(matrix_from(matrix)); },
      py::arg("matrix"), "A Monodromy of a 2x2 matrix: its eigenvalues, largest modulus first.");

  const FloquetOptions d;
  py::class_<FloquetOptions> options(m, "FloquetOptions", "Options of floquet_multipliers().");
  options
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
  def_record(options, field("fd_step", &FloquetOptions::fd_step),
             field("steady", &FloquetOptions::steady));

  using A = FloquetAnalysis;
  py::class_<A> analysis(m, "FloquetAnalysis", "The three Floquet analyses of one profile.");
  analysis
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
                    "methods [-]")
      .def("__repr__", [](const FloquetAnalysis& a) {
        return Repr("FloquetAnalysis")
            .raw("analytic", py::repr(py::cast(a.analytic)))
            .raw("saltation", py::repr(py::cast(a.saltation)))
            .raw("finite_difference", py::repr(py::cast(a.finite_difference)))("spread",
                                                                                a.spread)
            .str();
      });
  def_record(analysis, field("steady", &A::steady), field("analytic", &A::analytic),
             field("saltation", &A::saltation),
             field("finite_difference", &A::finite_difference), field("spread", &A::spread));

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
