// The three-phase table motion (Sect. 4.4.3, Fig. 7, Appendix eqs. 61-67), and its
// jerk-limited variant (Sect. 8, item 2; docs/jerk-limited-three-phase.md).
#include "selfalign/profiles/three_phase.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "repr.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"

namespace selfalign::python {

namespace {

// A jerk as Python source: float('inf') evaluates back (a bare inf would not).
std::string jerk_source(double jerk) {
  return std::isinf(jerk) && jerk > 0 ? "float('inf')" : format_number(jerk);
}

std::string parameters_repr(const char* type, const JerkLimitedThreePhaseParameters& p) {
  return Repr(type)("period", p.period)("stroke", p.stroke)("a2", p.a2)("a3", p.a3)
      .raw("jerk", jerk_source(p.jerk))
      .str();
}

void bind_jerk_limited(py::module_& m) {
  bind_int_enum<JerkLimitedCase0>(m, "JerkLimitedCase0", R"doc(
Why no jerk-limited three-phase profile exists (case 0), or none (an enum.IntEnum).
  none                  = 0  physical
  accelerations_too_low = 1  no jerk helps: 1/a2 + 1/a3 > period^2/(8 stroke) (three-phase
                             case 0)
  ramps_exceed_period   = 2  jerk below j_p = (s max(a2, a3)^2 + a2 + a3)/period: the ramps
                             alone outlast the period (s = 1/a2 + 1/a3)
  stroke_too_large      = 3  stroke > period^2/(8 s) - (a2 + a3)^3/(24 jerk^2): the ramps eat
                             the stroke
  stroke_too_small      = 4  reaching both plateaus overshoots the stroke)doc",
                                  {{"none", JerkLimitedCase0::none},
                                   {"accelerations_too_low", JerkLimitedCase0::accelerations_too_low},
                                   {"ramps_exceed_period", JerkLimitedCase0::ramps_exceed_period},
                                   {"stroke_too_large", JerkLimitedCase0::stroke_too_large},
                                   {"stroke_too_small", JerkLimitedCase0::stroke_too_small}});

