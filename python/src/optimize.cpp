// Profile optimisation (Sect. 4.4.2): families, limits, results.
#include "selfalign/design/optimize.hpp"

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"

namespace selfalign::python {

namespace {

// The numbers of a result without an optimum (no parameters: the search found no point to
// evaluate) do not exist: NaN (the library leaves them 0, and max_jerk inf).
constexpr auto has_optimum = [](const OptimizationResult& r) { return !r.parameters.empty(); };

// Binds name(limits, options): optimize(limits, options) without the GIL, interruptible by
// Ctrl-C (progress.hpp): the library's progress callback checks for cancellation, then calls
// the options' own callable.
template <class Optimize>
void def_optimizer(py::module_& m, const char* name, Optimize optimize, const char* doc) {
  m.def(
      name,
      [optimize](const ActuatorLimits& l, const OptimizeOptions& o) {
        const PythonProgress progress{py::none()};
        OptimizeOptions run = o;
        run.progress = [check = progress.callback(), user = o.progress](int done, int total) {
          check(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
          if (user) user(done, total);
        };
        return progress.run([&] { return optimize(l, run); });
      },
      py::arg("limits"), py::arg("options") = OptimizeOptions{}, doc);
}

}  // namespace

void bind_optimize(py::module_& m) {
  const ActuatorLimits dl;
  using L = ActuatorLimits;
  py::class_<L> limits(m, "ActuatorLimits", R"doc(
Actuator limits of the optimisation (dimensionless; Fig. 6: period 0.072, stroke 0.021,
max_velocity 3.2, max_acceleration 1275). Period and stroke are exact; |y'| and |y''| are
bounded over the whole period.)doc");
  limits
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
      .def_readwrite("max_acceleration", &ActuatorLimits::max_acceleration, "y''_max [-]")
      .def("__repr__", [](const L& l) {
        return Repr("ActuatorLimits")("period", l.period)("stroke", l.stroke)(
                   "max_velocity", l.max_velocity)("max_acceleration", l.max_acceleration)
            .raw("max_jerk", number_source(l.max_jerk))
            .str();
      });
  def_record(limits, field("period", &L::period), field("stroke", &L::stroke),
             field("max_velocity", &L::max_velocity),
             field("max_acceleration", &L::max_acceleration), field("max_jerk", &L::max_jerk));

  const OptimizeOptions d;
  using O = OptimizeOptions;
  py::class_<O> options(m, "OptimizeOptions", R"doc(
Options of the optimisers: Fourier order, K segments, multi-starts, evaluations per local run,
three-phase scan grid and polish count, seed, finite-difference step, and an optional
progress(done, total) callable (called after each local run, and with the same `done` about
every 50 ms while one is under way, from a helper thread holding the GIL). The optimisers run
without the GIL; Ctrl-C stops them with KeyboardInterrupt.)doc");
  options
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
      .def_readwrite("starts", &OptimizeOptions::starts, "multi-starts")
      .def_readwrite("max_evaluations", &O::max_evaluations, "objective evaluations per local run")
      .def_readwrite("grid", &O::grid, "three-phase scan: grid points per acceleration axis")
      .def_readwrite("polish", &O::polish, "three-phase: best scan cells polished locally")
      .def_readwrite("seed", &O::seed, "seed of the deterministic random starts")
      .def_readwrite("fd_step", &O::fd_step,
                     "relative central finite-difference step of the Fourier optimiser")
      .def("__repr__", [](const O& o) {
        return Repr("OptimizeOptions")("order", o.order)("segments", o.segments)(
                   "starts", o.starts)("max_evaluations", o.max_evaluations)("grid", o.grid)(
                   "polish", o.polish)("seed", static_cast<long long>(o.seed))(
                   "fd_step", o.fd_step)("threads", o.threads)
            .raw("law", py::repr(py::cast(o.law)))
            .str();
      });
  // progress is a callback, not a value: not part of the record (a copy has none).
  def_record(options, field("order", &O::order), field("segments", &O::segments),
             field("starts", &O::starts), field("max_evaluations", &O::max_evaluations),
             field("grid", &O::grid), field("polish", &O::polish), field("seed", &O::seed),
             field("fd_step", &O::fd_step), field("threads", &O::threads),
             field("law", &O::law));

  using R = OptimizationResult;
  py::class_<R> result(m, "OptimizationResult", R"doc(
An optimum: feasible, f (eq. 11), v_bar, family, parameters (three-phase: a2, a3; piecewise:
d_1..d_K, a_1..a_K; Fourier: A_1..A_N, B_1..B_N), the limits, the optimum's max |y'| and
|y''|, evaluations, starts and a message (the binding limit when infeasible). The numbers of
the optimum are NaN when the search found none (parameters empty).)doc");
  const auto f = nan_unless(&R::f, has_optimum), v_bar = nan_unless(&R::v_bar, has_optimum);
  result
      .def_readonly("feasible", &OptimizationResult::feasible, "an optimum was found")
      .def_property_readonly("f", f, "objective f of eq. (11) [-]")
      .def_property_readonly("v_bar", v_bar, "steady average velocity [-]")
      .def_readonly("family", &OptimizationResult::family, "profile family")
      .def_readonly("parameters", &OptimizationResult::parameters, "the optimum's parameters")
      .def_readonly("limits", &OptimizationResult::limits, "the limits")
      .def_property_readonly("max_velocity", nan_unless(&R::max_velocity, has_optimum),
                             "max |y'| [-]")
      .def_property_readonly("max_acceleration", nan_unless(&R::max_acceleration, has_optimum),
                             "max |y''| [-]")
      .def_property_readonly("max_jerk", nan_unless(&R::max_jerk, has_optimum),
                             "max |jerk| [-] (inf where the acceleration jumps)")
      .def_readonly("evaluations", &OptimizationResult::evaluations, "objective evaluations")
      .def_readonly("starts", &OptimizationResult::starts,
                    "local runs (piecewise-constant: over the chain K = 2 .. K)")
      .def_readonly("message", &OptimizationResult::message, "what happened")
      .def("__repr__", [f, v_bar](const R& r) {
        return Repr("OptimizationResult")
            .raw("family", py::repr(py::str(r.family)))("feasible", r.feasible)("f", f(r))(
                "v_bar", v_bar(r))("evaluations", r.evaluations)
            .raw("message", py::repr(py::str(r.message)))
            .str();
      });
  def_record(result, field("feasible", &R::feasible), field("f", &R::f),
             field("v_bar", &R::v_bar), field("family", &R::family),
             field("parameters", &R::parameters), field("limits", &R::limits),
             field("max_velocity", &R::max_velocity),
             field("max_acceleration", &R::max_acceleration), field("max_jerk", &R::max_jerk),
             field("evaluations", &R::evaluations), field("starts", &R::starts),
             field("message", &R::message));

  def_optimizer(m, "optimize_three_phase", [](const ActuatorLimits& l, const OptimizeOptions& o) {
    return optimize_three_phase(l, o);
  }, "Global optimum of the three-phase family (scan, then polish) within the limits.");
  def_optimizer(
      m, "optimize_piecewise_constant",
      [](const ActuatorLimits& l, const OptimizeOptions& o) {
        return optimize_piecewise_constant(l, o);
      },
      "Optimum of the K-segment piecewise-constant family (K = options.segments), searched after "
      "K - 1, ..., 2 and started from the (K-1) optimum (and, for K = 3, the three-phase one), "
      "so v_bar never falls as K grows.");
  def_optimizer(m, "optimize_fourier", [](const ActuatorLimits& l, const OptimizeOptions& o) {
    return optimize_fourier(l, o);
  }, "Optimum of the Fourier family of order options.order (Sect. 4.4.2).");
  def_optimizer(m, "compare_families", [](const ActuatorLimits& l, const OptimizeOptions& o) {
    return compare_families(l, o);
  }, "One optimum per family: three-phase, piecewise-constant, Fourier.");
  m.def("rebuild_profile", &rebuild_profile, py::arg("result"),
        "The optimal profile of a feasible result, as a TableProfile.");
}

}  // namespace selfalign::python
