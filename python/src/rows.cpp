// Queues of 1-D parts (analysis/row.hpp, docs/rows.md): RowPart, RowQueue, and the two
// analyses row_run (a conveying queue: clusters, velocities, throughput) and row_stop (a queue
// stopping at a friction step: end positions, process times, gaps, accumulation, errors).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/error.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxRecordedSamples, kMaxTimeSteps

namespace selfalign::python {

namespace {

// The parts of a queue from a sequence of RowPart (a list, a tuple, ...); TypeError naming
// `name` (or its bad item, name[i]) otherwise.
std::vector<RowPart> to_parts(const py::handle& parts, const std::string& name) {
  if (py::isinstance<py::str>(parts) || py::isinstance<py::bytes>(parts) ||
      !PySequence_Check(parts.ptr()))
    throw py::type_error(name + ": expected a list of RowPart, got " + python_type_name(parts));
  std::vector<RowPart> out;
  const py::sequence items = py::reinterpret_borrow<py::sequence>(parts);
  for (std::size_t i = 0; i < items.size(); ++i)
    out.push_back(argument<RowPart>(items[i], name + "[" + std::to_string(i) + "]", "RowPart"));
  return out;
}

// samples x parts as a 2-D float64 array (a read-only copy).
py::array positions_array(const std::vector<std::vector<double>>& positions) {
  const auto rows = static_cast<py::ssize_t>(positions.size());
  const auto cols = rows ? static_cast<py::ssize_t>(positions.front().size()) : 0;
  py::array_t<double> out({rows, cols});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i)
    for (py::ssize_t j = 0; j < cols; ++j)
      a(i, j) = positions[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return make_readonly(out);
}

// [a, b, ...] as Python source.
template <class T>
std::string numbers_source(const std::vector<T>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    s += (i ? ", " : "") + number_source(static_cast<double>(values[i]));
  return s + "]";
}

std::string part_repr(const RowPart& p) {
  return Repr("RowPart")("length", p.length)("mass", p.mass)
      .raw("law", py::repr(py::cast(p.law)).cast<std::string>())("x", p.x)("v", p.v)
      .str();
}

// The binding's own bounds on what a run returns and costs (the library bounds periods,
// samples and steps separately): a run records up to (periods x samples_per_period + 1) x
// parts positions, at most kMaxRecordedSamples, and Moreau takes up to periods x
// steps_per_period steps, at most kMaxTimeSteps (stopping_run's bound). `name`: "periods" or
// "max_periods". Out-of-range arguments are left to the library's own messages.
void check_run_size(const RowQueue& queue, long long periods, const char* name, Method method,
                    long long steps_per_period, long long samples_per_period) {
  if (periods < 1 || samples_per_period < 1) return;
  const double positions =
      (static_cast<double>(periods) * static_cast<double>(samples_per_period) + 1) *
      static_cast<double>(queue.parts.size());
  if (positions > kMaxRecordedSamples)
    throw InvalidParameter(name, static_cast<double>(periods),
                           "the run may record " + format_number(positions) + " positions ((" +
                               name + " x samples_per_period + 1) x parts); at most 1e7: fewer " +
                               name + " or samples_per_period");
  if (method == Method::time_stepping && steps_per_period >= 1 &&
      static_cast<double>(periods) * static_cast<double>(steps_per_period) > kMaxTimeSteps)
    throw InvalidParameter("steps_per_period", static_cast<double>(steps_per_period),
                           std::string(name) + " x steps_per_period must be at most 1e9 Moreau steps");
}

void bind_parts(py::module_& m) {
  py::class_<RowPart> part(m, "RowPart", R"doc(
One part of a queue (docs/rows.md): its length along the table [-] (> 0), its mass [-] (> 0;
only ratios matter), its friction law with the table (a Coulomb FrictionLaw: static >= kinetic,
no Stribeck or viscous term), and its start: leading edge x [-] and velocity relative to the
table v [-]. Immutable; checked where it is used (row_run, row_stop: InvalidParameter naming
parts[i].length, parts[i].mass, parts[i].law, parts[i].x or parts[i].v).)doc");
  part.def(py::init([](double length, double mass, const FrictionLaw& law, double x, double v) {
             return RowPart{length, mass, law, x, v};
           }),
           py::arg("length") = RowPart{}.length, py::arg("mass") = RowPart{}.mass,
           py::arg("law") = FrictionLaw{}, py::arg("x") = 0.0, py::arg("v") = 0.0,
           "A part of the given length, mass and law, its leading edge at x, moving at v "
           "relative to the table.")
      .def_readonly("length", &RowPart::length, "L: the part's length along the table [-]")
      .def_readonly("mass", &RowPart::mass, "m [-] (only the ratios of a queue's masses matter)")
      .def_readonly("law", &RowPart::law, "its FrictionLaw with the table")
      .def_readonly("x", &RowPart::x, "its leading (front) edge at the start [-]")
      .def_readonly("v", &RowPart::v, "its velocity relative to the table at the start [-]")
      .def("__repr__", &part_repr);
  def_record(part, field("length", &RowPart::length), field("mass", &RowPart::mass),
             field("law", &RowPart::law), field("x", &RowPart::x), field("v", &RowPart::v));

  py::class_<RowQueue> queue(m, "RowQueue", R"doc(
A queue of parts on the table (docs/rows.md): its parts from the rear to the front, each one's
trailing edge x - length at or ahead of the previous one's leading edge x (no overlap;
touching allowed), and Newton's restitution e in [0, 1] between neighbours (0: plastic).
Immutable; checked where it is used (row_run, row_stop: InvalidParameter naming parts,
parts[i].x (overlap) or restitution). row_run and row_stop also take a plain list of RowPart
(restitution 0).)doc");
  queue
      .def(py::init([](const py::object& parts, double restitution) {
             return RowQueue{to_parts(parts, "parts"), restitution};
           }),
           py::arg("parts"), py::arg("restitution") = 0.0,
           "parts: a list (any sequence) of RowPart, rear to front; restitution: e [-]. Raises "
           "TypeError naming parts[i] for an item that is not a RowPart.")
      .def_property_readonly(
          "parts", [](const RowQueue& q) { return q.parts; },
          "the parts, rear to front (a list of RowPart, a copy)")
      .def_readonly("restitution", &RowQueue::restitution,
                    "Newton's restitution e between neighbours [-]")
      .def("__len__", [](const RowQueue& q) { return q.parts.size(); }, "the number of parts")
      .def("__repr__", [](const RowQueue& q) {
        std::string parts = "[";
        for (std::size_t i = 0; i < q.parts.size(); ++i)
          parts += (i ? ", " : "") + part_repr(q.parts[i]);
        return Repr("RowQueue").raw("parts", parts + "]")("restitution", q.restitution).str();
      });
  def_record(queue, field("parts", &RowQueue::parts),
             field("restitution", &RowQueue::restitution));
}

void bind_results(py::module_& m) {
  using R = RowRun;
  py::class_<R> run(m, "RowRun", R"doc(
A conveying queue (row_run): each part at the end, the mean velocities of the last period, the
clusters of touching parts, the throughput, and the sampled trajectories.)doc");
  def_array(run, "x", &R::x, "each part's leading edge at the end [-] (rear to front)");
  def_array(run, "v", &R::v, "each part's velocity relative to the table at the end [-]");
  def_array(run, "mean_velocity", &R::mean_velocity,
            "each part's mean velocity over the last period [-]");
  run.def_readonly("queue_velocity", &R::queue_velocity,
                   "the parts' mean of mean_velocity [-]");
  def_array(run, "clusters", &R::clusters,
            "the sizes of the clusters of touching parts at the end, rear to front (int; exact: "
            "closed contacts; time-stepping: gaps at most 1e-9)");
  run.def_readonly("pitch", &R::pitch,
                   "the mean spacing of leading edges at the start [-]; NaN for one part")
      .def_readonly("throughput_per_period", &R::throughput_per_period,
                    "parts per table period past a point of the table at the queue's velocity "
                    "and pitch: queue_velocity x period / pitch; NaN for one part")
      .def_readonly("collisions", &R::collisions,
                    "collisions between neighbours (the exact solver; 0 for time-stepping)")
      .def_readonly("separations", &R::separations,
                    "separations of touching neighbours (the exact solver; 0 for time-stepping)");
  def_array(run, "times", &R::times, "the sample times [-], from 0");
  run.def_property_readonly(
      "positions", [](const R& r) { return positions_array(r.positions); },
      "every part's leading edge at each sample time [-]: a 2-D float array, samples x parts");
  run.def("__repr__", [](const R& r) {
    return Repr("RowRun")("parts", static_cast<long long>(r.x.size()))(
               "queue_velocity", r.queue_velocity)
        .raw("clusters", numbers_source(r.clusters))("pitch", r.pitch)(
            "throughput_per_period", r.throughput_per_period)("collisions", r.collisions)(
            "separations", r.separations)
        .str();
  });
  def_record(run, field("x", &R::x), field("v", &R::v), field("mean_velocity", &R::mean_velocity),
             field("queue_velocity", &R::queue_velocity), field("clusters", &R::clusters),
             field("pitch", &R::pitch), field("throughput_per_period", &R::throughput_per_period),
             field("collisions", &R::collisions), field("separations", &R::separations),
             field("times", &R::times), field("positions", &R::positions));

  using S = RowStop;
  py::class_<S> stop(m, "RowStop", R"doc(
A queue stopping at a friction step (row_stop): whether and when it stopped, each part's end
position, process time and positioning error, the gaps, whether it accumulated behind the
front part, and the sampled trajectories.)doc");
  stop.def_readonly("stopped", &S::stopped,
                    "no part moved through a whole period: the queue stays (the drive is "
                    "periodic)")
      .def_readonly("stop_time", &S::stop_time,
                    "the end of the last motion [-]; NaN when it did not stop")
      .def_readonly("periods", &S::periods, "periods run (the one that showed the stop included)");
  def_array(stop, "x", &S::x, "each part's leading edge at the end [-] (rear to front)");
  def_array(stop, "process_time", &S::process_time,
            "each part's last motion [-]; NaN for a part that never moved");
  def_array(stop, "gaps", &S::gaps,
            "the spacing at the end: the gap behind each part but the rear one [-] (parts - 1 "
            "values)");
  stop.def_readonly("accumulated", &S::accumulated,
                    "the queue packed behind the front part: every gap at most 1e-9");
  def_array(stop, "error", &S::error,
            "each part's positioning error [-]: x - target, the target the step for the front "
            "part and step - (the lengths of the parts ahead) for the others (packed)");
  stop.def_readonly("collisions", &S::collisions,
                    "collisions between neighbours (the exact solver; 0 for time-stepping)")
      .def_readonly("separations", &S::separations,
                    "separations of touching neighbours (the exact solver; 0 for time-stepping)");
  def_array(stop, "times", &S::times, "the sample times [-], from 0");
  stop.def_property_readonly(
      "positions", [](const S& s) { return positions_array(s.positions); },
      "every part's leading edge at each sample time [-]: a 2-D float array, samples x parts");
  stop.def("__repr__", [](const S& s) {
    return Repr("RowStop")("stopped", s.stopped)("stop_time", s.stop_time)("periods", s.periods)
        .raw("x", numbers_source(s.x))("accumulated", s.accumulated)
        .raw("error", numbers_source(s.error))
        .str();
  });
  def_record(stop, field("stopped", &S::stopped), field("stop_time", &S::stop_time),
             field("periods", &S::periods), field("x", &S::x),
             field("process_time", &S::process_time), field("gaps", &S::gaps),
             field("accumulated", &S::accumulated), field("error", &S::error),
             field("collisions", &S::collisions), field("separations", &S::separations),
             field("times", &S::times), field("positions", &S::positions));
}

void bind_analyses(py::module_& m) {
  m.def(
      "row_run",
      [](const TableProfile& profile, const py::object& queue_in, long long periods,
         std::optional<FrictionField> field, Method method, long long steps_per_period,
         long long samples_per_period) {
        const RowQueue queue = to_row_queue(queue_in);
        check_run_size(queue, periods, "periods", method, steps_per_period, samples_per_period);
        const py::gil_scoped_release release;
        return row_run(profile, queue, field ? &*field : nullptr, periods,
                       RowSolver{method, steps_per_period}, samples_per_period);
      },
      py::arg("profile"), py::arg("queue"), py::arg("periods"), py::arg("field") = py::none(),
      py::kw_only(), py::arg("method") = Method::exact, py::arg("steps_per_period") = 2000,
      py::arg("samples_per_period") = 20, R"doc(
A conveying queue (docs/rows.md): the queue (a RowQueue, or a list of RowPart) on the table
moving as `profile` (along the parts), the friction level `field` along the table (a
FrictionField; None: uniform level 1), for `periods` (>= 1) periods from the parts' start,
sampled `samples_per_period` (>= 1) times a period. Returns RowRun: each part's end x and v,
its mean velocity over the last period and their mean queue_velocity, the clusters of touching
parts, the pitch and throughput_per_period, and the trajectories (times, positions).
method="exact" (the default: the exact row solver, for a piecewise-constant table acceleration,
e.g. ThreePhaseProfile, and a uniform level or a field of steps) or "time-stepping" (the
contact core's Moreau step with part contacts, `steps_per_period` steps a period; any profile
and field). Raises InvalidParameter naming the
bad argument: parts, parts[i].length, parts[i].mass, parts[i].law (not Coulomb), parts[i].x
(overlapping parts), parts[i].v, restitution, periods, samples_per_period, method or
steps_per_period; also when the run would record more than 1e7 positions ((periods x
samples_per_period + 1) x parts) or take more than 1e9 Moreau steps. Runs without the GIL.)doc");

  m.def(
      "row_stop",
      [](const TableProfile& profile, const py::object& queue_in, const FrictionField& field,
         long long max_periods, Method method, long long steps_per_period,
         long long samples_per_period) {
        const RowQueue queue = to_row_queue(queue_in);
        check_run_size(queue, max_periods, "max_periods", method, steps_per_period,
                       samples_per_period);
        const py::gil_scoped_release release;
        return row_stop(profile, queue, field, max_periods, RowSolver{method, steps_per_period},
                        samples_per_period);
      },
      py::arg("profile"), py::arg("queue"), py::arg("field"), py::arg("max_periods"),
      py::kw_only(), py::arg("method") = Method::exact, py::arg("steps_per_period") = 2000,
      py::arg("samples_per_period") = 20, R"doc(
A queue stopping at a friction step (docs/rows.md): the queue (a RowQueue, or a list of
RowPart) on the table moving as `profile`, the friction level `field` along the table (a
FrictionField; its first node is the step the positioning errors refer to, e.g.
FrictionField.steps([1.5], [1.0, 4.0])), run period by period until no part moves through a
whole period (then it never moves again: the drive is periodic) or `max_periods` (>= 1)
periods, sampled `samples_per_period` times a period. Returns RowStop: stopped, stop_time (NaN
when it did not stop: a result, not an error), periods, each part's end x, process_time (NaN:
it never moved) and error, the gaps, accumulated, and the trajectories (times, positions).
method="exact" (the default: the exact row solver; a piecewise-constant table acceleration and
a field of steps) or "time-stepping" (Moreau, `steps_per_period` steps a period). Raises
InvalidParameter naming the bad argument (as row_run, and max_periods), also when max_periods
would allow more than 1e7 recorded positions ((max_periods x samples_per_period + 1) x parts)
or 1e9 Moreau steps. Runs without the GIL; max_periods bounds its work.)doc");
}

}  // namespace

// A row_run/row_stop `queue` argument: a RowQueue, or a list of RowPart (restitution 0).
RowQueue to_row_queue(const py::handle& queue) {
  if (py::isinstance<RowQueue>(queue)) return queue.cast<RowQueue>();
  if (py::isinstance<py::str>(queue) || py::isinstance<py::bytes>(queue) ||
      !PySequence_Check(queue.ptr()))
    throw py::type_error("queue: expected a RowQueue or a list of RowPart, got " +
                         python_type_name(queue));
  return RowQueue{to_parts(queue, "queue"), 0.0};
}

void bind_rows(py::module_& m) {
  bind_parts(m);
  bind_results(m);
  bind_analyses(m);
}

}  // namespace selfalign::python
