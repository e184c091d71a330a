// Positioning accuracy (Sect. 7.1, eq. 39) and the Fig. 17 surfaces.
#include "selfalign/analysis/positioning.hpp"

#include <cstdint>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"

namespace selfalign::python {

namespace {

void bind_positioning_options(py::module_& m) {
  const PositioningOptions d;
  using O = PositioningOptions;
  py::class_<O> cls(m, "PositioningOptions", "Options of positioning_accuracy().");
  cls
      .def(py::init([](int entries, const StoppingOptions& stopping, bool stop_at_first_failure,
                       const SteadyStateOptions& steady) {
             return PositioningOptions{entries, stopping, stop_at_first_failure, steady};
           }),
           py::kw_only(), py::arg("entries") = d.entries, py::arg("stopping") = d.stopping,
           py::arg("stop_at_first_failure") = d.stop_at_first_failure, py::arg("steady") = d.steady)
      .def_readwrite("entries", &PositioningOptions::entries,
                     "number N of steady-state entries, >= 1")
      .def_readwrite("stopping", &PositioningOptions::stopping, "per entry")
      .def_readwrite("stop_at_first_failure", &PositioningOptions::stop_at_first_failure,
                     "skip the remaining entries once one does not stop (Δx_d is then undefined)")
      .def_readwrite("steady", &PositioningOptions::steady, "the steady-state search")
      .def("__repr__", [](const PositioningOptions& o) {
        return Repr("PositioningOptions")("entries", o.entries)
            .raw("stopping", py::repr(py::cast(o.stopping)))("stop_at_first_failure",
                                                             o.stop_at_first_failure)
            .raw("steady", py::repr(py::cast(o.steady)))
            .str();
      });
  def_record(cls, field("entries", &O::entries), field("stopping", &O::stopping),
             field("stop_at_first_failure", &O::stop_at_first_failure),
             field("steady", &O::steady));
}

void bind_accuracy(py::module_& m) {
  py::class_<PositioningAccuracy> cls(m, "PositioningAccuracy", R"doc(
Sect. 7.1: N steady-state entries x_0s ∈ [-v̄Δt, 0] into the transition region placed at
x_mu = Δx, each stopped by a stopping run; then (eq. 39)
  Δx_d = (Δx_overshoot,max - Δx_overshoot,min) / 2,   x_d = x_mu + Δx_overshoot,min + Δx_d.)doc");
  cls.def_readonly("reaches", &PositioningAccuracy::reaches,
                   "False when v̄ <= 0: the object never walks into the region")
      .def_readonly("steady", &PositioningAccuracy::steady,
                    "the steady state on the low-friction table")
      .def_readonly("x_mu", &PositioningAccuracy::x_mu,
                    "= Δx, the largest displacement in one steady period [-]")
      .def_readonly("x_stick_min", &PositioningAccuracy::x_stick_min, "eq. (41) [-]");
  def_array(cls, "entries", &PositioningAccuracy::entries, "x_0s of each entry [-]");
  cls.def_property_readonly(
         "runs",
         [](const py::object& self) {
           py::list out;
           for (const StoppingRun& r : self.cast<const PositioningAccuracy&>().runs) out.append(r);
           return out;
         },
         "per entry: the StoppingRun (copies)")
      .def_property_readonly(
          "end_positions",
          [](const PositioningAccuracy& a) {
            std::vector<double> end;
            for (const StoppingRun& r : a.runs) end.push_back(r.end_position);
            return to_array(std::move(end));
          },
          "per entry: where the object stops [-] (float64)")
      .def_readonly("overshoot_min", &PositioningAccuracy::overshoot_min, "min end - x_mu [-]")
      .def_readonly("overshoot_max", &PositioningAccuracy::overshoot_max, "max end - x_mu [-]")
      .def_readonly("dx_d", &PositioningAccuracy::dx_d, "eq. (39) [-]")
      .def_readonly("x_d", &PositioningAccuracy::x_d, "desired end position [-]")
      .def_readonly("accumulating_entries", &PositioningAccuracy::accumulating_entries,
                    "entries that end by accumulation")
      .def_readonly("accumulates", &PositioningAccuracy::accumulates,
                    "every entry accumulates to x_stick,min")
      .def_readonly("all_stopped", &PositioningAccuracy::all_stopped,
                    "every entry stopped (none hit max_periods)")
      .def("__repr__", [](const PositioningAccuracy& a) {
        return Repr("PositioningAccuracy")("reaches", a.reaches)("x_mu", a.x_mu)(
                   "x_stick_min", a.x_stick_min)("dx_d", a.dx_d)("x_d", a.x_d)(
                   "accumulates", a.accumulates)("all_stopped", a.all_stopped)
            .str();
      });
  using A = PositioningAccuracy;
  def_record(cls, field("reaches", &A::reaches), field("steady", &A::steady),
             field("x_mu", &A::x_mu), field("x_stick_min", &A::x_stick_min),
             field("entries", &A::entries), field("runs", &A::runs),
             field("overshoot_min", &A::overshoot_min), field("overshoot_max", &A::overshoot_max),
             field("dx_d", &A::dx_d), field("x_d", &A::x_d),
             field("accumulating_entries", &A::accumulating_entries),
             field("accumulates", &A::accumulates), field("all_stopped", &A::all_stopped));

  m.def(
      "positioning_accuracy",
      [](const TableProfile& profile, double width, double c_mu, const PositioningOptions& o,
         const FrictionLaw& law) { return positioning_accuracy(profile, law, width, c_mu, o); },
      py::arg("profile"), py::arg("width"), py::arg("c_mu"),
      py::arg("options") = PositioningOptions{}, py::kw_only(), py::arg("law") = FrictionLaw{},
      py::call_guard<py::gil_scoped_release>(), R"doc(
Sect. 7.1 for a piecewise-constant or piecewise-linear (finite-jerk) profile on a two-region
table of width w [-] and ratio c_mu [-] (x_mu is placed at Δx), under the FrictionLaw
`law` (the paper's by default). Raises InvalidParameter on bad inputs. Runs without the
GIL.)doc");
  m.def(
      "positioning_accuracy",
      [](const TableProfile& profile, const FrictionMap& friction, const PositioningOptions& o,
         const FrictionLaw& law) { return positioning_accuracy(profile, law, friction, o); },
      py::arg("profile"), py::arg("friction"), py::arg("options") = PositioningOptions{},
      py::kw_only(), py::arg("law") = FrictionLaw{}, py::call_guard<py::gil_scoped_release>(),
      R"doc(
Sect. 7.1 on a friction level where it stands (a FieldFriction of steps, or ramps under a point
footprint; two_region_friction too): x_mu is the level's rise X, the entries lie in
[X - Δx - v̄Δt, X - Δx], overshoots are end - X and x_stick_min is eq. (41) on the level's
pieces. The level must be 1 before its rise (the part arrives in the uniform table's steady
state). Raises InvalidParameter naming "friction" otherwise. Runs without the GIL.)doc");
}

py::dict surfaces(std::vector<double> a2, std::vector<double> a3,
                  const std::vector<PositioningCell>& cells) {
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(a2.size()),
                                       static_cast<py::ssize_t>(a3.size())};
  py::array_t<std::int32_t> motion_case(shape), accumulating(shape), p99(shape), p999(shape);
  py::array_t<double> f(shape), dx_d(shape);
  py::array_t<bool> accumulates(shape);
  for (std::size_t k = 0; k < cells.size(); ++k) {  // row-major: k = i * len(a3) + j
    const PositioningCell& c = cells[k];
    motion_case.mutable_data()[k] = static_cast<std::int32_t>(c.motion_case);
    f.mutable_data()[k] = c.f;
    accumulates.mutable_data()[k] = c.accumulates;
    dx_d.mutable_data()[k] = c.dx_d;
    accumulating.mutable_data()[k] = c.accumulating_entries;
    p99.mutable_data()[k] = c.max_periods_p99;
    p999.mutable_data()[k] = c.max_periods_p999;
  }
  py::dict d;
  d["a2"] = to_array(std::move(a2)), d["a3"] = to_array(std::move(a3));
  d["case"] = motion_case, d["f"] = f, d["accumulates"] = accumulates, d["dx_d"] = dx_d;
  d["accumulating_entries"] = accumulating;
  d["max_periods_p99"] = p99, d["max_periods_p999"] = p999;
  d["failure"] = failure_array(cells, shape);
  return d;
}

}  // namespace

// positioning_surfaces' binding body for either table: the grids as vectors, progress and
// Ctrl-C, the GIL released while `compute(a2, a3, sweep)` runs, the cells as arrays.
template <class Compute>
py::dict surfaces_of(const py::object& a2_in, const py::object& a3_in, int threads,
                     const py::object& progress_in, const Compute& compute) {
  std::vector<double> a2 = to_vector(a2_in, "a2"), a3 = to_vector(a3_in, "a3");
  const PythonProgress progress(progress_in);
  const SweepOptions sweep = sweep_options(threads, progress);
  const std::vector<PositioningCell> cells = progress.run([&] { return compute(a2, a3, sweep); });
  return surfaces(std::move(a2), std::move(a3), cells);
}

void bind_positioning(py::module_& m) {
  bind_positioning_options(m);
  bind_accuracy(m);

  m.def(
      "positioning_surfaces",
      [](double period, double stroke, double width, double c_mu, const py::object& a2_in,
         const py::object& a3_in, const PositioningOptions& options, int threads,
         const py::object& progress_in) {
        return surfaces_of(a2_in, a3_in, threads, progress_in,
                           [&](const auto& a2, const auto& a3, const SweepOptions& sweep) {
                             return positioning_surfaces(period, stroke, width, c_mu, a2, a3,
                                                         options, sweep);
                           });
      },
      py::arg("period"), py::arg("stroke"), py::arg("width"), py::arg("c_mu"), py::arg("a2"),
      py::arg("a3"), py::kw_only(), py::arg("options") = PositioningOptions{},
      py::arg("threads") = 0, py::arg("progress") = py::none(), R"doc(
Fig. 17 over the grid a2 × a3 at (Δt, Δy, w, c_mu). Returns a dict of arrays shaped
(len(a2), len(a3)) (cell [i, j] is a2[i], a3[j]):
  'case'                 int32 StickSlipCase (B), a posteriori
  'f'                    float64 objective, eq. (11) (A)
  'accumulates'          bool (C)
  'dx_d'                 float64 eq. (39) (D); NaN where the object does not come to rest
  'accumulating_entries' int32
  'max_periods_p99', 'max_periods_p999'
                         int32 largest number of periods from entry to p = 0.99 / 0.999 over
                         the accumulating entries (-1 if none)
  'failure'              str: '' for a computed cell, else why it could not be (its numbers
                         are NaN; one cell never aborts the study)
plus the 1-D grids 'a2' and 'a3'. options.stopping.max_periods bounds the search per entry.
Cells are computed in parallel on `threads` workers (0: all cores; more are capped at the
cores), each into its own slot, so the result is identical for any thread count; `progress(done, total)` as in
sweep_accelerations. The GIL is released while computing.)doc");
  m.def(
      "positioning_surfaces",
      [](double period, double stroke, const FrictionMap& friction, const py::object& a2_in,
         const py::object& a3_in, const PositioningOptions& options, int threads,
         const py::object& progress_in) {
        return surfaces_of(a2_in, a3_in, threads, progress_in,
                           [&](const auto& a2, const auto& a3, const SweepOptions& sweep) {
                             return positioning_surfaces(period, stroke, friction, a2, a3,
                                                         options, sweep);
                           });
      },
      py::arg("period"), py::arg("stroke"), py::arg("friction"), py::arg("a2"), py::arg("a3"),
      py::kw_only(), py::arg("options") = PositioningOptions{}, py::arg("threads") = 0,
      py::arg("progress") = py::none(), R"doc(
The same on a friction level where it stands (a FieldFriction of steps, or ramps under a point
footprint; level 1 before its rise): every cell is positioning_accuracy(profile, friction)
(x_mu: the level's rise). Raises InvalidParameter naming "friction" before any cell runs for a
level positioning cannot use.)doc");
}

}  // namespace selfalign::python
