#include "selfalign/analysis/sweep.hpp"

#include "selfalign/analysis/three_phase_steady_state.hpp"

#ifndef SELFALIGN_SERIAL
#include <tbb/info.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>

#include "parallel_cells.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {

std::vector<double> linear_grid(double lo, double hi, int n) {
  require_finite("grid lower end", lo);
  require_finite("grid upper end", hi);
  if (n < 1 || n > kMaxGridPoints) throw InvalidParameter("grid size", n, "must be in [1, 1e7]");
  std::vector<double> g(static_cast<std::size_t>(n));
  // std::lerp: exact ends, monotone, and no overflow of hi - lo for ends near ±1.8e308.
  for (int i = 0; i < n; ++i)
    g[static_cast<std::size_t>(i)] =
        n == 1 ? lo : std::lerp(lo, hi, static_cast<double>(i) / static_cast<double>(n - 1));
  return g;
}

std::vector<double> log_grid(double lo, double hi, int n) {
  require_positive("grid lower end", lo);
  require_positive("grid upper end", hi);
  std::vector<double> g = linear_grid(std::log(lo), std::log(hi), n);
  for (double& v : g) v = std::exp(v);
  if (n > 1) {  // exact end points
    g.front() = lo;
    g.back() = hi;
  }
  return g;
}

int worker_threads(int requested) {
  if (requested < 0) throw InvalidParameter("threads", requested, "must be >= 0 (0: all cores)");
#ifdef SELFALIGN_SERIAL
  const int cores = 1;  // the single-threaded build (WebAssembly)
#else
  const int cores = std::max(1, tbb::info::default_concurrency());
#endif
  return requested == 0 ? cores : std::min(requested, cores);
}

namespace {

constexpr double kMaxCells = kMaxGridPoints;  // ~1 GB of results; hours of work

}  // namespace

std::size_t acceleration_cells(const std::vector<double>& a2, const std::vector<double>& a3) {
  const double cells = static_cast<double>(a2.size()) * static_cast<double>(a3.size());
  if (cells > kMaxCells)
    throw InvalidParameter("cells", cells, "len(a2) x len(a3) must be <= 1e7");
  return a2.size() * a3.size();
}

bool closed_form_cells(const SweepOptions& o) noexcept {
  return o.closed_form && std::isinf(o.jerk) && three_phase_closed_form_applies(o.law);
}

void sweep_accelerations(double period, double stroke, const std::vector<double>& a2,
                         const std::vector<double>& a3, const SweepOptions& o,
                         const AccelerationSink& sink) {
  require_positive("period", period);
  require_positive("stroke", stroke);
  for (double v : a2) require_positive("a2", v);
  for (double v : a3) require_positive("a3", v);
  if (!(o.jerk > 0)) throw InvalidParameter("jerk", o.jerk, "must be > 0 (+inf: jump accelerations)");
  const std::size_t n = acceleration_cells(a2, a3);
  const bool closed_form = closed_form_cells(o);
  auto cell_at = [&](std::size_t k) {
    AccelerationCell c;
    c.a2 = a2[k / a3.size()];
    c.a3 = a3[k % a3.size()];
    return c;
  };
  detail::parallel_cells(n, o, [&](std::size_t k) {
    AccelerationCell c = cell_at(k);
    const ThreePhaseParameters p{period, stroke, c.a2, c.a3};
    if (closed_form) {  // a formula per cell (docs/three-phase-steady-state.md)
      const ThreePhaseSolution r = solve_three_phase(p);
      const ThreePhaseSteadyState s = three_phase_steady_state(p, r, o.law);
      c.predicted = predict_case(p, r);
      c.observed = s.motion_case;
      c.v_bar = s.v_bar;
      c.f = s.f;
      c.x_dot_0s = s.x_dot_0s;
      c.converged = r.physical;
      return sink(k, c);
    }
    c.predicted = predict_case(p);
    const bool physical = std::isinf(o.jerk) ? c.predicted != StickSlipCase::non_physical
                                             : three_phase_is_physical(p, o.jerk);
    if (!physical) {
      c.observed = StickSlipCase::non_physical;
      c.v_bar = c.f = c.x_dot_0s = kNaN;
      return sink(k, c);
    }
    const SteadyState s = steady_state(*make_three_phase_profile(p, o.jerk), o.law, o.steady);
    c.observed = s.motion_case;
    c.v_bar = s.v_bar;
    c.f = s.f;
    c.x_dot_0s = s.x_dot_0s;
    c.converged = s.converged;
    sink(k, c);
  }, [&](std::size_t k, const std::string& why) {
    AccelerationCell c = cell_at(k);
    c.observed = StickSlipCase::non_physical;
    c.v_bar = c.f = c.x_dot_0s = kNaN;
    c.converged = false;
    c.failure = why;
    sink(k, c);
  });
}

std::vector<AccelerationCell> sweep_accelerations(double period, double stroke,
                                                  const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const SweepOptions& o) {
  std::vector<AccelerationCell> cells;
  // sized only within the bound: the sink form checks the inputs in order, the cells last
  if (static_cast<double>(a2.size()) * static_cast<double>(a3.size()) <= kMaxCells)
    cells.resize(a2.size() * a3.size());
  sweep_accelerations(period, stroke, a2, a3, o,
                      [&](std::size_t k, const AccelerationCell& c) { cells[k] = c; });
  return cells;
}

