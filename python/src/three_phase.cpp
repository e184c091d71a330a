// The three-phase table motion (Sect. 4.4.3, Fig. 7, Appendix eqs. 61-67), and its
// jerk-limited variant (Sect. 8, item 2; docs/jerk-limited-three-phase.md).
#include "selfalign/profiles/three_phase.hpp"

#include <limits>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"

namespace selfalign::python {

namespace {

// A solution's durations, velocities and times exist only when it is physical (NaN otherwise).
constexpr auto physical = [](const auto& solution) { return solution.physical; };

std::string parameters_repr(const char* type, const JerkLimitedThreePhaseParameters& p) {
  return Repr(type)("period", p.period)("stroke", p.stroke)("a2", p.a2)("a3", p.a3)
      .raw("jerk", number_source(p.jerk))
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

  using JP = JerkLimitedThreePhaseParameters;
  py::class_<JP> parameters(m, "JerkLimitedThreePhaseParameters", R"doc(
The free parameters of the jerk-limited three-phase profile [-] (Sect. 8, item 2): the
three-phase profile whose acceleration switches are linear ramps of slope +-jerk:
  y'' = 0 (T1) -> ramp to -a2 -> -a2 (T2h) -> ramp to +a3 -> +a3 (T3h) -> ramp to 0
with min y = 0, stroke Δy, and y, y' periodic. Not validated until used.)doc");
  parameters
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
  def_record(parameters, field("period", &JP::period), field("stroke", &JP::stroke),
             field("a2", &JP::a2), field("a3", &JP::a3), field("jerk", &JP::jerk));

  using JS = JerkLimitedThreePhaseSolution;
  py::class_<JS> solution(m, "JerkLimitedThreePhaseSolution", R"doc(
Solution of the jerk-limited three-phase constraints (docs/jerk-limited-three-phase.md), or
case 0. With D the velocity swing and s = 1/a2 + 1/a3:
  T2h = D/a2 - a2/j,  T3h = D/a3 - a3/j,  T1 = Δt - s D - (a2 + a3)/j.
A profile exists iff jerk >= min_jerk; physical = False (with a reason) otherwise.)doc");
  solution
      .def_readonly("physical", &JS::physical,
                    "False: case 0 (see reason); the durations and velocities are then NaN")
      .def_readonly("reason", &JS::reason, "why case 0 (JerkLimitedCase0.none when physical)")
      .def_property_readonly("hold0", nan_unless(&JS::hold0, physical),
                             "T1: duration of y'' = 0 at the start of the period [-]")
      .def_property_readonly("ramp_down", nan_unless(&JS::ramp_down, physical),
                             "a2/j: the ramp of y'' from 0 to -a2 [-] (0 for jerk = inf)")
      .def_property_readonly("hold2", nan_unless(&JS::hold2, physical), "T2h: y'' = -a2 [-]")
      .def_property_readonly("ramp_up", nan_unless(&JS::ramp_up, physical),
                             "(a2 + a3)/j: the ramp of y'' from -a2 to +a3 [-]")
      .def_property_readonly("hold3", nan_unless(&JS::hold3, physical), "T3h: y'' = +a3 [-]")
      .def_property_readonly("ramp_end", nan_unless(&JS::ramp_end, physical),
                             "a3/j: the ramp of y'' from +a3 back to 0 [-]")
      .def_property_readonly("velocity_swing", nan_unless(&JS::velocity_swing, physical),
                             "D = max y' - min y' [-]")
      .def_property_readonly("yd_ini", nan_unless(&JS::yd_ini, physical),
                             "y' on the first hold, the largest table velocity [-]")
      .def_readonly("min_jerk", &JS::min_jerk,
                    "smallest jerk for which (period, stroke, a2, a3) has a profile [-]; inf "
                    "when no finite jerk has one")
      .def_readonly("closed_form", &JS::closed_form,
                    "True: closed form; False: bisection on D (a zero crossing of y' on a ramp)")
      .def(
          "durations",
          [](const JS& r) {
            const auto d = r.durations();
            std::vector<double> out(d.begin(), d.end());
            if (!r.physical) out.assign(out.size(), std::numeric_limits<double>::quiet_NaN());
            return to_array(std::move(out));
          },
          "The six phase durations in order [-] as a float64 array: hold0, ramp_down, hold2, "
          "ramp_up, hold3, ramp_end (they sum to the period when physical; NaN in case 0).")
      .def("__repr__", [](const JS& r) {
        return Repr("JerkLimitedThreePhaseSolution")("physical", r.physical)
            .raw("reason", enum_name(r.reason))(
                "velocity_swing", nan_unless(&JS::velocity_swing, physical)(r))(
                "yd_ini", nan_unless(&JS::yd_ini, physical)(r))("min_jerk", r.min_jerk)
            .str();
      });
  def_record(solution, field("physical", &JS::physical), field("reason", &JS::reason),
             field("hold0", &JS::hold0), field("ramp_down", &JS::ramp_down),
             field("hold2", &JS::hold2), field("ramp_up", &JS::ramp_up),
             field("hold3", &JS::hold3), field("ramp_end", &JS::ramp_end),
             field("velocity_swing", &JS::velocity_swing), field("yd_ini", &JS::yd_ini),
             field("min_jerk", &JS::min_jerk), field("closed_form", &JS::closed_form));

  m.def("solve_jerk_limited_three_phase", &solve_jerk_limited_three_phase, py::arg("parameters"),
        R"doc(
Solves the jerk-limited three-phase constraints (closed form where both zero crossings of y'
lie on the plateaus, else a bisection on the velocity swing over a certified bracket). Raises
InvalidParameter on misuse (see JerkLimitedThreePhaseParameters.validate); returns
physical = False with a reason (case 0) when no profile exists. min_jerk is set whenever the
parameters are valid. jerk = inf reproduces solve_three_phase.)doc");

  py::class_<JerkLimitedThreePhaseProfile, TableProfile> profile(
      m, "JerkLimitedThreePhaseProfile",
      "A physical jerk-limited three-phase profile (trapezoidal acceleration, Sect. 8 item 2); "
      "its acceleration is piecewise linear, so the exact solver applies.");
  profile
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
  def_record(
      profile, [](const JP& p) { return JerkLimitedThreePhaseProfile(p); },
      field("parameters", &JerkLimitedThreePhaseProfile::parameters));
}

}  // namespace

void bind_three_phase(py::module_& m) {
  using TP = ThreePhaseParameters;
  py::class_<TP> parameters(m, "ThreePhaseParameters", R"doc(
The free parameters of the three-phase profile [-] (Sect. 4.4.3, Fig. 7):
  [t0, t1]: y'' = 0,   [t1, t2]: y'' = -a2,   [t2, t3]: y'' = +a3   (t0 = 0, t3 = period)
with min y = 0, stroke Δy, and y, y' periodic. Not validated until used.)doc");
  parameters
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
  def_record(parameters, field("period", &TP::period), field("stroke", &TP::stroke),
             field("a2", &TP::a2), field("a3", &TP::a3));

  using TS = ThreePhaseSolution;
  py::class_<TS> solution(m, "ThreePhaseSolution", R"doc(
Solution of the appendix's eqs. (61)-(67) in the closed form of docs/three-phase-profile.md:
with s = 1/a2 + 1/a3 and G = sqrt(2 s Δy)/Δt a physical profile exists iff G <= 1/2, and then
u = 1 - sqrt(1 - 2G), t1 = (1 - u)Δt, t2 = t1 + u Δt/(s a2), y'_ini = u^2 Δt/(2 s),
y_ini = y'_ini^2/(2 a3). physical = False is the paper's non-physical case 0.)doc");
  const auto t1 = nan_unless(&TS::t1, physical), t2 = nan_unless(&TS::t2, physical),
             t3 = nan_unless(&TS::t3, physical), y_ini = nan_unless(&TS::y_ini, physical),
             yd_ini = nan_unless(&TS::yd_ini, physical);
  solution
      .def_readonly("physical", &TS::physical,
                    "False: case 0, no real solution; the times and the table state are then NaN")
      .def_property_readonly("t1", t1, "switch time t1 [-] (t0 = 0)")
      .def_property_readonly("t2", t2, "switch time t2 [-]")
      .def_property_readonly("t3", t3, "t3 = Δt [-]")
      .def_property_readonly("y_ini", y_ini, "y(t0) [-]")
      .def_property_readonly("yd_ini", yd_ini, "y'(t0) = y' on [t0, t1] [-], >= 0")
      .def_property_readonly("velocity_swing", nan_unless(&TS::velocity_swing, physical),
                             "D = max y' - min y' = a2 (t2 - t1) = a3 (t3 - t2) [-]")
      .def_property_readonly("t_yd0_1", nan_unless(&TS::t_yd0_1, physical),
                             "time of y' = 0 in [t1, t2] (table at its maximum y) [-]")
      .def_property_readonly("t_yd0_2", nan_unless(&TS::t_yd0_2, physical),
                             "time of y' = 0 in [t2, t3] (table at y = 0) [-]")
      .def_readonly("inverse_accel_sum", &TS::inverse_accel_sum, "s = 1/a2 + 1/a3 [-]")
      .def_readonly("inverse_accel_limit", &TS::inverse_accel_limit,
                    "largest physical s: Δt^2 / (8 Δy) [-]")
      .def("__repr__", [=](const TS& r) {
        return Repr("ThreePhaseSolution")("physical", r.physical)("t1", t1(r))("t2", t2(r))(
                   "t3", t3(r))("y_ini", y_ini(r))("yd_ini", yd_ini(r))
            .str();
      });
  def_record(solution, field("physical", &TS::physical), field("t1", &TS::t1),
             field("t2", &TS::t2), field("t3", &TS::t3), field("y_ini", &TS::y_ini),
             field("yd_ini", &TS::yd_ini), field("velocity_swing", &TS::velocity_swing),
             field("t_yd0_1", &TS::t_yd0_1), field("t_yd0_2", &TS::t_yd0_2),
             field("inverse_accel_sum", &TS::inverse_accel_sum),
             field("inverse_accel_limit", &TS::inverse_accel_limit));

  m.def("solve_three_phase", &solve_three_phase, py::arg("parameters"), R"doc(
Closed-form solution of the appendix's eqs. (61)-(67). Raises InvalidParameter on misuse
(non-positive or NaN parameters); returns physical = False (case 0) when the stroke cannot be
reached, i.e. when 1/a2 + 1/a3 > period^2 / (8 stroke).)doc");

  py::class_<ThreePhaseProfile, TableProfile> profile(
      m, "ThreePhaseProfile", "A physical three-phase profile (Sect. 4.4.3).");
  profile
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
  def_record(
      profile, [](const TP& p) { return ThreePhaseProfile(p); },
      field("parameters", &ThreePhaseProfile::parameters));

  bind_jerk_limited(m);
}

}  // namespace selfalign::python
