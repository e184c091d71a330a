// identify (identify/identification.hpp, issue 25) for Python: measured runs (paths or dicts of
// columns) and model configs (dicts) in, an Identification with NumPy arrays out.

#include "selfalign/identify/identification.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/identification_report.hpp"
#include "selfalign/io/measured_motion.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign::python {
namespace {

// A run: a path (read_measured_motion) or a dict with float arrays "t", "x" (SI; "source").
MeasuredMotion measured_of(const py::handle& item, std::size_t index) {
  if (py::isinstance<py::str>(item) || py::hasattr(item, "__fspath__"))
    return read_measured_motion(py::str(py::module_::import("os").attr("fspath")(item)));
  if (!py::isinstance<py::dict>(item))
    throw py::type_error("data[" + std::to_string(index) +
                         "]: expected a path or a dict with arrays 't' and 'x'");
  const py::dict d = py::reinterpret_borrow<py::dict>(item);
  MeasuredMotion m;
  m.source = d.contains("source") ? py::str(d["source"]).cast<std::string>()
                                  : "data[" + std::to_string(index) + "]";
  if (!d.contains("t") || !d.contains("x"))
    throw InvalidParameter(m.source, "a dict", "needs arrays 't' [s] and 'x' [m]");
  m.t = to_vector(d["t"], "t");
  m.x = to_vector(d["x"], "x");
  if (m.t.size() != m.x.size())
    throw InvalidParameter(m.source + " x", static_cast<double>(m.x.size()),
                           "must have as many samples as t (" + std::to_string(m.t.size()) + ")");
  for (std::size_t i = 0; i < m.t.size(); ++i) {
    if (!std::isfinite(m.t[i]) || !std::isfinite(m.x[i]))
      throw InvalidParameter(m.source + " sample " + std::to_string(i), "nan",
                             "t and x must be finite");
    if (i > 0 && !(m.t[i] > m.t[i - 1]))
      throw InvalidParameter(m.source + " t[" + std::to_string(i) + "]", m.t[i],
                             "must be > t[" + std::to_string(i - 1) + "] = " +
                                 format_number(m.t[i - 1]) + " (time strictly increasing)");
    m.line.push_back(i);
  }
  return m;
}

py::array matrix(const std::vector<double>& m, std::size_t n) {
  py::array_t<double> a({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(n)});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      v(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) =
          m.size() == n * n ? m[i * n + j] : std::nan("");
  return a;
}

template <class F>
py::array column(const Identification& r, F get) {
  std::vector<double> v;
  for (const IdentifiedParameter& p : r.parameters) v.push_back(get(p));
  return to_array(std::move(v));
}

}  // namespace