ThreePhaseFamily::ThreePhaseFamily(double a2, double a3)
    : a2_(require_positive("a2", a2)), a3_(require_positive("a3", a3)) {}

std::unique_ptr<TableProfile> ThreePhaseFamily::make(double period, double stroke) const {
  const ThreePhaseParameters p{period, stroke, a2_, a3_};
  if (!solve_three_phase(p).physical) return nullptr;
  return std::make_unique<ThreePhaseProfile>(p);
}

JerkLimitedThreePhaseFamily::JerkLimitedThreePhaseFamily(double a2, double a3, double jerk)
    : a2_(a2), a3_(a3), jerk_(jerk) {
  validate(JerkLimitedThreePhaseParameters{1.0, 1.0, a2, a3, jerk});
}

std::unique_ptr<TableProfile> JerkLimitedThreePhaseFamily::make(double period,
                                                                double stroke) const {
  const JerkLimitedThreePhaseParameters p{period, stroke, a2_, a3_, jerk_};
  if (!solve_jerk_limited_three_phase(p).physical) return nullptr;
  return std::make_unique<JerkLimitedThreePhaseProfile>(p);
}

ScaledShapeFamily::ScaledShapeFamily(PiecewisePolynomialProfile shape) : shape_(std::move(shape)) {}

ScaledShapeFamily ScaledShapeFamily::paper_like() {
  const double durations[3] = {0.35, 0.35, 0.30}, accels[3] = {0.0, -6.0 / 7.0, 1.0};
  return ScaledShapeFamily(
      PiecewisePolynomialProfile::from_accelerations(durations, accels, "scaled-shape"));
}

std::unique_ptr<TableProfile> ScaledShapeFamily::make(double period, double stroke) const {
  require_positive("period", period);
  require_positive("stroke", stroke);
  const double time_scale = period / shape_.period();
  const double accel_scale = stroke / shape_.stroke() / (time_scale * time_scale);
  const auto segs = shape_.segments();
  std::vector<double> durations, begin, end;
  for (const AccelerationSegment& s : segs) {
    durations.push_back(s.duration * time_scale);
    begin.push_back(s.accel * accel_scale);
    end.push_back(s.jerk == 0 ? s.accel * accel_scale : s.end_accel() * accel_scale);
  }
  return std::make_unique<PiecewisePolynomialProfile>(
      PiecewisePolynomialProfile::from_linear_accelerations(durations, begin, end,
                                                            "scaled-shape"));
}

ScaledFourierFamily::ScaledFourierFamily(std::vector<double> cos_coeffs,
                                         std::vector<double> sin_coeffs)
    : cos_(std::move(cos_coeffs)),
      sin_(std::move(sin_coeffs)),
      unit_stroke_(FourierProfile(1.0, cos_, sin_).stroke()) {}

std::unique_ptr<TableProfile> ScaledFourierFamily::make(double period, double stroke) const {
  require_positive("stroke", stroke);
  const double k = stroke / unit_stroke_;  // the stroke is linear in the coefficients
  std::vector<double> c = cos_, s = sin_;
  for (double& v : c) v *= k;
  for (double& v : s) v *= k;
  return std::make_unique<FourierProfile>(period, std::move(c), std::move(s));
}

namespace {
std::vector<FamilyPoint> sweep_family(const ProfileFamily& family,
                                      const std::vector<std::pair<double, double>>& points,
                                      const SweepOptions& o) {
  if (static_cast<double>(points.size()) > kMaxCells)
    throw InvalidParameter("cells", static_cast<double>(points.size()), "must be <= 1e7");
  std::vector<FamilyPoint> out(points.size());
  detail::parallel_cells(points.size(), o, [&](std::size_t k) {
    FamilyPoint& pt = out[k];
    pt.period = points[k].first;
    pt.stroke = points[k].second;
    const std::unique_ptr<TableProfile> profile = family.make(pt.period, pt.stroke);
    if (!profile) {
      pt.v_bar = pt.f = kNaN;
      return;
    }
    pt.physical = true;
    const SteadyState s = steady_state(*profile, o.law, o.steady);
    pt.observed = s.motion_case;
    pt.v_bar = s.v_bar;
    pt.f = s.f;
  }, [&](std::size_t k, const std::string& why) {
    FamilyPoint& pt = out[k];
    pt.observed = StickSlipCase::non_physical;
    pt.v_bar = pt.f = kNaN;
    pt.failure = why;
  });
  return out;
}
}  // namespace

std::vector<FamilyPoint> sweep_period(const ProfileFamily& family, double stroke,
                                      const std::vector<double>& periods, const SweepOptions& o) {
  require_positive("stroke", stroke);
  std::vector<std::pair<double, double>> points;
  for (double p : periods) points.emplace_back(require_positive("period", p), stroke);
  return sweep_family(family, points, o);
}

std::vector<FamilyPoint> sweep_stroke(const ProfileFamily& family, double period,
                                      const std::vector<double>& strokes, const SweepOptions& o) {
  require_positive("period", period);
  std::vector<std::pair<double, double>> points;
  for (double s : strokes) points.emplace_back(period, require_positive("stroke", s));
  return sweep_family(family, points, o);
}

}  // namespace selfalign