  py::class_<JerkLimitedThreePhaseParameters>(m, "JerkLimitedThreePhaseParameters", R"doc(
The free parameters of the jerk-limited three-phase profile [-] (Sect. 8, item 2): the
three-phase profile whose acceleration switches are linear ramps of slope +-jerk:
  y'' = 0 (T1) -> ramp to -a2 -> -a2 (T2h) -> ramp to +a3 -> +a3 (T3h) -> ramp to 0
with min y = 0, stroke Δy, and y, y' periodic. Not validated until used.)doc")
      .def(py::init([](double period, double stroke, double a2, double a3, double jerk) {
             return JerkLimitedThreePhaseParameters{period, stroke, a2, a3, jerk};
           }),
           py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"), py::arg("jerk"))
      .def_readwrite("period", &JerkLimitedThreePhaseParameters::period,
                     "Δt [-], in [1e-50, 1e50]")
      .def_readwrite("stroke", &JerkLimitedThreePhaseParameters::stroke,
                     "Δy = max y - min y [-], in [1e-50, 1e50]")
      .def_readwrite("a2", &JerkLimitedThreePhaseParameters::a2,
                     "y2'' > 0: the table accelerates with -a2 on its second plateau [-]")
      .def_readwrite("a3", &JerkLimitedThreePhaseParameters::a3,
                     "y3'' > 0: the table accelerates with +a3 on its third plateau [-]")
      .def_readwrite("jerk", &JerkLimitedThreePhaseParameters::jerk,
                     "j > 0: |y'''| on the ramps [-]; float('inf'): jump accelerations (the "
                     "three-phase profile)")
      .def(
          "validate", [](const JerkLimitedThreePhaseParameters& p) { validate(p); },
          "Raises InvalidParameter unless period, stroke (in [1e-50, 1e50]), a2, a3 are finite "
          "and > 0 and jerk > 0 (inf allowed, NaN refused).")
      .def("__repr__", [](const JerkLimitedThreePhaseParameters& p) {
        return parameters_repr("JerkLimitedThreePhaseParameters", p);
      });

  py::class_<JerkLimitedThreePhaseSolution>(m, "JerkLimitedThreePhaseSolution", R"doc(
Solution of the jerk-limited three-phase constraints (docs/jerk-limited-three-phase.md), or
case 0. With D the velocity swing and s = 1/a2 + 1/a3:
  T2h = D/a2 - a2/j,  T3h = D/a3 - a3/j,  T1 = Δt - s D - (a2 + a3)/j.
A profile exists iff jerk >= min_jerk; physical = False (with a reason) otherwise.)doc")
      .def_readonly("physical", &JerkLimitedThreePhaseSolution::physical,
                    "False: case 0 (see reason); the durations and velocities are then 0")
      .def_readonly("reason", &JerkLimitedThreePhaseSolution::reason,
                    "why case 0 (JerkLimitedCase0.none when physical)")
      .def_readonly("hold0", &JerkLimitedThreePhaseSolution::hold0,
                    "T1: duration of y'' = 0 at the start of the period [-]")
      .def_readonly("ramp_down", &JerkLimitedThreePhaseSolution::ramp_down,
                    "a2/j: the ramp of y'' from 0 to -a2 [-] (0 for jerk = inf)")
      .def_readonly("hold2", &JerkLimitedThreePhaseSolution::hold2, "T2h: y'' = -a2 [-]")
      .def_readonly("ramp_up", &JerkLimitedThreePhaseSolution::ramp_up,
                    "(a2 + a3)/j: the ramp of y'' from -a2 to +a3 [-]")
      .def_readonly("hold3", &JerkLimitedThreePhaseSolution::hold3, "T3h: y'' = +a3 [-]")
      .def_readonly("ramp_end", &JerkLimitedThreePhaseSolution::ramp_end,
                    "a3/j: the ramp of y'' from +a3 back to 0 [-]")
      .def_readonly("velocity_swing", &JerkLimitedThreePhaseSolution::velocity_swing,
                    "D = max y' - min y' [-]")
      .def_readonly("yd_ini", &JerkLimitedThreePhaseSolution::yd_ini,
                    "y' on the first hold, the largest table velocity [-]")
      .def_readonly("min_jerk", &JerkLimitedThreePhaseSolution::min_jerk,
                    "smallest jerk for which (period, stroke, a2, a3) has a profile [-]; inf "
                    "when no finite jerk has one")
      .def_readonly("closed_form", &JerkLimitedThreePhaseSolution::closed_form,
                    "True: closed form; False: bisection on D (a zero crossing of y' on a ramp)")
      .def(
          "durations",
          [](const JerkLimitedThreePhaseSolution& r) {
            const auto d = r.durations();
            return to_array(std::vector<double>(d.begin(), d.end()));
          },
          "The six phase durations in order [-] as a float64 array: hold0, ramp_down, hold2, "
          "ramp_up, hold3, ramp_end (they sum to the period when physical).")
      .def("__repr__", [](const JerkLimitedThreePhaseSolution& r) {
        return Repr("JerkLimitedThreePhaseSolution")("physical", r.physical)
            .raw("reason", enum_name(r.reason))("velocity_swing", r.velocity_swing)(
                "yd_ini", r.yd_ini)("min_jerk", r.min_jerk)
            .str();
      });

  m.def("solve_jerk_limited_three_phase", &solve_jerk_limited_three_phase, py::arg("parameters"),
        R"doc(
Solves the jerk-limited three-phase constraints (closed form where both zero crossings of y'
lie on the plateaus, else a bisection on the velocity swing over a certified bracket). Raises
InvalidParameter on misuse (see JerkLimitedThreePhaseParameters.validate); returns
physical = False with a reason (case 0) when no profile exists. min_jerk is set whenever the
parameters are valid. jerk = inf reproduces solve_three_phase.)doc");

  py::class_<JerkLimitedThreePhaseProfile, TableProfile>(
      m, "JerkLimitedThreePhaseProfile",
      "A physical jerk-limited three-phase profile (trapezoidal acceleration, Sect. 8 item 2); "
      "its acceleration is piecewise linear, so the exact solver applies.")
      .def(py::init<const JerkLimitedThreePhaseParameters&>(), py::arg("parameters"))
      .def(py::init([](double period, double stroke, double a2, double a3, double jerk) {
             return JerkLimitedThreePhaseProfile({period, stroke, a2, a3, jerk});
           }),
           py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"), py::arg("jerk"),
           R"doc(
period, stroke in [1e-50, 1e50], a2, a3 > 0, jerk > 0 [-] (float('inf'): ThreePhaseProfile's
segments exactly). Raises InvalidParameter on misuse and on case 0: naming 'a2, a3' when no
jerk helps (as ThreePhaseProfile), else 'jerk' with the smallest feasible jerk.)doc")
      .def_property_readonly("parameters", &JerkLimitedThreePhaseProfile::parameters,
                             "(Δt, Δy, a2, a3, jerk)")
      .def_property_readonly("solution", &JerkLimitedThreePhaseProfile::solution,
                             "phase durations, velocity swing and min_jerk")
      .def("__repr__", [](const JerkLimitedThreePhaseProfile& p) {
        return parameters_repr("JerkLimitedThreePhaseProfile", p.parameters());
      });
}

}  // namespace

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

  bind_jerk_limited(m);
}

}  // namespace selfalign::python
