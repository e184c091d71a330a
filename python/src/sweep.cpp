// Parameter studies (Sect. 4.4.1, 5.2): the (a2, a3) grid of Figs. 10, 11 and the f(Δt),
// f(Δy) studies of Figs. 4, 5, as dicts of NumPy arrays. Parallel, deterministic.
#include "selfalign/analysis/sweep.hpp"

#include <cstdint>
#include <limits>
#include <mutex>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

namespace {

constexpr const char* kSweepArgs = R"doc(
Cells are computed in parallel on `threads` workers (0: all cores; more than the cores are
capped at the cores), each into its own slot, so
the result is identical for any thread count. `progress`, if given, is called as
progress(done, total) as cells complete (from worker threads, one call at a time, holding the
GIL); an exception it raises stops the sweep and is re-raised, and Ctrl-C (KeyboardInterrupt)
stops it with or without a callback. The GIL is released otherwise.)doc";

py::dict family_points(std::vector<FamilyPoint>&& points) {
  const auto n = static_cast<py::ssize_t>(points.size());
  py::array_t<double> period(n), stroke(n), v_bar(n), f(n);
  py::array_t<bool> physical(n);
  py::array_t<std::int32_t> observed(n);
  for (py::ssize_t k = 0; k < n; ++k) {
    const FamilyPoint& p = points[static_cast<std::size_t>(k)];
    period.mutable_data()[k] = p.period;
    stroke.mutable_data()[k] = p.stroke;
    physical.mutable_data()[k] = p.physical;
    observed.mutable_data()[k] = static_cast<std::int32_t>(p.observed);
    v_bar.mutable_data()[k] = p.v_bar;
    f.mutable_data()[k] = p.f;
  }
  py::dict d;
  d["period"] = period, d["stroke"] = stroke, d["physical"] = physical;
  d["observed"] = observed, d["v_bar"] = v_bar, d["f"] = f;
  d["failure"] = failure_array(points, {n});
  return d;
}