void bind_identification(py::module_& m) {
  py::class_<Identification> c(m, "Identification", R"doc(
The result of identify() (C++ selfalign::Identification; docs/identification.md). Per free
parameter, in the order given (time_offset excluded: it is per run, in `runs`): names,
estimates, standard_errors, intervals (n x 2, Wald at `confidence`), profile_intervals (n x 2,
NaN where not profiled or beyond the grid), identifiable (bool) and reasons ('' when
identifiable). Absent values are NaN. covariance and correlation (n x n; NaN rows and columns
for a parameter that is not identifiable). runs: a list of dicts per measured run with arrays
t, x_measured, x_fitted, residual [SI, or the config's units], window (int), stick (bool) and
source, time_offset, time_offset_standard_error, rms. profiles: dicts name, values, rss.
sigma (residual sd), rss, max_abs_residual, samples, windows, estimated, iterations,
converged, termination, global_best_rss, global_evaluations, warnings. report() is the JSON
report as a dict; uncertainty_text(mu) the uncertainty file (TOML) for design_robust /
`design --robust --uncertainty-file`.)doc");
  c.def_property_readonly("names", [](const Identification& r) {
       std::vector<std::string> n;
       for (const IdentifiedParameter& p : r.parameters) n.push_back(p.name);
       return n;
     }, "free parameter names, in the order given (time_offset excluded)")
      .def_property_readonly("estimates", [](const Identification& r) {
        return column(r, [](const IdentifiedParameter& p) { return p.estimate; });
      }, "estimates; NaN where not identifiable")
      .def_property_readonly("initial", [](const Identification& r) {
        return column(r, [](const IdentifiedParameter& p) { return p.initial; });
      }, "the values the local stage started from (config or global stage)")
      .def_property_readonly("standard_errors", [](const Identification& r) {
        return column(r, [](const IdentifiedParameter& p) { return p.standard_error; });
      }, "standard errors; NaN where not identifiable")
      .def_property_readonly("intervals", [](const Identification& r) {
        py::array_t<double> a({static_cast<py::ssize_t>(r.parameters.size()), py::ssize_t{2}});
        auto v = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < r.parameters.size(); ++i)
          v(static_cast<py::ssize_t>(i), 0) = r.parameters[i].lower,
                                        v(static_cast<py::ssize_t>(i), 1) = r.parameters[i].upper;
        return a;
      }, "n x 2 Wald intervals estimate -+ z se at the confidence asked")
      .def_property_readonly("profile_intervals", [](const Identification& r) {
        py::array_t<double> a({static_cast<py::ssize_t>(r.parameters.size()), py::ssize_t{2}});
        auto v = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < r.parameters.size(); ++i)
          v(static_cast<py::ssize_t>(i), 0) = r.parameters[i].profile_lower,
                                        v(static_cast<py::ssize_t>(i), 1) =
                                            r.parameters[i].profile_upper;
        return a;
      }, "n x 2 profile-likelihood intervals; NaN where not profiled or beyond the grid")
      .def_property_readonly("identifiable", [](const Identification& r) {
        py::array_t<bool> a(static_cast<py::ssize_t>(r.parameters.size()));
        for (std::size_t i = 0; i < r.parameters.size(); ++i)
          a.mutable_at(static_cast<py::ssize_t>(i)) = r.parameters[i].identifiable;
        return a;
      }, "bool per parameter")
      .def_property_readonly("reasons", [](const Identification& r) {
        std::vector<std::string> n;
        for (const IdentifiedParameter& p : r.parameters) n.push_back(p.reason);
        return n;
      }, "why a parameter is not identifiable ('' when it is)")
      .def_property_readonly("covariance", [](const Identification& r) {
        return matrix(r.covariance, r.parameters.size());
      }, "n x n covariance; NaN rows/columns where not identifiable")
      .def_property_readonly("correlation", [](const Identification& r) {
        return matrix(r.correlation, r.parameters.size());
      }, "n x n correlation; unit diagonal")
      .def_property_readonly("runs", [](const Identification& r) {
        py::list out;
        for (const FittedRun& f : r.runs) {
          py::dict d;
          d["source"] = f.source;
          d["t"] = to_array(std::vector<double>(f.t));
          d["x_measured"] = to_array(std::vector<double>(f.x_measured));
          d["x_fitted"] = to_array(std::vector<double>(f.x_fitted));
          d["residual"] = to_array(std::vector<double>(f.residual));
          d["window"] = to_array(std::vector<std::int64_t>(f.window.begin(), f.window.end()));
          py::array_t<bool> stick(static_cast<py::ssize_t>(f.stick.size()));
          for (std::size_t i = 0; i < f.stick.size(); ++i)
            stick.mutable_at(static_cast<py::ssize_t>(i)) = f.stick[i] != 0;
          d["stick"] = stick;
          d["time_offset"] = f.time_offset;
          d["time_offset_standard_error"] = f.time_offset_standard_error;
          d["rms"] = f.rms;
          out.append(d);
        }
        return out;
      }, "per run: dict of t, x_measured, x_fitted, residual, window, stick arrays and source, time_offset, time_offset_standard_error, rms")
      .def_property_readonly("profiles", [](const Identification& r) {
        py::list out;
        for (const ProfileLikelihood& p : r.profiles) {
          py::dict d;
          d["name"] = p.name;
          d["values"] = to_array(std::vector<double>(p.values));
          d["rss"] = to_array(std::vector<double>(p.rss));
          out.append(d);
        }
        return out;
      }, "per profiled parameter: dict of name, values, rss")
      .def_readonly("sigma", &Identification::sigma, "residual sd [m]")
      .def_readonly("rss", &Identification::rss, "sum of squared residuals [m^2]")
      .def_readonly("max_abs_residual", &Identification::max_abs_residual, "[m]")
      .def_readonly("samples", &Identification::samples, "residuals (samples), all runs")
      .def_readonly("windows", &Identification::windows, "shooting windows, all runs")
      .def_readonly("estimated", &Identification::estimated,
                    "parameters estimated: free + offsets + 2 per window")
      .def_readonly("iterations", &Identification::iterations, "Levenberg-Marquardt iterations of the kept fit")
      .def_readonly("converged", &Identification::converged, "whether the kept local stage converged")
      .def_readonly("termination", &Identification::termination, "Ceres' termination message")
      .def_readonly("global_best_rss", &Identification::global_best_rss, "best RSS of the global stage (NaN when skipped) [m^2]")
      .def_readonly("global_evaluations", &Identification::global_evaluations, "passes the global stage used")
      .def_readonly("warnings", &Identification::warnings, "plain-text warnings (identifiability, bounds, convergence)")
      .def(
          "report",
          [](const Identification& r) {
            return py::module_::import("json").attr("loads")(identification_json(r).dump());
          },
          "the JSON report as a dict (null -> None)")
      .def(
          "uncertainty_text",
          [](const Identification& r, double mu) { return identification_uncertainty(r, mu); },
          py::arg("mu"),
          "the uncertainty file (TOML) of the identified inputs; mu: the config's mu, used for "
          "static_ratio when mu is not free")
      .def("__repr__", [](const Identification& r) {
        std::string s = "Identification(";
        for (std::size_t i = 0; i < r.parameters.size(); ++i)
          s += (i ? ", " : "") + r.parameters[i].name + "=" +
               (r.parameters[i].identifiable
                    ? format_number(r.parameters[i].estimate) + "+-" +
                          format_number(r.parameters[i].standard_error)
                    : std::string("not identifiable"));
        return s + ", sigma=" + format_number(r.sigma) + ")";
      });

  m.def(
      "identify",
      [](const py::object& data, const py::object& config, const std::vector<std::string>& free,
         const std::map<std::string, std::pair<double, double>>& bounds, double window_periods,
         const std::string& loss, double loss_scale, int starts, int global_evaluations,
         int max_iterations, const py::object& profile, int profile_points, double confidence,
         int threads) {
        std::vector<py::object> items;
        if (py::isinstance<py::list>(data) || py::isinstance<py::tuple>(data))
          for (const py::handle& h : data) items.push_back(py::reinterpret_borrow<py::object>(h));
        else
          items.push_back(data);
        std::vector<py::dict> configs;
        if (py::isinstance<py::dict>(config)) {
          configs.assign(items.size(), py::reinterpret_borrow<py::dict>(config));
        } else {
          for (const py::handle& h : config) configs.push_back(py::reinterpret_borrow<py::dict>(h));
          if (configs.size() != items.size())
            throw InvalidParameter("config", std::to_string(configs.size()) + " configs",
                                   "give one dict, or one per run (" +
                                       std::to_string(items.size()) + ")");
        }
        std::vector<IdentificationRun> runs;
        for (std::size_t i = 0; i < items.size(); ++i)
          runs.push_back({measured_of(items[i], i), config_of(configs[i])});
        IdentificationOptions o;
        o.free = free;
        for (const auto& [name, b] : bounds) o.bounds[name] = {b.first, b.second};
        o.window_periods = window_periods;
        if (loss == "squared")
          o.loss = SquaredLoss{};
        else if (loss == "huber")
          o.loss = HuberLoss{loss_scale};
        else if (loss == "cauchy")
          o.loss = CauchyLoss{loss_scale};
        else
          throw InvalidParameter("loss", loss, "must be squared, huber or cauchy");
        o.starts = starts;
        o.global_evaluations = global_evaluations;
        o.max_iterations = max_iterations;
        if (profile.is_none()) {
          for (const std::string& n : free)
            if (n == "mu" || n == "mu_static") o.profile.push_back(n);
        } else {
          o.profile = profile.cast<std::vector<std::string>>();
        }
        o.profile_points = profile_points;
        o.confidence = confidence;
        o.threads = threads;
        const py::gil_scoped_release release;
        return identify(runs, o);
      },
      py::arg("data"), py::arg("config"), py::arg("free"), py::kw_only(),
      py::arg("bounds") = std::map<std::string, std::pair<double, double>>{},
      py::arg("window_periods") = 2.0, py::arg("loss") = "squared", py::arg("loss_scale") = 1.0,
      py::arg("starts") = 16, py::arg("global_evaluations") = 4000,
      py::arg("max_iterations") = 100, py::arg("profile") = py::none(),
      py::arg("profile_points") = 13, py::arg("confidence") = 0.95, py::arg("threads") = 2,
      R"doc(
Friction identified from measured motion (C++ identify, docs/identification.md): the free
parameters of the model fitted to measured positions by least squares with multiple shooting
(each window of `window_periods` table periods restarts from its own estimated state), a global
stage (NLopt MLSL, `starts` low-discrepancy points, `global_evaluations` passes of
position-reset shooting; starts=0 skips it) and Ceres' Levenberg-Marquardt with the Schur
complement over the window states.

data: a path (read_measured_motion), a dict with arrays 't' [s] and 'x' [m] (optional
'source'), or a list of them (runs fitted together). config: a dict of config keys (as
model_parameters takes), or one per run (different drive settings). free: names of the
model's parameter view (model_parameters) and 'time_offset' (the data's clock against the
model's, one per run). bounds: {name: (lower, upper)}, default the config's value +-30 %.
loss: 'squared', 'huber' or 'cauchy' with loss_scale [m]. profile: names whose profile
likelihood is computed (default mu_static and mu when free; [] for none).
Returns an Identification. Raises InvalidParameter naming the parameter or the file: a name
that is not a parameter of the model, fewer samples than estimated parameters, bad options.)doc");
}

}  // namespace selfalign::python
