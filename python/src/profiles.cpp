// Table profiles (Sect. 4.4): the TableProfile interface with a vectorised sample(), and the
// piecewise-constant, Fourier and sampled families. The three-phase profile: three_phase.cpp.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "arguments.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/sampled.hpp"

namespace selfalign::python {

namespace {

// (y, y', y'') at every t: floats for a float, arrays of t's shape for an array-like.
py::tuple sample(const TableProfile& profile, const py::object& t) {
  auto state = [&](double v) {
    if (!std::isfinite(v)) throw InvalidParameter("t", v, "must be a finite number");
    return profile.state(v);
  };
  if (is_scalar(t)) {
    const TableState s = state(scalar_value(t, "t"));
    return py::make_tuple(s.y, s.yd, s.ydd);
  }
  const auto in = DoubleArray::ensure(t);
  if (!in) throw py::type_error("t: expected a float or an array-like of floats");
  const std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
  py::array_t<double> y(shape), yd(shape), ydd(shape);
  const double* src = in.data();
  double *py = y.mutable_data(), *pyd = yd.mutable_data(), *pydd = ydd.mutable_data();
  for (py::ssize_t i = 0; i < in.size(); ++i) {
    const TableState s = state(src[i]);
    py[i] = s.y;
    pyd[i] = s.yd;
    pydd[i] = s.ydd;
  }
  return py::make_tuple(y, yd, ydd);
}

py::dict segments(const PiecewisePolynomialProfile& p) {
  std::vector<double> begin, accel, y, yd, jerk;
  for (const AccelerationSegment& s : p.segments()) {
    jerk.push_back(s.jerk);
    begin.push_back(s.begin);
    accel.push_back(s.accel);
    y.push_back(s.y);
    yd.push_back(s.yd);
  }
  py::dict d;
  d["begin"] = to_array(std::move(begin));
  d["accel"] = to_array(std::move(accel));
  d["jerk"] = to_array(std::move(jerk));
  d["y"] = to_array(std::move(y));
  d["yd"] = to_array(std::move(yd));
  return d;
}

// Column of the segments of one period (a record field of PiecewisePolynomialProfile).
template <class F>
auto segment_column(F value) {
  return [value](const PiecewisePolynomialProfile& p) {
    std::vector<double> out;
    for (const AccelerationSegment& s : p.segments()) out.push_back(value(s));
    return out;
  };
}

// The end accelerations b from which from_linear_accelerations rebuilds p exactly: per segment
// s.end_accel() up to rounding, the float nearest it whose jerk (b - a)/d is s.jerk again and
// |b| <= peak, ±peak first (which an end acceleration at the peak was: then the rebuilt peak
// acceleration, the largest |a| or |b|, is the same too).
std::vector<double> end_accels(const PiecewisePolynomialProfile& p) {
  const double peak = p.peak_acceleration(), inf = std::numeric_limits<double>::infinity();
  std::vector<double> out;
  for (const AccelerationSegment& s : p.segments()) {
    const double guess = s.end_accel();
    const auto fits = [&](double b) {
      return std::abs(b) <= peak && (b - s.accel) / s.duration == s.jerk;
    };
    double b = s.accel;
    if (s.jerk != 0.0) {
      const double at_peak = std::copysign(peak, guess);
      const double ulp = std::nextafter(std::abs(guess), inf) - std::abs(guess);
      b = std::abs(at_peak - guess) <= 64 * ulp && fits(at_peak) ? at_peak : guess;
      double up = guess, down = guess;
      for (int step = 0; step < 64 && !fits(b); ++step) {
        b = fits(up) ? up : fits(down) ? down : guess;
        up = std::nextafter(up, inf), down = std::nextafter(down, -inf);
      }
    }
    out.push_back(b);
  }
  return out;
}

std::string profile_repr(const py::object& self) {
  const auto& p = self.cast<const TableProfile&>();
  return "<" + py::type::of(self).attr("__name__").cast<std::string>() + " kind='" + p.kind() +
         "' period=" + format_number(p.period()) + " stroke=" + format_number(p.stroke()) + ">";
}

void bind_table_profile(py::module_& m) {
  py::class_<TableState> state(m, "TableState",
                              "Table position, velocity and acceleration at one time [-].");
  state
      .def(py::init([](double y, double yd, double ydd) {
             return TableState{y, yd, ydd};
           }),
           py::arg("y") = 0.0, py::arg("yd") = 0.0, py::arg("ydd") = 0.0)
      .def_readwrite("y", &TableState::y, "table position y [-]")
      .def_readwrite("yd", &TableState::yd, "table velocity y' [-]")
      .def_readwrite("ydd", &TableState::ydd,
                     "table acceleration y'' [-] (right limit at a switch)")
      .def("__repr__", [](const TableState& s) {
        return Repr("TableState")("y", s.y)("yd", s.yd)("ydd", s.ydd).str();
      });
  def_record(state, field("y", &TableState::y), field("yd", &TableState::yd),
             field("ydd", &TableState::ydd));

  py::class_<TableProfile>(m, "TableProfile", R"doc(
A prescribed periodic table motion y(t) (Sect. 4.4). Abstract: build a ThreePhaseProfile,
JerkLimitedThreePhaseProfile, PiecewisePolynomialProfile, FourierProfile or a sampled profile
(make_sampled_profile).

All quantities are dimensionless (Sect. 3.2). A profile is periodic with period Δt; its
velocity has zero mean, and min y = 0 (Sect. 4.4.3, constraint 1), so the stroke is max y.)doc")
      .def_property_readonly("period", &TableProfile::period, "Δt [-], > 0")
      .def_property_readonly("peak_acceleration", &TableProfile::peak_acceleration,
                             "sup over the period of |y''| [-] (used by eq. 40)")
      .def_property_readonly("stroke", &TableProfile::stroke, "Δy = max y - min y [-]")
      .def_property_readonly("kind", &TableProfile::kind,
                             "short family name ('three-phase', 'fourier', ...)")
      .def(
          "state",
          [](const TableProfile& p, double t) {
            return p.state(require_finite("t", t));
          },
          py::arg("t"),
           "y, y', y'' at one time t [-] (any real t: periodic extension; y'' right-continuous).")
      .def(
          "velocity",
          [](const TableProfile& p, const py::object& t) {
            return map_elementwise<double>(t, [&](double v) { return p.velocity(v); }, "t");
          },
          py::arg("t"), "y'(t) [-] at time(s) t (float or ndarray).")
      .def("sample", &sample, py::arg("t"), R"doc(
The table motion at every time of t (float or array-like of any shape) [-]: a tuple
(y, yd, ydd) of float64 arrays shaped like t (floats for a float t).)doc")
      .def("piecewise_polynomial", &TableProfile::piecewise_polynomial,
           py::return_value_policy::reference_internal,
           "The profile as a PiecewisePolynomialProfile when its acceleration is piecewise "
           "polynomial of degree <= 1 (constant or linear in time: then the exact solver "
           "applies), else None.")
      .def(
          "piecewise_constant",
          [](const TableProfile& p) -> const PiecewisePolynomialProfile* {
            const PiecewisePolynomialProfile* q = p.piecewise_polynomial();
            return q && q->piecewise_constant() ? q : nullptr;
          },
          py::return_value_policy::reference_internal,
          "The profile as a PiecewisePolynomialProfile when its acceleration is piecewise "
          "constant (jerk 0 everywhere), else None.")
      .def("__repr__", &profile_repr);
}

void bind_piecewise_constant(py::module_& m) {
  auto cls = py::class_<PiecewisePolynomialProfile, TableProfile>(m, "PiecewisePolynomialProfile", R"doc(
A periodic table profile whose acceleration is piecewise polynomial of degree <= 1: constant
(the paper's sequences of second-order polynomials, Fig. 3 style, Sect. 4.2) or linear in time
(finite jerk) on each segment; the form the exact solver integrates. Build it with
PiecewisePolynomialProfile.from_accelerations (constant), from_linear_accelerations or
from_breakpoints (finite jerk).)doc");
  cls
      .def_static(
          "from_accelerations",
          [](const py::object& durations, const py::object& accels, const std::string& kind) {
            const std::vector<double> d = to_vector(durations, "durations");
            const std::vector<double> a = to_vector(accels, "accels");
            return PiecewisePolynomialProfile::from_accelerations(d, a, kind);
          },
          py::arg("durations"), py::arg("accels"), py::arg("kind") = "quadratic-sequence",
          R"doc(
The periodic profile with accelerations accels[i] [-] held for durations[i] [-].

Periodicity of y' needs sum(accels[i] durations[i]) = 0 (checked to 1e-12 relative to
sum |accels[i]| durations[i]). The initial velocity makes the mean velocity zero (periodic y),
the initial position makes min y = 0. Zero-length segments are dropped. Raises
InvalidParameter on sizes that differ, negative or non-finite durations, a zero period,
non-finite accelerations, or a velocity that does not return.)doc")
      .def("segments", &segments, R"doc(
The constant-acceleration segments of one period as a dict of 1-D float64 arrays:
'begin' (start time in [0, Δt)), 'accel' (y''), 'y' and 'yd' (table state at the start) [-].)doc")
      .def("segment_at", &PiecewisePolynomialProfile::segment_at, py::arg("phase"),
           "Index of the segment containing phase p in [0, Δt).")
      .def("phase", &PiecewisePolynomialProfile::phase, py::arg("t"), "Phase of t in [0, Δt) [-].")
      .def_property_readonly("peak_jerk", &PiecewisePolynomialProfile::peak_jerk,
                             "largest |jerk| over the segments [-] (0: piecewise constant)")
      .def_static(
          "from_linear_accelerations",
          [](const py::object& durations, const py::object& a0, const py::object& a1,
             const std::string& kind) {
            return PiecewisePolynomialProfile::from_linear_accelerations(
                to_vector(durations, "durations"), to_vector(a0, "accel_begin"),
                to_vector(a1, "accel_end"), kind);
          },
          py::arg("durations"), py::arg("accel_begin"), py::arg("accel_end"),
          py::arg("kind") = "piecewise-linear-acceleration", R"doc(
The periodic profile whose acceleration goes linearly from accel_begin[i] to accel_end[i] over
durations[i] [-] (finite jerk; jumps between segments allowed). Same normalisation and checks
as from_accelerations.)doc")
      .def_static(
          "from_breakpoints",
          [](const py::object& times, const py::object& accels, double period,
             const std::string& kind) {
            return PiecewisePolynomialProfile::from_breakpoints(
                to_vector(times, "times"), to_vector(accels, "accels"), period, kind);
          },
          py::arg("times"), py::arg("accels"), py::arg("period"),
          py::arg("kind") = "piecewise-linear-acceleration", R"doc(
The continuous piecewise-linear acceleration through the periodic breakpoints (times[i],
accels[i]) [-]: times[0] = 0, strictly increasing, period > times[-1]; the acceleration returns
to accels[0] at t = period.)doc");
  // The record: from_linear_accelerations' arguments (what every factory builds from).
  def_record(
      cls,
      [](const std::vector<double>& durations, const std::vector<double>& accel_begin,
         const std::vector<double>& accel_end, const std::string& kind) {
        return PiecewisePolynomialProfile::from_linear_accelerations(durations, accel_begin,
                                                                     accel_end, kind);
      },
      field("durations", segment_column([](const AccelerationSegment& s) { return s.duration; })),
      field("accel_begin", segment_column([](const AccelerationSegment& s) { return s.accel; })),
      field("accel_end", &end_accels),
      field("kind", &TableProfile::kind));
}

void bind_fourier(py::module_& m) {
  py::class_<FourierProfile, TableProfile> cls(m, "FourierProfile", R"doc(
A Fourier-series table profile of any order N (Sect. 4.4.2):
  y(t) = c_0 + sum_{k=1..N} (A_k cos(k w t) + B_k sin(k w t)),   w = 2 pi / Δt,
with c_0 chosen so that min y = 0. Periodic in y and y' by construction. Not piecewise
constant: the exact smooth-profile solver takes it on piecewise-constant friction levels
(simulate/smooth_exact.hpp; Method.exact), time-stepping elsewhere.)doc");
  cls
      .def(py::init([](double period, const py::object& cos_coeffs, const py::object& sin_coeffs) {
             return FourierProfile(period, to_vector(cos_coeffs, "cos_coeffs"),
                                   to_vector(sin_coeffs, "sin_coeffs"));
           }),
           py::arg("period"), py::arg("cos_coeffs"), py::arg("sin_coeffs"), R"doc(
period:     Δt [-], > 0
cos_coeffs: A_1..A_N [-]; sin_coeffs: B_1..B_N [-] (the shorter is padded with zeros);
            finite, not all zero. Raises InvalidParameter otherwise.)doc")
      .def_property_readonly("order", &FourierProfile::order, "N")
      .def_property_readonly(
          "cos_coeffs",
          [](const FourierProfile& p) { return to_array(std::vector(p.cos_coeffs())); },
          "A_1..A_N [-] (a copy)")
      .def_property_readonly(
          "sin_coeffs",
          [](const FourierProfile& p) { return to_array(std::vector(p.sin_coeffs())); },
          "B_1..B_N [-] (a copy)")
      .def_property_readonly("offset", &FourierProfile::offset, "c_0 [-]");
  def_record(
      cls,
      [](double period, const std::vector<double>& cos_coeffs,
         const std::vector<double>& sin_coeffs) {
        return FourierProfile(period, cos_coeffs, sin_coeffs);
      },
      field("period", &FourierProfile::period), field("cos_coeffs", &FourierProfile::cos_coeffs),
      field("sin_coeffs", &FourierProfile::sin_coeffs));
}

void bind_sampled(py::module_& m) {
  py::enum_<Interpolation> interpolation(m, "Interpolation",
                                         "How sampled accelerations are interpolated; also "
                                         "accepted as the strings 'constant' and 'linear'.");
  interpolation
      .value("constant", Interpolation::constant,
             "y'' = y''_i on [t_i, t_{i+1}) (piecewise constant: the exact solver applies)")
      .value("linear", Interpolation::linear, "y'' linear between samples (piecewise-cubic y)")
      .def(py::init(&parse_interpolation), py::arg("text"));
  refuse_unknown_values(interpolation, "Interpolation", 2);
  py::implicitly_convertible<py::str, Interpolation>();

  py::class_<AccelerationSamples> samples(m, "AccelerationSamples",
                                         "Samples (t_i, y''_i) of one table period.");
  samples
      .def(py::init([](const py::object& t, const py::object& ydd) {
             return AccelerationSamples{to_vector(t, "t"), to_vector(ydd, "ydd")};
           }),
           py::arg("t"), py::arg("ydd"),
           "t: sample times [-] (t[0] = 0, strictly increasing; the last is the period Δt); "
           "ydd: table accelerations at t [-].")
      .def_property(
          "t", [](const AccelerationSamples& s) { return to_array(std::vector(s.t)); },
          [](AccelerationSamples& s, const py::object& v) { s.t = to_vector(v, "t"); },
          "sample times (a float64 copy) [-] or [s]")
      .def_property(
          "ydd", [](const AccelerationSamples& s) { return to_array(std::vector(s.ydd)); },
          [](AccelerationSamples& s, const py::object& v) { s.ydd = to_vector(v, "ydd"); },
          "table accelerations at t (a float64 copy) [-] or [m/s^2]")
      .def("__len__", [](const AccelerationSamples& s) { return s.t.size(); })
      .def("__repr__", [](const AccelerationSamples& s) {
        Repr r("AccelerationSamples");
        r("samples", static_cast<long long>(s.t.size()));
        if (!s.t.empty()) r("period", s.t.back());
        return r.str();
      });
  def_record(samples, field("t", &AccelerationSamples::t),
             field("ydd", &AccelerationSamples::ydd));

  m.def(
      "read_acceleration_samples",
      [](const py::object& path) {
        if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
          throw py::type_error("path: expected a str or os.PathLike, got " + python_type_name(path));
        return read_acceleration_samples(py::str(py::module_::import("os").attr("fspath")(path)));
      },
      py::arg("path"), R"doc(
Reads a samples CSV: one 't,y''' pair per line, in the same unit system as the rest of the
input; blank lines, lines starting with '#', and one leading header line are ignored. The first
time must be 0, times strictly increasing; the last time is the period Δt. Raises
InvalidParameter naming the file and line on malformed input.)doc");

  m.def("make_sampled_profile", &make_sampled_profile, py::arg("samples"),
        py::arg("interpolation") = Interpolation::constant, R"doc(
The periodic profile of dimensionless samples, interpolated piecewise constant (returns a
PiecewisePolynomialProfile: the exact solver applies) or piecewise linear (returns a
LinearAccelerationProfile). The acceleration must integrate to zero over the period (1e-9
relative); the initial velocity makes y periodic and the initial position makes min y = 0.
Raises InvalidParameter on fewer than 2 samples, t[0] != 0, non-increasing or non-finite
times, non-finite accelerations or a non-zero net velocity change.)doc");

  py::class_<LinearAccelerationProfile, TableProfile> linear(
      m, "LinearAccelerationProfile",
      "Piecewise-linear acceleration (piecewise-cubic y) through samples; built by "
      "make_sampled_profile(samples, Interpolation.linear).");
  linear.def(py::init<const AccelerationSamples&>(), py::arg("samples"))
      .def_property_readonly("samples", &LinearAccelerationProfile::samples,
                             "the AccelerationSamples it was built from")
      .def("__repr__", [](const LinearAccelerationProfile& p) {
        return Repr("LinearAccelerationProfile")("period", p.period())(
                   "samples", static_cast<long long>(p.samples().t.size()))
            .str();
      });
  def_record(
      linear,
      [](std::vector<double> t, std::vector<double> ydd) {
        return LinearAccelerationProfile(AccelerationSamples{std::move(t), std::move(ydd)});
      },
      field("t", [](const LinearAccelerationProfile& p) { return p.samples().t; }),
      field("ydd", [](const LinearAccelerationProfile& p) { return p.samples().ydd; }));
}

}  // namespace

void bind_profiles(py::module_& m) {
  bind_table_profile(m);
  bind_piecewise_constant(m);
  bind_fourier(m);
  bind_sampled(m);
}

}  // namespace selfalign::python