void bind_families(py::module_& m) {
  py::class_<ProfileFamily>(m, "ProfileFamily",
                            "A family of table profiles indexed by period Δt and stroke Δy "
                            "(Figs. 4, 5). Abstract.")
      .def("make", &ProfileFamily::make, py::arg("period"), py::arg("stroke"),
           "The member with this period and stroke [-], or None when it does not exist (case 0).")
      .def_property_readonly("name", &ProfileFamily::name, "short family name");
  py::class_<ThreePhaseFamily, ProfileFamily> three(m, "ThreePhaseFamily",
                                                    "Three-phase profiles with fixed "
                                                    "accelerations (a2, a3).");
  three.def(py::init<double, double>(), py::arg("a2"), py::arg("a3"),
            "a2, a3: y2'', y3'' [-], > 0.")
      .def_property_readonly("a2", &ThreePhaseFamily::a2, "y2'' [-]")
      .def_property_readonly("a3", &ThreePhaseFamily::a3, "y3'' [-]")
      .def("__repr__", [](const ThreePhaseFamily& f) {
        return Repr("ThreePhaseFamily")("a2", f.a2())("a3", f.a3()).str();
      });
  def_record(three, [](double a2, double a3) { return ThreePhaseFamily(a2, a3); },
             field("a2", &ThreePhaseFamily::a2), field("a3", &ThreePhaseFamily::a3));
  py::class_<JerkLimitedThreePhaseFamily, ProfileFamily> jerk(
      m, "JerkLimitedThreePhaseFamily",
      "Jerk-limited three-phase profiles (trapezoidal acceleration) with fixed accelerations "
      "(a2, a3) and jerk limit j; make() gives None where no member exists (case 0, e.g. a "
      "jerk too low for the period and stroke).");
  jerk.def(py::init<double, double, double>(), py::arg("a2"), py::arg("a3"), py::arg("jerk"),
           "a2, a3: y2'', y3'' [-], > 0; jerk: j [-], > 0 (inf: the ThreePhaseFamily). Raises "
           "InvalidParameter otherwise.")
      .def_property_readonly("a2", &JerkLimitedThreePhaseFamily::a2, "y2'' [-]")
      .def_property_readonly("a3", &JerkLimitedThreePhaseFamily::a3, "y3'' [-]")
      .def_property_readonly("jerk", &JerkLimitedThreePhaseFamily::jerk, "jerk limit j [-]")
      .def("__repr__", [](const JerkLimitedThreePhaseFamily& f) {
        return Repr("JerkLimitedThreePhaseFamily")("a2", f.a2())("a3", f.a3())("jerk", f.jerk())
            .str();
      });
  def_record(jerk,
             [](double a2, double a3, double j) { return JerkLimitedThreePhaseFamily(a2, a3, j); },
             field("a2", &JerkLimitedThreePhaseFamily::a2),
             field("a3", &JerkLimitedThreePhaseFamily::a3),
             field("jerk", &JerkLimitedThreePhaseFamily::jerk));
  py::class_<ScaledShapeFamily, ProfileFamily> shape(m, "ScaledShapeFamily", R"doc(
One shape of piecewise-constant acceleration (a Fig. 3 style sequence of quadratics), stretched
in time to the period and scaled in amplitude to the stroke: durations scale with Δt,
accelerations with Δy / Δt^2.)doc");
  shape.def(py::init<PiecewisePolynomialProfile>(), py::arg("shape"))
      .def_static("paper_like", &ScaledShapeFamily::paper_like,
                  "The default shape: fractions (0.35, 0.35, 0.30) of the period with "
                  "accelerations (0, -6/7, +1).")
      .def_property_readonly("shape", &ScaledShapeFamily::shape, "the unscaled shape")
      .def("__repr__", [](const ScaledShapeFamily& f) {
        return Repr("ScaledShapeFamily")("segments",
                                         static_cast<long long>(f.shape().segments().size()))
            .str();
      });
  def_record(shape, [](const PiecewisePolynomialProfile& p) { return ScaledShapeFamily(p); },
             field("shape", &ScaledShapeFamily::shape));
  py::class_<ScaledFourierFamily, ProfileFamily> fourier(m, "ScaledFourierFamily", R"doc(
One Fourier shape (Sect. 4.4.2) with its coefficients scaled to the stroke: the members share
the harmonic content and differ in period and amplitude. Their steady states use
the exact smooth-profile solver.)doc");
  fourier
      .def(py::init([](const py::object& cos_coeffs, const py::object& sin_coeffs) {
             return ScaledFourierFamily(to_vector(cos_coeffs, "cos_coeffs"),
                                        to_vector(sin_coeffs, "sin_coeffs"));
           }),
           py::arg("cos_coeffs"), py::arg("sin_coeffs"),
           "Coefficients of y(t) = sum A_k cos(k w t) + B_k sin(k w t), any amplitude.")
      .def_property_readonly(
          "cos_coeffs",
          [](const ScaledFourierFamily& f) { return to_array(std::vector(f.cos_coeffs())); },
          "the shape's cosine coefficients as given")
      .def_property_readonly(
          "sin_coeffs",
          [](const ScaledFourierFamily& f) { return to_array(std::vector(f.sin_coeffs())); },
          "the shape's sine coefficients as given")
      .def("__repr__", [](const ScaledFourierFamily& f) {
        return Repr("ScaledFourierFamily")("order", static_cast<long long>(std::max(
                                                        f.cos_coeffs().size(), f.sin_coeffs().size())))
            .str();
      });
  def_record(fourier,
             [](std::vector<double> c, std::vector<double> s) {
               return ScaledFourierFamily(std::move(c), std::move(s));
             },
             field("cos_coeffs", [](const ScaledFourierFamily& f) { return f.cos_coeffs(); }),
             field("sin_coeffs", [](const ScaledFourierFamily& f) { return f.sin_coeffs(); }));
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "linear_grid", [](double lo, double hi, int n) { return to_array(linear_grid(lo, hi, n)); },
      py::arg("lo"), py::arg("hi"), py::arg("n"),
      "n values from lo to hi inclusive, evenly spaced (n >= 1; n = 1 gives lo); float64.");
  m.def(
      "log_grid", [](double lo, double hi, int n) { return to_array(log_grid(lo, hi, n)); },
      py::arg("lo"), py::arg("hi"), py::arg("n"),
      "n values from lo to hi inclusive, evenly spaced in log (lo, hi > 0); float64.");

  m.def(
      "sweep_accelerations",
      [](double period, double stroke, const py::object& a2_in, const py::object& a3_in,
         const SteadyStateOptions& steady, int threads, const py::object& progress_in,
         const FrictionLaw& law, double jerk, bool closed_form) {
        const std::vector<double> a2 = to_vector(a2_in, "a2"), a3 = to_vector(a3_in, "a3");
        const PythonProgress progress(progress_in);
        SweepOptions options = sweep_options(threads, progress, steady, law, jerk);
        options.closed_form = closed_form;
        acceleration_cells(a2, a3);  // refuses too many cells before the arrays exist
        const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(a2.size()),
                                             static_cast<py::ssize_t>(a3.size())};
        // The workers write each cell straight into the arrays (row-major: k = i * len(a3) + j).
        py::array_t<std::int32_t> predicted(shape), observed(shape);
        py::array_t<double> v_bar(shape), f(shape), x_dot_0s(shape);
        py::array_t<bool> converged(shape);
        std::int32_t *pp = predicted.mutable_data(), *po = observed.mutable_data();
        double *pv = v_bar.mutable_data(), *pf = f.mutable_data(), *px = x_dot_0s.mutable_data();
        bool* pc = converged.mutable_data();
        std::vector<std::pair<std::size_t, std::string>> failures;  // rare: under a mutex
        std::mutex failures_mutex;
        progress.run([&] {
          sweep_accelerations(period, stroke, a2, a3, options,
                              [&](std::size_t k, const AccelerationCell& c) {
                                pp[k] = static_cast<std::int32_t>(c.predicted);
                                po[k] = static_cast<std::int32_t>(c.observed);
                                pv[k] = c.v_bar, pf[k] = c.f, px[k] = c.x_dot_0s;
                                pc[k] = c.converged;
                                if (c.failure.empty()) return;
                                std::lock_guard lock(failures_mutex);
                                failures.emplace_back(k, c.failure);
                              });
        });
        py::dict d;
        d["a2"] = to_array(std::vector(a2)), d["a3"] = to_array(std::vector(a3));
        d["predicted"] = predicted, d["observed"] = observed, d["v_bar"] = v_bar, d["f"] = f;
        d["x_dot_0s"] = x_dot_0s, d["converged"] = converged;
        d["failure"] = sparse_failure_array(failures, shape);
        return d;
      },
      py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"), py::kw_only(),
      py::arg("steady") = SteadyStateOptions{}, py::arg("threads") = 0,
      py::arg("progress") = py::none(), py::arg("law") = FrictionLaw{},
      py::arg("jerk") = std::numeric_limits<double>::infinity(), py::arg("closed_form") = true,
      (std::string(R"doc(
f and the motion case of the three-phase profile over the grid a2 × a3 at fixed (Δt, Δy)
(Figs. 10, 11). Returns a dict of arrays shaped (len(a2), len(a3)) (cell [i, j] is a2[i],
a3[j]): 'predicted', 'observed' (int32 StickSlipCase values: a priori Fig. 8 rules and the
steady period), 'v_bar' (eq. 10), 'f' (eq. 11; +inf for v̄ = 0), 'x_dot_0s'
(float64, NaN for case 0), 'converged' (bool), 'failure' (str: '' for a computed cell, else
why it could not be computed; its numbers are then NaN — one cell never aborts the sweep);
plus the 1-D grids 'a2' and 'a3'.
law: every cell's friction law (FrictionLaw; the paper's by default). jerk: the jerk
limit of every cell's profile [-], > 0 (JerkLimitedThreePhaseProfile; a cell without one is
case 0); inf (the default): the paper's jump accelerations. 'predicted' always applies the
Fig. 8 rules of the jump profile under the paper's law. closed_form: True (the default): a
cell with jump accelerations under a Coulomb law is the closed-form steady state
(three_phase_steady_state, a formula per cell); False: the fixed-point search (steady_state)
on every cell, e.g. to check it. Finite jerk and velocity-dependent laws always search.
Raises InvalidParameter on bad inputs (jerk <= 0 or NaN included).)doc") +
       kSweepArgs)
          .c_str());

  bind_families(m);

  m.def(
      "sweep_period",
      [](const ProfileFamily& family, double stroke, const py::object& periods_in,
         const SteadyStateOptions& steady, int threads, const py::object& progress_in,
         const FrictionLaw& law) {
        const std::vector<double> periods = to_vector(periods_in, "periods");
        const PythonProgress progress(progress_in);
        const SweepOptions options = sweep_options(threads, progress, steady, law);
        return family_points(
            progress.run([&] { return sweep_period(family, stroke, periods, options); }));
      },
      py::arg("family"), py::arg("stroke"), py::arg("periods"), py::kw_only(),
      py::arg("steady") = SteadyStateOptions{}, py::arg("threads") = 0,
      py::arg("progress") = py::none(), py::arg("law") = FrictionLaw{},
      (std::string(R"doc(
f against Δt at fixed Δy (Fig. 4). Returns a dict of 1-D arrays, one entry per period:
'period', 'stroke', 'v_bar' (eq. 10), 'f' (eq. 11) (float64; NaN where the family has no
member), 'physical' (bool), 'observed' (int32 StickSlipCase values), 'failure' (str: '' for a
computed point, else why it could not be computed; v_bar and f are then NaN).
law: every point's friction law (FrictionLaw; the paper's by default).)doc") +
       kSweepArgs)
          .c_str());
  m.def(
      "sweep_stroke",
      [](const ProfileFamily& family, double period, const py::object& strokes_in,
         const SteadyStateOptions& steady, int threads, const py::object& progress_in,
         const FrictionLaw& law) {
        const std::vector<double> strokes = to_vector(strokes_in, "strokes");
        const PythonProgress progress(progress_in);
        const SweepOptions options = sweep_options(threads, progress, steady, law);
        return family_points(
            progress.run([&] { return sweep_stroke(family, period, strokes, options); }));
      },
      py::arg("family"), py::arg("period"), py::arg("strokes"), py::kw_only(),
      py::arg("steady") = SteadyStateOptions{}, py::arg("threads") = 0,
      py::arg("progress") = py::none(), py::arg("law") = FrictionLaw{},
      (std::string(R"doc(
f against Δy at fixed Δt (Fig. 5). Returns the same dict as sweep_period, one entry per
stroke. law: every point's friction law (FrictionLaw; the paper's by default).)doc") +
       kSweepArgs)
          .c_str());
}

}  // namespace selfalign::python
