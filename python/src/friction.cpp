// Friction maps m(x) = mu_bar(x)/mu_1 (eqs. 7-9).
#include <cstddef>

#include "arrays.hpp"
#include "bindings.hpp"
#include "repr.hpp"
#include "selfalign/friction/coulomb_friction.hpp"
#include "selfalign/friction/friction_map.hpp"

namespace selfalign::python {

namespace {

// The affine pieces as a dict of 1-D arrays, or None.
py::object pieces(const FrictionMap& f) {
  const PiecewiseAffineFriction* affine = f.piecewise_affine();
  if (!affine) return py::none();
  std::vector<double> begin, end, bound, slope;
  for (const AffinePiece& p : affine->pieces()) {
    begin.push_back(p.begin);
    end.push_back(p.end);
    bound.push_back(p.bound_at_begin);
    slope.push_back(p.slope);
  }
  py::dict d;
  d["begin"] = to_array(std::move(begin));
  d["end"] = to_array(std::move(end));
  d["bound_at_begin"] = to_array(std::move(bound));
  d["slope"] = to_array(std::move(slope));
  return d;
}

}  // namespace

void bind_friction(py::module_& m) {
  py::class_<CoulombFriction>(m, "CoulombFriction", R"doc(
The contact's friction law: Coulomb friction with a static coefficient at least the kinetic
one, optionally with direction-dependent kinetic coefficients (sawtooth or textured surfaces).
Dimensionless: every coefficient is relative to mu_1, the forward kinetic coefficient of the
low-friction region, so CoulombFriction() = (1, 1, 1) is the paper's law. While stuck the
object is held as long as |y''| <= static m(x); while slipping in direction sigma the force is
-kinetic_sigma m(x) sigma.)doc")
      .def(py::init<>())
      .def(py::init<double, double>(), py::arg("static"), py::arg("kinetic"),
           "Symmetric law: 0 < kinetic <= static. Raises InvalidParameter naming both otherwise.")
      .def(py::init<double, double, double>(), py::arg("static"), py::arg("kinetic_forward"),
           py::arg("kinetic_backward"),
           "Direction-dependent kinetic coefficients: 0 < kinetic_forward, kinetic_backward <= "
           "static.")
      .def_property_readonly("static", &CoulombFriction::static_coefficient, "s [-]")
      .def_property_readonly("kinetic_forward", &CoulombFriction::kinetic_forward, "k_+ [-]")
      .def_property_readonly("kinetic_backward", &CoulombFriction::kinetic_backward, "k_- [-]")
      .def("__eq__", [](const CoulombFriction& a, const CoulombFriction& b) { return a == b; })
      .def("__repr__", [](const CoulombFriction& f) {
        return Repr("CoulombFriction")("static", f.static_coefficient())(
                   "kinetic_forward", f.kinetic_forward())("kinetic_backward",
                                                           f.kinetic_backward())
            .str();
      });

  py::class_<FrictionMap>(m, "FrictionMap", R"doc(
A friction law m(x) = mu_bar(x)/mu_1 >= 0 [-] (eqs. 7-9): in the dimensionless model
(Sect. 3.2) the friction force lies in -m(x) Sign(x'); m = 1 on the low-friction table.
Abstract: use UniformFriction or TwoRegionFriction.)doc")
      .def(
          "bound",
          [](const FrictionMap& f, const py::object& x) {
            return map_elementwise<double>(x, [&](double v) { return f.bound(v); }, "x");
          },
          py::arg("x"),
          "Friction bound m(x) [-] at dimensionless position(s) x [-] (float or ndarray).")
      .def("pieces", &pieces, R"doc(
The map as affine pieces m(x) = bound_at_begin + slope (x - begin) on [begin, end), sorted,
covering the real line (the form the exact solver integrates), as a dict of 1-D float64
arrays 'begin', 'end', 'bound_at_begin', 'slope'; None when the map is not piecewise affine.)doc");

  py::class_<UniformFriction, FrictionMap>(m, "UniformFriction",
                                           "Uniform Coulomb friction: m(x) = level (1 on the "
                                           "paper's low-friction table).")
      .def(py::init<double>(), py::arg("level") = 1.0,
           "level: m = mu/mu_1 [-], finite and > 0. Raises InvalidParameter otherwise.")
      .def_property_readonly("level", &UniformFriction::level, "m [-]")
      .def("__repr__", [](const UniformFriction& f) {
        return Repr("UniformFriction")("level", f.level()).str();
      });

  py::class_<TwoRegionFriction, FrictionMap>(m, "TwoRegionFriction", R"doc(
The paper's two-region table (Sect. 3.3): mu_1 for x < x_mu, mu_2 = c_mu mu_1 beyond x_mu + w,
and in between the width-averaged transition of eqs. (7)-(9):
  m(x) = 1 + (c_mu - 1)/w * z,   z = min(max(x - x_mu, 0), w)
x is the position of the object's leading edge [-], w its dimensionless width.)doc")
      .def(py::init<double, double, double>(), py::arg("x_mu"), py::arg("width"), py::arg("c_mu"),
           R"doc(
x_mu:  start of the high-friction region [-], finite
width: object width w [-], > 0
c_mu:  friction ratio mu_2/mu_1 [-], > 1
Raises InvalidParameter naming the offending argument.)doc")
      .def_property_readonly("x_mu", &TwoRegionFriction::x_mu, "start of the transition [-]")
      .def_property_readonly("width", &TwoRegionFriction::width, "object width w [-]")
      .def_property_readonly("c_mu", &TwoRegionFriction::c_mu, "mu_2/mu_1 [-]")
      .def_property_readonly("b1", &TwoRegionFriction::b1,
                             "b_1 = (c_mu - 1)/w, the stiffness of the transition (eq. 42) [-]")
      .def_property_readonly("b2", &TwoRegionFriction::b2,
                             "b_2 = (c_mu - 1) x_mu / w - 1 (eq. 42) [-]")
      .def("__repr__", [](const TwoRegionFriction& f) {
        return Repr("TwoRegionFriction")("x_mu", f.x_mu())("width", f.width())("c_mu", f.c_mu())
            .str();
      });
}

}  // namespace selfalign::python
