// Profile optimisation (Sect. 4.4.2): families, limits, results.
#include "selfalign/design/optimize.hpp"

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"

namespace selfalign::python {

void bind_optimize(py::module_& m) {
  const ActuatorLimits dl;
  py::class_<ActuatorLimits>(m, "ActuatorLimits", R"doc(
Actuator limits of the optimisation (dimensionless; Fig. 6: period 0.072, stroke 0.021,
max_velocity 3.2, max_acceleration 1275). Period and stroke are exact; |y'| and |y''| are
bounded over the whole period.)doc")
      .def(py::init([](double period, double stroke, double v, double a, double j) {
             return ActuatorLimits{period, stroke, v, a, j};
           }),
           py::kw_only(), py::arg("period") = dl.period, py::arg("stroke") = dl.stroke,
           py::arg("max_velocity") = dl.max_velocity,
           py::arg("max_acceleration") = dl.max_acceleration, py::arg("max_jerk") = dl.max_jerk)
      .def_readwrite("max_jerk", &ActuatorLimits::max_jerk,
                     "jerk limit [-] (inf: none; three-phase then ramps at it, "
                     "piecewise-constant is infeasible)")
      .def_readwrite("period", &ActuatorLimits::period, "Δt [-]")
      .def_readwrite("stroke", &ActuatorLimits::stroke, "Δy [-]")
      .def_readwrite("max_velocity", &ActuatorLimits::max_velocity, "y'_max [-]")
      .def_readwrite("max_acceleration", &ActuatorLimits::max_acceleration, "y''_max [-]");

  const OptimizeOptions d;
  py::class_<OptimizeOptions>(m, "OptimizeOptions", R"doc(
Options of the optimisers: Fourier order, K segments, multi-starts, evaluations per local run,
three-phase scan grid and polish count, seed, finite-difference step, and an optional
progress(done, total) callable.)doc")
      .def(py::init([](int order, int segments, int starts, int max_evaluations, int grid,
                       int polish, unsigned seed, double fd_step,
                       std::function<void(int, int)> progress, const FrictionLaw& law,
                       int threads) {
             OptimizeOptions o;
             o.threads = threads;
             o.order = order, o.segments = segments, o.starts = starts;
             o.max_evaluations = max_evaluations, o.grid = grid, o.polish = polish;
             o.seed = seed, o.fd_step = fd_step, o.law = law;
             o.progress = std::move(progress);
             return o;
           }),
           py::kw_only(), py::arg("order") = d.order, py::arg("segments") = d.segments,
           py::arg("starts") = d.starts, py::arg("max_evaluations") = d.max_evaluations,
           py::arg("grid") = d.grid, py::arg("polish") = d.polish, py::arg("seed") = d.seed,
           py::arg("fd_step") = d.fd_step, py::arg("progress") = py::none(),
           py::arg("law") = FrictionLaw{}, py::arg("threads") = d.threads)
      .def_readwrite("threads", &OptimizeOptions::threads,
                     "worker threads of the Fourier optimiser's gradient stencils (0: all cores; "
                     "the result does not depend on it)")
      .def_readwrite("law", &OptimizeOptions::law, "friction law of every steady state")
      .def_readwrite("order", &OptimizeOptions::order, "Fourier order N")
      .def_readwrite("segments", &OptimizeOptions::segments, "K of the piecewise family")
      .def_readwrite("starts", &OptimizeOptions::starts, "multi-starts");

  py::class_<OptimizationResult>(m, "OptimizationResult", R"doc(
An optimum: feasible, f (eq. 11), v_bar, family, parameters (three-phase: a2, a3; piecewise:
d_1..d_K, a_1..a_K; Fourier: A_1..A_N, B_1..B_N), the limits, the optimum's max |y'| and
|y''|, evaluations, starts and a message (the binding limit when infeasible).)doc")
      .def_readonly("feasible", &OptimizationResult::feasible, "an optimum was found")
      .def_readonly("f", &OptimizationResult::f, "objective f of eq. (11) [-]")
      .def_readonly("v_bar", &OptimizationResult::v_bar, "steady average velocity [-]")
      .def_readonly("family", &OptimizationResult::family, "profile family")
      .def_readonly("parameters", &OptimizationResult::parameters, "the optimum's parameters")
      .def_readonly("limits", &OptimizationResult::limits, "the limits")
      .def_readonly("max_velocity", &OptimizationResult::max_velocity, "max |y'| [-]")
      .def_readonly("max_acceleration", &OptimizationResult::max_acceleration, "max |y''| [-]")
      .def_readonly("max_jerk", &OptimizationResult::max_jerk,
                    "max |jerk| [-] (inf where the acceleration jumps)")
      .def_readonly("evaluations", &OptimizationResult::evaluations, "objective evaluations")
      .def_readonly("starts", &OptimizationResult::starts,
                    "local runs (piecewise-constant: over the chain K = 2 .. K)")
      .def_readonly("message", &OptimizationResult::message, "what happened");

  m.def("optimize_three_phase", &optimize_three_phase, py::arg("limits"),
        py::arg("options") = OptimizeOptions{},
        "Global optimum of the three-phase family (scan, then polish) within the limits.");
  m.def(
      "optimize_piecewise_constant",
      [](const ActuatorLimits& l, const OptimizeOptions& o) {
        return optimize_piecewise_constant(l, o);
      },
      py::arg("limits"), py::arg("options") = OptimizeOptions{},
      "Optimum of the K-segment piecewise-constant family (K = options.segments), searched after "
      "K - 1, ..., 2 and started from the (K-1) optimum (and, for K = 3, the three-phase one), "
      "so v_bar never falls as K grows.");
  m.def(
      "optimize_fourier",
      [](const ActuatorLimits& l, const OptimizeOptions& o) { return optimize_fourier(l, o); },
      py::arg("limits"), py::arg("options") = OptimizeOptions{},
      "Optimum of the Fourier family of order options.order (Sect. 4.4.2).");
  m.def("compare_families", &compare_families, py::arg("limits"),
        py::arg("options") = OptimizeOptions{},
        "One optimum per family: three-phase, piecewise-constant, Fourier.");
  m.def("rebuild_profile", &rebuild_profile, py::arg("result"),
        "The optimal profile of a feasible result, as a TableProfile.");
}

}  // namespace selfalign::python
