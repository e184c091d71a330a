// The three-phase table motion (Sect. 4.4.3, Fig. 7, Appendix eqs. 61-67).
#include "selfalign/profiles/three_phase.hpp"

#include "bindings.hpp"
#include "repr.hpp"

namespace selfalign::python {

void bind_three_phase(py::module_& m) {
  py::class_<ThreePhaseParameters>(m, "ThreePhaseParameters", R"doc(
The free parameters of the three-phase profile [-] (Sect. 4.4.3, Fig. 7):
  [t0, t1]: y'' = 0,   [t1, t2]: y'' = -a2,   [t2, t3]: y'' = +a3   (t0 = 0, t3 = period)
with min y = 0, stroke Δy, and y, y' periodic. Not validated until used.)doc")
      .def(py::init([](double period, double stroke, double a2, double a3) {
             return ThreePhaseParameters{period, stroke, a2, a3};
           }),
           py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"))
      .def_readwrite("period", &ThreePhaseParameters::period, "Δt = t3 - t0 [-], > 0")
      .def_readwrite("stroke", &ThreePhaseParameters::stroke, "Δy = max y - min y [-], > 0")
      .def_readwrite("a2", &ThreePhaseParameters::a2,
                     "y2'' > 0: the table accelerates with -y2'' on [t1, t2] [-]")
      .def_readwrite("a3", &ThreePhaseParameters::a3,
                     "y3'' > 0: the table accelerates with +y3'' on [t2, t3] [-]")
      .def(
          "validate", [](const ThreePhaseParameters& p) { validate(p); },
          "Raises InvalidParameter unless period, stroke, a2, a3 are finite and > 0.")
      .def("__repr__", [](const ThreePhaseParameters& p) {
        return Repr("ThreePhaseParameters")("period", p.period)("stroke", p.stroke)("a2", p.a2)(
                   "a3", p.a3)
            .str();
      });

  py::class_<ThreePhaseSolution>(m, "ThreePhaseSolution", R"doc(
Solution of the appendix's eqs. (61)-(67) in the closed form of docs/three-phase-profile.md:
with s = 1/a2 + 1/a3 and G = sqrt(2 s Δy)/Δt a physical profile exists iff G <= 1/2, and then
u = 1 - sqrt(1 - 2G), t1 = (1 - u)Δt, t2 = t1 + u Δt/(s a2), y'_ini = u^2 Δt/(2 s),
y_ini = y'_ini^2/(2 a3). physical = False is the paper's non-physical case 0.)doc")
      .def_readonly("physical", &ThreePhaseSolution::physical,
                    "False: case 0, no real solution; the times are then 0")
      .def_readonly("t1", &ThreePhaseSolution::t1, "switch time t1 [-] (t0 = 0)")
      .def_readonly("t2", &ThreePhaseSolution::t2, "switch time t2 [-]")
      .def_readonly("t3", &ThreePhaseSolution::t3, "t3 = Δt [-]")
      .def_readonly("y_ini", &ThreePhaseSolution::y_ini, "y(t0) [-]")
      .def_readonly("yd_ini", &ThreePhaseSolution::yd_ini, "y'(t0) = y' on [t0, t1] [-], >= 0")
      .def_readonly("t_yd0_1", &ThreePhaseSolution::t_yd0_1,
                    "time of y' = 0 in [t1, t2] (table at its maximum y) [-]")
      .def_readonly("t_yd0_2", &ThreePhaseSolution::t_yd0_2,
                    "time of y' = 0 in [t2, t3] (table at y = 0) [-]")
      .def_readonly("inverse_accel_sum", &ThreePhaseSolution::inverse_accel_sum,
                    "s = 1/a2 + 1/a3 [-]")
      .def_readonly("inverse_accel_limit", &ThreePhaseSolution::inverse_accel_limit,
                    "largest physical s: Δt^2 / (8 Δy) [-]")
      .def("__repr__", [](const ThreePhaseSolution& r) {
        return Repr("ThreePhaseSolution")("physical", r.physical)("t1", r.t1)("t2", r.t2)(
                   "t3", r.t3)("y_ini", r.y_ini)("yd_ini", r.yd_ini)
            .str();
      });

  m.def("solve_three_phase", &solve_three_phase, py::arg("parameters"), R"doc(
Closed-form solution of the appendix's eqs. (61)-(67). Raises InvalidParameter on misuse
(non-positive or NaN parameters); returns physical = False (case 0) when the stroke cannot be
reached, i.e. when 1/a2 + 1/a3 > period^2 / (8 stroke).)doc");

  py::class_<ThreePhaseProfile, TableProfile>(m, "ThreePhaseProfile",
                                              "A physical three-phase profile (Sect. 4.4.3).")
      .def(py::init<const ThreePhaseParameters&>(), py::arg("parameters"))
      .def(py::init([](double period, double stroke, double a2, double a3) {
             return ThreePhaseProfile({period, stroke, a2, a3});
           }),
           py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"), R"doc(
Raises InvalidParameter on misuse and on a non-physical (case 0) request, naming 'a2, a3' and
the allowed range 1/a2 + 1/a3 <= period^2/(8 stroke).)doc")
      .def_property_readonly("parameters", &ThreePhaseProfile::parameters, "(Δt, Δy, a2, a3)")
      .def_property_readonly("solution", &ThreePhaseProfile::solution,
                             "switch times and initial table state (eqs. 61-67)")
      .def("__repr__", [](const ThreePhaseProfile& p) {
        const ThreePhaseParameters& q = p.parameters();
        return Repr("ThreePhaseProfile")("period", q.period)("stroke", q.stroke)("a2", q.a2)("a3",
                                                                                             q.a3)
            .str();
      });
}

}  // namespace selfalign::python
