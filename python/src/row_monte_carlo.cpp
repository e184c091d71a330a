// Monte Carlo of a queue stopping at the friction step (robust/row_monte_carlo.hpp,
// docs/rows.md section 11): row_monte_carlo and its result RowMonteCarloResult (NumPy arrays, runs x
// parts, NaN where a run has no value).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/error.hpp"
#include "selfalign/robust/row_monte_carlo.hpp"

namespace selfalign::python {

namespace {

using R = RowMonteCarloResult;

// A runs x parts read-only view of a run-major column of `self`.
template <class T>
py::array table_view(const std::vector<T>& values, const R& r, py::handle self) {
  return readonly_view(values, self).attr("reshape")(r.runs, r.parts);
}

py::array flags_table(const std::vector<std::uint8_t>& values, const R& r, py::handle self) {
  return readonly_bool_view(values, self).attr("reshape")(r.runs, r.parts);
}

// One field of every part's summary as a float array (parts values).
template <class T>
py::array per_part(const R& r, T RowPartSummary::*member) {
  std::vector<T> out;
  for (const RowPartSummary& s : r.summary) out.push_back(s.*member);
  return make_readonly(to_array(std::move(out)));
}

// The result from its per-run columns (unpickling): sizes checked, summary recomputed.
R from_columns(std::uint64_t seed, std::uint64_t first_run, double tolerance, double step,
               int runs, int parts, std::vector<double> inputs, std::vector<std::uint8_t> queue_stopped,
               std::vector<std::uint8_t> accumulated, std::vector<std::uint8_t> stopped,
               std::vector<double> end, std::vector<double> error, std::vector<double> time) {
  const auto n = static_cast<std::size_t>(runs < 0 ? 0 : runs),
             m = static_cast<std::size_t>(parts < 0 ? 0 : parts);
  if (runs < 0 || parts < 0 || inputs.size() != n * m * kUncertainInputs ||
      queue_stopped.size() != n || accumulated.size() != n || stopped.size() != n * m ||
      end.size() != n * m || error.size() != n * m || time.size() != n * m)
    throw InvalidParameter("state", "RowMonteCarloResult", "columns of inconsistent sizes");
  R r;
  r.seed = seed, r.first_run = first_run, r.tolerance = tolerance, r.step_position = step;
  r.runs = runs, r.parts = parts;
  r.inputs = std::move(inputs);
  r.queue_stopped = std::move(queue_stopped);
  r.accumulated = std::move(accumulated);
  r.stopped = std::move(stopped);
  r.end_position = std::move(end);
  r.error = std::move(error);
  r.process_time = std::move(time);
  summarize(r);
  return r;
}

void bind_result(py::module_& m) {
  py::class_<R> c(m, "RowMonteCarloResult", R"doc(
The runs of a queue's Monte Carlo (row_monte_carlo, docs/rows.md section 11). Per run and part
(2-D arrays, runs x parts, rear part first): end_position, error (x - the packed target at the
nominal step) and process_time (the part's last motion), NaN where the queue did not stop (and
process_time NaN for a part that never moved); stopped (bool: the queue stopped). Per run:
queue_stopped, accumulated. inputs {name: runs x parts array}: mu as the factor on the part's
coefficients, width NaN (not drawn). Per part (arrays of parts values): within, p_within and its
95% Wilson interval, means and standard deviations over the stopped runs (NaN where none).)doc");
  c.def_readonly("seed", &R::seed, "seed of the draws")
      .def_readonly("first_run", &R::first_run, "index of the first run")
      .def_readonly("tolerance", &R::tolerance, "allowed |error| [-]")
      .def_readonly("step_position", &R::step_position, "the nominal step the errors refer to [-]")
      .def_readonly("runs", &R::runs, "number of runs")
      .def_readonly("parts", &R::parts, "number of parts")
      .def_property_readonly(
          "inputs",
          [](py::object self) {
            const R& r = self.cast<const R&>();
            py::dict d;
            const py::array all = readonly_view(r.inputs, self).attr("reshape")(
                r.runs, r.parts, static_cast<int>(kUncertainInputs));
            for (std::size_t k = 0; k < kUncertainInputs; ++k)
              d[uncertain_inputs()[k].name] = all[py::make_tuple(py::ellipsis(), py::int_(k))];
            return d;
          },
          "{name: float64 array runs x parts}: the inputs each part ran with")
      .def_property_readonly("queue_stopped", [](py::object self) {
            return readonly_bool_view(self.cast<const R&>().queue_stopped, self); },
          "bool per run: the queue stopped (no part moved through a whole period)")
      .def_property_readonly("accumulated", [](py::object self) {
            return readonly_bool_view(self.cast<const R&>().accumulated, self); },
          "bool per run: it stopped packed behind the front part")
      .def_property_readonly("stopped", [](py::object self) {
            const R& r = self.cast<const R&>();
            return flags_table(r.stopped, r, self); },
          "bool, runs x parts: the part stopped for good (the queue stopped)")
      .def_property_readonly("end_position", [](py::object self) {
            const R& r = self.cast<const R&>();
            return table_view(r.end_position, r, self); },
          "runs x parts [-]; NaN where the queue did not stop")
      .def_property_readonly("error", [](py::object self) {
            const R& r = self.cast<const R&>();
            return table_view(r.error, r, self); },
          "runs x parts: x - target at the nominal step [-]; NaN where the queue did not stop")
      .def_property_readonly("process_time", [](py::object self) {
            const R& r = self.cast<const R&>();
            return table_view(r.process_time, r, self); },
          "runs x parts: the part's last motion [-]; NaN where the queue did not stop or the "
          "part never moved")
      .def_readonly("queue_stops", &R::queue_stops, "runs where the queue stopped")
      .def_readonly("all_within", &R::all_within, "runs where every part ended within the tolerance")
      .def_readonly("p_stop", &R::p_stop, "queue_stops / runs")
      .def_readonly("p_all_within", &R::p_all_within, "all_within / runs")
      .def_readonly("p_all_within_low", &R::p_all_within_low, "95% Wilson lower bound")
      .def_readonly("p_all_within_high", &R::p_all_within_high, "95% Wilson upper bound")
      .def_property_readonly("within", [](const R& r) { return per_part(r, &RowPartSummary::within); },
                             "per part: runs that stopped with |error| <= tolerance (int)")
      .def_property_readonly("p_within", [](const R& r) { return per_part(r, &RowPartSummary::p_within); },
                             "per part: within / runs")
      .def_property_readonly("p_within_low", [](const R& r) { return per_part(r, &RowPartSummary::p_within_low); },
                             "per part: 95% Wilson lower bound of p_within")
      .def_property_readonly("p_within_high", [](const R& r) { return per_part(r, &RowPartSummary::p_within_high); },
                             "per part: 95% Wilson upper bound of p_within")
      .def_property_readonly("end_mean", [](const R& r) { return per_part(r, &RowPartSummary::end_mean); },
                             "per part: mean end position over the stopped runs [-]")
      .def_property_readonly("end_sd", [](const R& r) { return per_part(r, &RowPartSummary::end_sd); },
                             "per part: its standard deviation (n - 1) [-]")
      .def_property_readonly("error_mean", [](const R& r) { return per_part(r, &RowPartSummary::error_mean); },
                             "per part: mean positioning error [-]")
      .def_property_readonly("error_sd", [](const R& r) { return per_part(r, &RowPartSummary::error_sd); },
                             "per part: its standard deviation (n - 1) [-]")
      .def_property_readonly("process_time_mean", [](const R& r) { return per_part(r, &RowPartSummary::process_time_mean); },
                             "per part: mean last motion over the stopped runs where it moved [-]")
      .def_property_readonly("process_time_sd", [](const R& r) { return per_part(r, &RowPartSummary::process_time_sd); },
                             "per part: its standard deviation (n - 1) [-]")
      .def("end_position_quantile", &row_end_position_quantile, py::arg("part"), py::arg("q"),
           "the q-quantile of the part's end position over the stopped runs (NaN if none)")
      .def("error_quantile", &row_error_quantile, py::arg("part"), py::arg("q"),
           "the q-quantile of the part's positioning error over the stopped runs")
      .def("process_time_quantile", &row_process_time_quantile, py::arg("part"), py::arg("q"),
           "the q-quantile of the part's process time over all runs (not stopped: +inf)")
      .def("__repr__", [](const R& r) {
        return Repr("RowMonteCarloResult")("runs", r.runs)("parts", r.parts)("p_stop", r.p_stop)(
                   "p_all_within", r.p_all_within)
            .str();
      });
  def_record(c, &from_columns, field("seed", &R::seed), field("first_run", &R::first_run),
             field("tolerance", &R::tolerance), field("step_position", &R::step_position),
             field("runs", &R::runs), field("parts", &R::parts), field("inputs", &R::inputs),
             field("queue_stopped", &R::queue_stopped), field("accumulated", &R::accumulated),
             field("stopped", &R::stopped), field("end_position", &R::end_position),
             field("error", &R::error), field("process_time", &R::process_time));
}

void bind_study(py::module_& m) {
  m.def(
      "row_monte_carlo",
      [](const ThreePhaseProfile& profile, const py::object& queue_in, double step_position,
         double c_mu, const ProcessUncertainty& u, int runs, std::uint64_t seed,
         std::uint64_t first_run, long long max_periods, double tolerance, Method method,
         long long steps_per_period, int threads, const py::object& progress_in) {
        RowProcess p;
        p.table = profile.parameters();
        p.step_position = step_position;
        p.c_mu = c_mu;
        p.queue = to_row_queue(queue_in);
        RowMonteCarloOptions o;
        o.runs = runs, o.seed = seed, o.first_run = first_run, o.max_periods = max_periods;
        o.tolerance = tolerance, o.solver = {method, steps_per_period}, o.threads = threads;
        const PythonProgress progress(progress_in);
        o.progress = progress.callback();
        return progress.run([&] { return row_monte_carlo(p, u, o); });
      },
      py::arg("profile"), py::arg("queue"), py::arg("step_position"), py::arg("c_mu"),
      py::arg("uncertainty"), py::kw_only(), py::arg("runs") = 1000, py::arg("seed") = 1,
      py::arg("first_run") = 0, py::arg("max_periods") = 1000, py::arg("tolerance") = 0.01,
      py::arg("method") = Method::exact, py::arg("steps_per_period") = 2000,
      py::arg("threads") = 0, py::arg("progress") = py::none(), R"doc(
Monte Carlo of a queue stopping at the friction step (docs/rows.md section 11): the queue (a
RowQueue or a list of RowPart) on the three-phase table `profile`, the step from level 1 to
c_mu at step_position, under `uncertainty` (ProcessUncertainty, the model of monte_carlo): mu
and static_ratio drawn per part, c_mu, x_mu_offset, amplitude and period_factor per run, width
refused. Run r (first_run <= r < first_run + runs) draws from (seed, r) and runs row_stop.
Returns RowMonteCarloResult (NumPy arrays); the same for any `threads`. Raises InvalidParameter
naming the bad argument (runs, max_periods, tolerance, width.uncertain, an input's end of its
draws, the queue's parts[i]...). Runs without the GIL.)doc");
}

}  // namespace

void bind_row_monte_carlo(py::module_& m) {
  bind_result(m);
  bind_study(m);
}

}  // namespace selfalign::python
