// Robust design under uncertainty (include/selfalign/robust/): distributions, the uncertain
// inputs of a designed process, Monte Carlo, the worst case, fragility and design_robust.
// Thin: convert arguments, release the GIL, return records and NumPy arrays.
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>

#include "arrays.hpp"
#include "selfalign/special_values.hpp"
#include "arguments.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/robust/fragility.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/robust/robust_design.hpp"
#include "selfalign/robust/worst_case.hpp"

namespace selfalign::python {
namespace {


// A distribution argument: a Distribution object, its text form ("normal:0.2,5%"), a number
// x (known to be exactly x: a normal of zero spread, Normal(x, 0)), or None (known: the
// request's value).
Distribution to_distribution(const char* name, const py::object& value) {
  if (value.is_none()) return Known{};
  if (py::isinstance<py::str>(value)) return parse_distribution(name, value.cast<std::string>());
  Distribution d = is_scalar(value) && !py::isinstance<py::bool_>(value)
                       ? Distribution(Normal{scalar_value(value, name), 0})
                       : argument<Distribution>(value, name,
                                                "a Normal, Uniform, Samples, Interval, Known, a "
                                                "number, a text such as 'normal:0.2,5%' or None");
  validate(name, d);
  return d;
}

// inputs[k] columns as a dict {name: array}.
py::dict input_columns(const std::vector<std::vector<double>>& columns) {
  py::dict d;
  for (std::size_t k = 0; k < uncertain_inputs().size(); ++k)
    d[uncertain_inputs()[k].name] = to_array(std::vector(columns[k]));
  return d;
}

py::dict input_values(const InputValues& v) {
  py::dict d;
  for (std::size_t k = 0; k < v.size(); ++k) d[uncertain_inputs()[k].name] = v[k];
  return d;
}

// Uniform and Interval: [lower, upper], lower < upper, both finite.
template <class T>
void bind_bounds(py::module_& m, const char* name, const char* key, const char* doc) {
  py::class_<T> c(m, name, doc);
  c.def(py::init([key](double lower, double upper) {
         T t{lower, upper};
         validate(key, t);
         return t;
       }),
       py::arg("lower"), py::arg("upper"), "Raises InvalidParameter unless lower < upper.")
      .def_readonly("lower", &T::lower, "lower bound")
      .def_readonly("upper", &T::upper, "upper bound")
      .def("__repr__", [name](const T& t) {
        return Repr(name)("lower", t.lower)("upper", t.upper).str();
      });
  def_record(c, [](double lo, double hi) { return T{lo, hi}; }, field("lower", &T::lower),
             field("upper", &T::upper));
}

void bind_distributions(py::module_& m) {
  py::class_<Known> known(m, "Known", "Known exactly: the design request's nominal value.");
  known.def(py::init<>()).def("__repr__", [](const Known&) { return std::string("Known()"); });
  def_record(known);

  py::class_<Normal> normal(m, "Normal", R"doc(
Normal(mean, sd) truncated to [lower, upper] (infinite bounds: not truncated). Draws use the
inverse CDF restricted to [Phi(a), Phi(b)], so one uniform number gives one value.)doc");
  normal
      .def(py::init([](double mean, double sd, double lower, double upper) {
             Normal n{mean, sd, lower, upper};
             validate("normal", n);
             return n;
           }),
           py::arg("mean"), py::arg("sd"), py::arg("lower") = -kInf, py::arg("upper") = kInf,
           "Raises InvalidParameter for sd < 0 or bounds that exclude the mean.")
      .def_readonly("mean", &Normal::mean, "mean")
      .def_readonly("sd", &Normal::sd, "standard deviation (>= 0)")
      .def_readonly("lower", &Normal::lower, "lower bound")
      .def_readonly("upper", &Normal::upper, "upper bound")
      .def("__repr__", [](const Normal& n) {
        return Repr("Normal")("mean", n.mean)("sd", n.sd)("lower", n.lower)("upper", n.upper)
            .str();
      });
  def_record(normal, [](double mean, double sd, double lo, double hi) { return Normal{mean, sd, lo, hi}; },
             field("mean", &Normal::mean), field("sd", &Normal::sd),
             field("lower", &Normal::lower), field("upper", &Normal::upper));

  bind_bounds<Uniform>(m, "Uniform", "uniform", "Uniform on [lower, upper].");
  bind_bounds<Interval>(m, "Interval", "interval", R"doc(
Only bounds are known: worst_case searches [lower, upper]; monte_carlo draws it uniformly.)doc");

  py::class_<Samples> samples(m, "Samples", "Measured values, each drawn with probability 1/n.");
  samples
      .def(py::init([](const py::object& values) {
             Samples s{to_vector(values, "values")};
             validate("samples", s);
             return s;
           }),
           py::arg("values"), "Raises InvalidParameter for an empty or non-finite list.")
      .def_property_readonly(
          "values", [](const Samples& s) { return to_array(std::vector(s.values)); },
          "the samples (float64)")
      .def("__repr__", [](const Samples& s) {
        return Repr("Samples")("n", static_cast<long long>(s.values.size())).str();
      });
  def_record(samples, [](std::vector<double> v) { return Samples{std::move(v)}; },
             field("values", &Samples::values));

  m.def("parse_distribution", &parse_distribution, py::arg("name"), py::arg("text"), R"doc(
The distribution of its text form: "normal:MEAN,SD[,LOWER,UPPER]" (SD may end in % of MEAN),
"uniform:LOWER,UPPER", "interval:LOWER,UPPER", "samples:V1,V2,...", "known". Raises
InvalidParameter naming `name` (e.g. "mu.sd").)doc");
}

void bind_process(py::module_& m) {
  py::class_<ProcessUncertainty> u(m, "ProcessUncertainty", R"doc(
What is known about each uncertain input of a designed process (SI): mu, c_mu, static_ratio
(mu_static/mu), width [m] (transition = object width), x_mu_offset [m] (error of the rough
region's start), amplitude and period_factor (factors on the table's displacement and period).
Each keyword takes a Normal, Uniform, Samples, Interval, Known, a text form such as
"normal:0.2,5%", a number x (known to be exactly x: Normal(x, 0)), or None (known: the design
request's value). A value of another type raises TypeError naming the keyword.)doc");
  u.def(py::init([](const py::object& mu, const py::object& c_mu, const py::object& static_ratio,
                    const py::object& width, const py::object& x_mu_offset,
                    const py::object& amplitude, const py::object& period_factor) {
          ProcessUncertainty p;
          p.mu = to_distribution("mu", mu);
          p.c_mu = to_distribution("c_mu", c_mu);
          p.static_ratio = to_distribution("static_ratio", static_ratio);
          p.width = to_distribution("width", width);
          p.x_mu_offset = to_distribution("x_mu_offset", x_mu_offset);
          p.amplitude = to_distribution("amplitude", amplitude);
          p.period_factor = to_distribution("period_factor", period_factor);
          validate(p);
          return p;
        }),
        py::kw_only(), py::arg("mu") = py::none(), py::arg("c_mu") = py::none(),
        py::arg("static_ratio") = py::none(), py::arg("width") = py::none(),
        py::arg("x_mu_offset") = py::none(), py::arg("amplitude") = py::none(),
        py::arg("period_factor") = py::none(),
        "Raises InvalidParameter naming the input (e.g. mu.sd) for an unusable distribution, "
        "or one whose draws leave the input's domain (mu > 0, c_mu > 1, ...).");
  for (const UncertainInput& in : uncertain_inputs())
    u.def_property_readonly(
        in.name, [member = in.member](const ProcessUncertainty& p) { return p.*member; },
        (std::string(in.meaning) + " [" + in.unit + "]").c_str());
  u.def("__repr__", [](const ProcessUncertainty& p) {
    Repr r("ProcessUncertainty");
    for (const UncertainInput& in : uncertain_inputs())
      if (is_uncertain(p.*in.member)) r.raw(in.name, "'" + describe(p.*in.member) + "'");
    return r.str();
  });
  using U = ProcessUncertainty;
  def_record(
      u,
      [](Distribution a, Distribution b, Distribution c, Distribution d, Distribution e,
         Distribution f, Distribution g) { return U{a, b, c, d, e, f, g}; },
      field("mu", &U::mu), field("c_mu", &U::c_mu), field("static_ratio", &U::static_ratio),
      field("width", &U::width), field("x_mu_offset", &U::x_mu_offset),
      field("amplitude", &U::amplitude), field("period_factor", &U::period_factor));

  m.def(
      "uncertain_inputs",
      [] {
        py::list out;
        for (const UncertainInput& in : uncertain_inputs())
          out.append(py::make_tuple(in.name, in.unit, in.meaning));
        return out;
      },
      "The uncertain inputs, in the order of MonteCarloResult.inputs: (name, unit, meaning).");

  py::class_<Process> p(m, "Process", R"doc(
A designed process in SI: the three-phase table motion (period [s], stroke [m], a2, a3
[m/s^2], jerk [m/s^3], inf: jump accelerations) and where the rough region starts, x_mu [m]
(from the start position). process_of(design_result) gives a design's.)doc");
  p.def(py::init([](double period, double stroke, double a2, double a3, double x_mu, double jerk) {
         Process q{period, stroke, a2, a3, jerk, x_mu};
         validate(q);
         return q;
       }),
       py::kw_only(), py::arg("period"), py::arg("stroke"), py::arg("a2"), py::arg("a3"),
       py::arg("x_mu"), py::arg("jerk") = kInf,
       "Raises InvalidParameter for a bad value or a non-physical (case 0) profile.")
      .def_readonly("period", &Process::period, "table period [s]")
      .def_readonly("stroke", &Process::stroke, "table stroke [m]")
      .def_readonly("a2", &Process::a2, "y2'' [m/s^2]")
      .def_readonly("a3", &Process::a3, "y3'' [m/s^2]")
      .def_readonly("jerk", &Process::jerk, "jerk limit [m/s^3] (inf: jump accelerations)")
      .def_readonly("x_mu", &Process::x_mu, "start of the rough region [m]")
      .def("__repr__", [](const Process& q) {
        return Repr("Process")("period", q.period)("stroke", q.stroke)("a2", q.a2)("a3", q.a3)(
                   "x_mu", q.x_mu)("jerk", q.jerk)
            .str();
      });
  def_record(p, field("period", &Process::period), field("stroke", &Process::stroke),
             field("a2", &Process::a2), field("a3", &Process::a3), field("jerk", &Process::jerk),
             field("x_mu", &Process::x_mu));
  m.def("process_of", &process_of, py::arg("design"),
        "The Process of a feasible DesignResult (its profile and x_mu).");

  m.def(
      "draw_inputs",
      [](const DesignRequest& q, const ProcessUncertainty& u, std::uint64_t seed, int runs,
         std::uint64_t first_run) {
        validate(u);
        if (runs < 0 || runs > 10'000'000)
          throw InvalidParameter("runs", runs, "must be in [0, 1e7]");
        std::vector<std::vector<double>> columns(kUncertainInputs,
                                                 std::vector<double>(static_cast<std::size_t>(runs)));
        for (int r = 0; r < runs; ++r) {
          const InputValues v = draw_inputs(q, u, seed, first_run + static_cast<std::uint64_t>(r));
          for (std::size_t k = 0; k < kUncertainInputs; ++k) columns[k][static_cast<std::size_t>(r)] = v[k];
        }
        return input_columns(columns);
      },
      py::arg("request"), py::arg("uncertainty"), py::kw_only(), py::arg("seed") = 1,
      py::arg("runs") = 1000, py::arg("first_run") = 0,
      "The inputs monte_carlo draws for runs first_run ... first_run + runs - 1: {name: array}.");
}

void bind_monte_carlo(py::module_& m) {
  using R = MonteCarloResult;
  py::class_<R> r(m, "MonteCarloResult", R"doc(
The runs of one Monte-Carlo study, in run order: inputs {name: array}, kind (int8 StopKind
values), end_position [m] and process_time [s] (NaN when not stopped), entry_time [s] (NaN when
the rough region was never reached); counts, P(stop), P(within tolerance) and its 95% Wilson
interval. merge_monte_carlo joins consecutive chunks into the result of one call.)doc");
  r.def_readonly("seed", &R::seed, "seed of the draws")
      .def_readonly("first_run", &R::first_run, "index of the first run")
      .def_readonly("target", &R::target, "desired end position [m]")
      .def_readonly("tolerance", &R::tolerance, "allowed |end - target| [m]")
      .def_property_readonly("inputs", [](const R& x) { return input_columns(x.inputs); },
                             "{name: float64 array} of each run's inputs")
      .def_property_readonly(
          "kind",
          [](const R& x) {
            py::array_t<std::int8_t> a(static_cast<py::ssize_t>(x.kind.size()));
            for (std::size_t i = 0; i < x.kind.size(); ++i)
              a.mutable_data()[i] = static_cast<std::int8_t>(x.kind[i]);
            return a;
          },
          "int8 StopKind values per run")
      .def_property_readonly("end_position", [](const R& x) { return to_array(std::vector(x.end_position)); }, "[m]; NaN when not stopped")
      .def_property_readonly("process_time", [](const R& x) { return to_array(std::vector(x.process_time)); }, "T_p [s]; NaN when not stopped")
      .def_property_readonly("entry_time", [](const R& x) { return to_array(std::vector(x.entry_time)); }, "[s]; NaN if never entered")
      .def_readonly("runs", &R::runs, "number of runs")
      .def_readonly("stopped", &R::stopped, "runs that stopped for good")
      .def_readonly("within", &R::within, "runs that stopped within the tolerance")
      .def_readonly("never_entered", &R::never_entered, "runs that never reached the rough region")
      .def_readonly("p_stop", &R::p_stop, "fraction of runs that stopped")
      .def_readonly("p_within", &R::p_within, "fraction of runs within the tolerance")
      .def_readonly("p_within_low", &R::p_within_low, "95% Wilson lower bound")
      .def_readonly("p_within_high", &R::p_within_high, "95% Wilson upper bound")
      .def("process_time_quantile", &process_time_quantile, py::arg("q"),
           "the q-quantile of T_p [s] over all runs (not stopped: +inf); inverse empirical CDF")
      .def("end_position_quantile", &end_position_quantile, py::arg("q"),
           "the q-quantile of the end position [m] over the runs that stopped (NaN if none)")
      .def(
          "histogram",
          [](const R& x, int bins) {
            Histogram h = histogram(x.end_position, bins);
            return py::make_tuple(to_array(std::vector<int>(h.counts)), to_array(std::move(h.edges)));
          },
          py::arg("bins") = 20, "(counts, edges [m]) of the end positions of the stopped runs")
      .def("__repr__", [](const R& x) {
        return Repr("MonteCarloResult")("runs", x.runs)("p_stop", x.p_stop)(
                   "p_within", x.p_within)("p_within_low", x.p_within_low)(
                   "p_within_high", x.p_within_high)
            .str();
      });
  def_record(
      r, field("seed", &R::seed), field("first_run", &R::first_run), field("target", &R::target),
      field("tolerance", &R::tolerance), field("inputs", &R::inputs),
      field(
          "kind",
          [](const R& x) {
            std::vector<std::int8_t> k;
            for (StopKind s : x.kind) k.push_back(static_cast<std::int8_t>(s));
            return k;
          },
          [](R& x, const std::vector<std::int8_t>& k) {
            x.kind.clear();
            for (std::int8_t s : k) x.kind.push_back(static_cast<StopKind>(s));
          }),
      field("end_position", &R::end_position), field("process_time", &R::process_time),
      field("entry_time", &R::entry_time),
      field("runs", &R::runs), field("stopped", &R::stopped), field("within", &R::within),
      field("never_entered", &R::never_entered), field("p_stop", &R::p_stop),
      field("p_within", &R::p_within), field("p_within_low", &R::p_within_low),
      field("p_within_high", &R::p_within_high));

  m.def(
      "monte_carlo",
      [](const DesignRequest& q, const Process& p, const ProcessUncertainty& u, int runs,
         std::uint64_t seed, std::uint64_t first_run, int max_periods, int threads,
         const py::object& progress_in) {
        const PythonProgress progress(progress_in);
        MonteCarloOptions o;
        o.runs = runs, o.seed = seed, o.first_run = first_run, o.max_periods = max_periods;
        o.threads = threads;
        o.progress = progress.callback();
        return progress.run([&] { return monte_carlo(q, p, u, o); });
      },
      py::arg("request"), py::arg("process"), py::arg("uncertainty"), py::kw_only(),
      py::arg("runs") = 10'000, py::arg("seed") = 1, py::arg("first_run") = 0,
      py::arg("max_periods") = 3000, py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(
Monte Carlo of a designed process (SI) under the uncertainty: run r (first_run <= r <
first_run + runs) draws its inputs from (seed, r) and runs the exact stopping run from rest;
the request gives g, the target (distance) and the tolerance (> 0). The result does not depend
on `threads`, and chunks (first_run, runs) merge (merge_monte_carlo) into the same result bit
for bit. selfalign.monte_carlo also takes executor= (a concurrent.futures.Executor: Dask,
mpi4py) and chunk_size= to spread the chunks. Runs without the GIL.)doc");
  m.def("merge_monte_carlo",
        &merge_monte_carlo, py::arg("parts"),
        "Joins consecutive chunks of one study (same seed; each first_run continuing the "
        "previous) into the result of a single call.");
}

void bind_worst_case_and_fragility(py::module_& m) {
  py::class_<WorstCase> w(m, "WorstCase", R"doc(
The worst case over the uncertainty box: method (how the box was searched), evaluations
(exact stopping runs), box {name: (lower, upper)}, the inputs and error of the largest
|end - target| [m] (inf: a run that does not stop), all_within, and the slowest T_p [s].)doc");
  w.def_readonly("method", &WorstCase::method, "how the box was searched")
      .def_readonly("evaluations", &WorstCase::evaluations, "exact stopping runs evaluated")
      .def_property_readonly(
          "box",
          [](const WorstCase& x) {
            py::dict d;
            for (std::size_t k = 0; k < kUncertainInputs; ++k)
              if (x.box[k].first < x.box[k].second) d[uncertain_inputs()[k].name] = x.box[k];
            return d;
          },
          "{name: (lower, upper)} of the uncertain inputs searched")
      .def_property_readonly(
          "worst_inputs", [](const WorstCase& x) { return input_values(x.worst_inputs); },
          "{name: value}: the inputs of the largest end-position error")
      .def_readonly("worst_error", &WorstCase::worst_error, "|end - target| of the worst run [m]; inf: it does not stop")
      .def_property_readonly(
          "worst_end_position", [](const WorstCase& x) { return x.worst.end_position; },
          "end position of the worst run [m]; NaN when it does not stop")
      .def_property_readonly(
          "worst_stops", [](const WorstCase& x) { return x.worst.kind != StopKind::not_stopped; },
          "whether the worst run stops")
      .def_readonly("all_within", &WorstCase::all_within, "every evaluated point ended within the tolerance")
      .def_property_readonly(
          "slowest_inputs", [](const WorstCase& x) { return input_values(x.slowest_inputs); },
          "{name: value}: the inputs of the longest T_p")
      .def_readonly("slowest_time", &WorstCase::slowest_time, "the longest T_p found [s]; inf: a run does not stop")
      .def("__repr__", [](const WorstCase& x) {
        return Repr("WorstCase")("evaluations", x.evaluations)("worst_error", x.worst_error)(
                   "all_within", x.all_within)("slowest_time", x.slowest_time)
            .str();
      });
  def_record(
      w, field("method", &WorstCase::method), field("evaluations", &WorstCase::evaluations),
      field("box", &WorstCase::box),
      field("worst_inputs", [](const WorstCase& x) { return std::vector<double>(x.worst_inputs.begin(), x.worst_inputs.end()); },
            [](WorstCase& x, const std::vector<double>& v) { std::copy_n(v.begin(), kUncertainInputs, x.worst_inputs.begin()); }),
      field("worst_error", &WorstCase::worst_error),
      field("worst_end_position", [](const WorstCase& x) { return x.worst.end_position; },
            [](WorstCase& x, double v) { x.worst.end_position = v; }),
      field("worst_stops", [](const WorstCase& x) { return x.worst.kind != StopKind::not_stopped; },
            [](WorstCase& x, bool v) { x.worst.kind = v ? StopKind::permanent_stick : StopKind::not_stopped; }),
      field("all_within", &WorstCase::all_within),
      field("slowest_inputs", [](const WorstCase& x) { return std::vector<double>(x.slowest_inputs.begin(), x.slowest_inputs.end()); },
            [](WorstCase& x, const std::vector<double>& v) { std::copy_n(v.begin(), kUncertainInputs, x.slowest_inputs.begin()); }),
      field("slowest_time", &WorstCase::slowest_time));
  m.def(
      "worst_case",
      [](const DesignRequest& q, const Process& p, const ProcessUncertainty& u, double sigmas,
         int interior_points, int starts, int local_evaluations, int max_periods, int threads) {
        WorstCaseOptions o;
        o.sigmas = sigmas, o.interior_points = interior_points, o.starts = starts;
        o.local_evaluations = local_evaluations, o.max_periods = max_periods, o.threads = threads;
        py::gil_scoped_release release;
        return worst_case(q, p, u, o);
      },
      py::arg("request"), py::arg("process"), py::arg("uncertainty"), py::kw_only(),
      py::arg("sigmas") = 3.0, py::arg("interior_points") = 64, py::arg("starts") = 3,
      py::arg("local_evaluations") = 100, py::arg("max_periods") = 3000, py::arg("threads") = 0,
      R"doc(
The worst case of the process over the box of the uncertain inputs (an unbounded normal spans
mean -/+ sigmas sd): every corner, interior_points Halton points, then NLopt's bounded
Nelder-Mead from the `starts` worst points (local_evaluations runs each). Deterministic,
independent of threads.)doc");

  py::class_<Fragility> f(m, "Fragility", R"doc(
How fragile a process is to mu, c_mu and mu_static at relative error `level`: stop_margin (the
relative drop of mu_static c_mu after which it never stops, eq. 40), motion_margin, the end
positions with mu and c_mu off by -/+level and the static ratio mu_static/mu at max(1, (1 -
level) s) and (1 + level) s (NaN: never stops), the largest shifts (inf: a run never stops),
assumes_equal_static (the request gave no mu_static above mu) and one warning line per finding
(a plain one whenever the design assumed mu_static = mu).)doc");
  f.def_readonly("level", &Fragility::level, "the relative error of mu, c_mu and mu_static examined [-]")
      .def_readonly("stop_margin", &Fragility::stop_margin, "1 - max(a2, a3)/(mu_static c_mu g): relative drop of mu_static c_mu before it never stops [-]")
      .def_readonly("motion_margin", &Fragility::motion_margin, "a2/(mu_static g) - 1: relative rise of mu_static before it never moves [-]")
      .def_readonly("end_nominal", &Fragility::end_nominal, "end position at the nominal inputs [m]")
      .def_readonly("end_mu", &Fragility::end_mu, "end positions with mu at (1 - level), (1 + level) x nominal [m]; NaN: never stops")
      .def_readonly("end_c_mu", &Fragility::end_c_mu, "end positions with c_mu at (1 - level), (1 + level) x nominal [m]; NaN: never stops")
      .def_readonly("end_shift_mu", &Fragility::end_shift_mu, "largest |end - end_nominal| over the mu runs [m]; inf: one never stops")
      .def_readonly("end_shift_c_mu", &Fragility::end_shift_c_mu, "largest |end - end_nominal| over the c_mu runs [m]; inf: one never stops")
      .def_readonly("end_static", &Fragility::end_static, "end positions with the static ratio s = mu_static/mu at max(1, (1 - level) s), (1 + level) s [m]; NaN: never stops")
      .def_readonly("end_shift_static", &Fragility::end_shift_static, "largest |end - end_nominal| over the static-ratio runs [m]; inf: one never stops")
      .def_readonly("assumes_equal_static", &Fragility::assumes_equal_static, "the request left mu_static unset or equal to mu")
      .def_readonly("warnings", &Fragility::warnings, "one line per finding; empty when not fragile at this level")
      .def_property_readonly(
          "fragile", [](const Fragility& x) { return !x.warnings.empty(); },
          "whether there is any warning")
      .def("__repr__", [](const Fragility& x) {
        return Repr("Fragility")("level", x.level)("stop_margin", x.stop_margin)(
                   "motion_margin", x.motion_margin)("warnings", static_cast<long long>(x.warnings.size()))
            .str();
      });
  def_record(f, field("level", &Fragility::level), field("stop_margin", &Fragility::stop_margin),
             field("motion_margin", &Fragility::motion_margin),
             field("end_nominal", &Fragility::end_nominal), field("end_mu", &Fragility::end_mu),
             field("end_c_mu", &Fragility::end_c_mu),
             field("end_shift_mu", &Fragility::end_shift_mu),
             field("end_shift_c_mu", &Fragility::end_shift_c_mu),
             field("end_static", &Fragility::end_static),
             field("end_shift_static", &Fragility::end_shift_static),
             field("assumes_equal_static", &Fragility::assumes_equal_static),
             field("warnings", &Fragility::warnings));
  m.def(
      "fragility",
      [](const DesignRequest& q, const Process& p, double level, int max_periods) {
        py::gil_scoped_release release;
        return fragility(q, p, level, max_periods);
      },
      py::arg("request"), py::arg("process"), py::kw_only(), py::arg("level") = 0.05,
      py::arg("max_periods") = 3000,
      "Fragility of the process to mu, c_mu and mu_static off by `level` (relative, in (0, 1)).");
}

void bind_robust_design(py::module_& m) {
  py::class_<FailureCounts> fc(m, "FailureCounts",
                               "Why runs failed: no_motion (never reached the rough region), "
                               "no_stop (never stopped), outside (stopped outside the tolerance).");
  fc.def_readonly("no_motion", &FailureCounts::no_motion, "runs that never reached the rough region")
      .def_readonly("no_stop", &FailureCounts::no_stop, "runs that reached it but never stopped")
      .def_readonly("outside", &FailureCounts::outside, "runs that stopped outside the tolerance")
      .def("__repr__", [](const FailureCounts& x) {
        return Repr("FailureCounts")("no_motion", x.no_motion)("no_stop", x.no_stop)(
                   "outside", x.outside)
            .str();
      });
  def_record(fc, field("no_motion", &FailureCounts::no_motion),
             field("no_stop", &FailureCounts::no_stop), field("outside", &FailureCounts::outside));

  using R = RobustDesignResult;
  py::class_<R> r(m, "RobustDesignResult", R"doc(
design_robust's answer: meets_target (the selection's 95% Wilson lower bound of P(within) and
the independent verification's P(within) reach the target), message, binding (the failure mode
that limits: "end-position spread", "stopping", "motion", "actuator limits"), the design
(DesignResult, SI) and its process (x_mu placed), its selection and its independent
verification (MonteCarloResult), failures, the T_p quantile [s], the tolerance it holds at the
target probability, the limits it sits on, the screen's rungs and the candidate counts.)doc");
  r.def_readonly("meets_target", &R::meets_target, "the selection (95% Wilson lower bound) and the independent verification reach the target")
      .def_readonly("message", &R::message, "what was found, or why no design reaches the target")
      .def_readonly("binding", &R::binding, "the failure mode that limits the design")
      .def_readonly("design", &R::design, "the chosen profile (the best found when not meets_target), SI")
      .def_readonly("process", &R::process, "the chosen Process, x_mu placed")
      .def_readonly("selection", &R::selection, "MonteCarloResult of the runs that selected it (selection stream)")
      .def_readonly("verification", &R::verification, "MonteCarloResult of its verification runs, independent of every draw that chose it: the claim")
      .def_readonly("failures", &R::failures, "FailureCounts over the verification")
      .def_readonly("time_quantile_value", &R::time_quantile_value, "the T_p quantile of the verification [s] (inf: too many runs never stop)")
      .def_readonly("achievable_tolerance", &R::achievable_tolerance, "the smallest tolerance [m] a fraction probability_target of its verification runs end within (inf: too many never stop)")
      .def_readonly("limits", &R::limits, "the request limits the chosen profile sits on")
      .def_readonly("rungs", &R::rungs, "screening draws of each rung of the screen")
      .def_readonly("candidates", &R::candidates, "candidates in the grid")
      .def_readonly("screened", &R::screened, "candidates screened by Monte Carlo")
      .def_readonly("verified", &R::verified, "finalists run through the selection Monte Carlo")
      .def("__repr__", [](const R& x) {
        return Repr("RobustDesignResult")("meets_target", x.meets_target)(
                   "p_within", x.verification.p_within)("time_quantile_value", x.time_quantile_value)
            .raw("binding", "'" + x.binding + "'")
            .str();
      });
  def_record(r, field("meets_target", &R::meets_target), field("message", &R::message),
             field("binding", &R::binding), field("design", &R::design),
             field("process", &R::process), field("selection", &R::selection),
             field("verification", &R::verification), field("failures", &R::failures),
             field("time_quantile_value", &R::time_quantile_value),
             field("achievable_tolerance", &R::achievable_tolerance),
             field("limits", &R::limits), field("rungs", &R::rungs),
             field("candidates", &R::candidates), field("screened", &R::screened),
             field("verified", &R::verified));
  m.def(
      "design_robust",
      [](const DesignRequest& q, const ProcessUncertainty& u, double probability_target,
         double time_quantile, int screening_runs, int verification_runs, int finalists,
         std::uint64_t seed, int max_periods, double slow_factor, int threads,
         const py::object& progress_in) {
        const PythonProgress progress(progress_in);
        RobustOptions o;
        o.probability_target = probability_target, o.time_quantile = time_quantile;
        o.screening_runs = screening_runs, o.verification_runs = verification_runs;
        o.finalists = finalists, o.seed = seed, o.max_periods = max_periods;
        o.slow_factor = slow_factor, o.threads = threads;
        o.progress = progress.callback();
        return progress.run([&] { return design_robust(q, u, o); });
      },
      py::arg("request"), py::arg("uncertainty"), py::kw_only(),
      py::arg("probability_target") = 0.99, py::arg("time_quantile") = 0.99,
      py::arg("screening_runs") = 200, py::arg("verification_runs") = 4000,
      py::arg("finalists") = 6, py::arg("seed") = 1, py::arg("max_periods") = 3000,
      py::arg("slow_factor") = 4.0, py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(
The fastest process (minimum time_quantile of T_p) with P(|end - distance| <= tolerance) >=
probability_target under the uncertainty, over design_process's candidate grid: a closed-form
prune (eq. 40), a Monte-Carlo screen in rungs of 25, 50, 100, ... screening_runs draws placing
x_mu by exact runs (any stop kind), a selection Monte Carlo of the finalists (`finalists` per
rung), then a verification Monte Carlo of the chosen design on draws independent of all the
others (docs/robust-design.md). With screening_runs on the ladder 25 x 2^j, more screening
runs or finalists never select a worse design. When no candidate reaches the target,
meets_target is False and the result holds the best probability found and the tolerance it
holds (achievable_tolerance). Runs without the GIL.)doc");
}

}  // namespace

void bind_uncertainty(py::module_& m) {
  bind_distributions(m);
  bind_process(m);
  bind_monte_carlo(m);
  bind_worst_case_and_fragility(m);
  bind_robust_design(m);
}

}  // namespace selfalign::python
