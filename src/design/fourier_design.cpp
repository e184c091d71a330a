#include "selfalign/design/fourier_design.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <string>
#include <vector>

#include "../profiles/periodic_extrema.hpp"
#include "selfalign/design/local_search.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"
#include "selfalign/analysis/sweep.hpp"  // worker_threads
#include "selfalign/error.hpp"

namespace selfalign {

namespace {

constexpr int kSamplesPerHarmonic = 32;    // extrema search grid of the optimiser
constexpr int kNewtonIterations = 8;       // cap of the Newton refinement of one extremum
constexpr int kMaxDerivative = 5;
constexpr int kResync = 16;                // harmonics between exact cos/sin in jet()          // tabulated powers (k w)^p: p = 0..5

// The q-th derivative of a cos(theta) + b sin(theta) with respect to theta (q quarter turns),
// from c = cos(theta), s = sin(theta).
double quarter_turns(double a, double b, double c, double s, int q) {
  switch (q % 4) {
    case 0: return a * c + b * s;
    case 1: return -a * s + b * c;
    case 2: return -a * c - b * s;
    default: return a * s - b * c;
  }
}

// Fast evaluation of a Fourier design x = (A_1..A_N, B_1..B_N) (unscaled): trigonometric
// tables on the extrema grid, extrema refined by Newton on the next derivative from every
// near-extreme grid point, then the exact steady state of the scaled series (smooth solver).
class FourierEvaluator {
 public:
  FourierEvaluator(const ActuatorLimits& l, int order, const FrictionLaw& law)
      : l_(l), law_(law), n_(order), w_(2 * std::numbers::pi / l.period) {
    table(kSamplesPerHarmonic * n_, grid_cos_, grid_sin_);
    powers_.resize(static_cast<std::size_t>((kMaxDerivative + 1) * n_));
    for (int p = 0; p <= kMaxDerivative; ++p)
      for (int k = 1; k <= n_; ++k) powers_[index(p, k)] = std::pow(k * w_, p);
  }

  // d-th derivative of y at t for coefficients x (unscaled), d <= kMaxDerivative.
  double derivative(std::span<const double> x, int d, double t) const {
    double v = 0;
    for (int k = 1; k <= n_; ++k) {
      const double ph = k * w_ * t;
      v += power(d, k) * quarter_turns(x[k - 1], x[n_ + k - 1], std::cos(ph), std::sin(ph), d);
    }
    return v;
  }

  // Derivatives d, d + 1 and d + 2 of y at t (d + 2 <= kMaxDerivative), in one pass: cos and
  // sin of k w t by the rotation recurrence from one sincos, re-seeded every kResync harmonics
  // (its rounding grows like k eps in between), as FourierProfile::derivatives does.
  std::array<double, 3> jet(std::span<const double> x, int d, double t) const {
    std::array<double, 3> g{};
    const double theta = w_ * t, c1 = std::cos(theta), s1 = std::sin(theta);
    double c = c1, s = s1;
    for (int k = 1; k <= n_; ++k) {
      if (k > 1 && (k - 1) % kResync == 0) c = std::cos(k * theta), s = std::sin(k * theta);
      const double a = x[k - 1], b = x[n_ + k - 1];
      for (int q = 0; q < 3; ++q) g[q] += power(d + q, k) * quarter_turns(a, b, c, s, d + q);
      const double c_next = c * c1 - s * s1;  // (k + 1) theta from k theta
      s = s * c1 + c * s1;
      c = c_next;
    }
    return g;
  }

  // min and max of the d-th derivative over the period (d = 0, 1, 2), from its samples on the
  // extrema grid (sampled_all), every near-extreme grid point refined by Newton.
  detail::Extrema extrema(std::span<const double> x, int d, const std::vector<double>& buf) const {
    const int s = kSamplesPerHarmonic * n_;
    const auto [lo_it, hi_it] = std::minmax_element(buf.begin(), buf.end());
    detail::Extrema e{*lo_it, *hi_it};
    const double margin = 0.05 * (e.max - e.min), h = l_.period / s;
    for (int j = 0; j < s; ++j) {
      const double v = buf[static_cast<std::size_t>(j)];
      const double prev = buf[static_cast<std::size_t>((j + s - 1) % s)];
      const double next = buf[static_cast<std::size_t>((j + 1) % s)];
      const bool is_max = v >= prev && v >= next && v >= e.max - margin;
      const bool is_min = v <= prev && v <= next && v <= e.min + margin;
      if (is_max || is_min) refine(x, d, j * h, h, e);
    }
    return e;
  }

  struct Point {
    bool valid = false;
    double scale = 0;  // common factor that makes the stroke Δy
    double v_bar = 0, max_velocity = 0, max_acceleration = 0;
    Method method = Method::exact;  // of the steady state (integrator: velocity-dependent law)
    double x_dot_0s = 0;            // of a converged steady state: the next evaluation's start
    double slope = std::numeric_limits<double>::quiet_NaN();  // its map's slope (ditto)
    bool converged = false;
  };

  // Thread-safe. `warm`: the steady-state search starts there (a neighbour's x'_0s: the
  // optimiser's finite-difference points lie 1e-6 apart, about half the periods of a start
  // from rest, and the same fixed point).
  struct Warm {
    double velocity = 0;
    double slope = std::numeric_limits<double>::quiet_NaN();
  };
  Point evaluate(std::span<const double> x, const Warm& warm) const {
    Point p;
    std::array<std::vector<double>, 3> grid;  // y, y', y'' on the extrema grid (per call)
    sampled_all(x, grid);
    const detail::Extrema ey = extrema(x, 0, grid[0]);
    if (!(ey.max - ey.min > 1e-300)) return p;
    p.scale = l_.stroke / (ey.max - ey.min);
    if (!std::isfinite(p.scale)) return p;
    const detail::Extrema ev = extrema(x, 1, grid[1]), ea = extrema(x, 2, grid[2]);
    p.max_velocity = p.scale * std::max(-ev.min, ev.max);
    p.max_acceleration = p.scale * std::max(-ea.min, ea.max);
    const FourierProfile profile = scaled_profile(x, p.scale, ey, p.max_acceleration);
    SteadyStateOptions options;
    options.initial_velocity = warm.velocity;
    options.initial_slope = warm.slope;
    const SteadyState st = steady_state(profile, law_, options);
    p.converged = st.converged;
    p.x_dot_0s = st.x_dot_0s;
    p.slope = st.slope;
    p.method = st.method;
    p.v_bar = trusted_v_bar(st, p.max_velocity, l_.period);
    p.valid = std::isfinite(p.v_bar);
    return p;
  }

 private:
  std::size_t index(int p, int k) const { return static_cast<std::size_t>(p * n_ + k - 1); }
  double power(int p, int k) const { return powers_[index(p, k)]; }  // (k w)^p

  // Newton on the (d+1)-th derivative from the grid point t0, kept within the neighbouring
  // cells [t0 - h, t0 + h]; every iterate's value of the d-th derivative widens e (each is a
  // value the function takes). Stops when the step falls below 1e-15 Δt (converged).
  void refine(std::span<const double> x, int d, double t0, double h, detail::Extrema& e) const {
    double t = t0;
    for (int it = 0; it < kNewtonIterations; ++it) {
      const std::array<double, 3> g = jet(x, d, t);
      e.max = std::max(e.max, g[0]);
      e.min = std::min(e.min, g[0]);
      if (g[2] == 0) break;
      const double next = std::clamp(t - g[1] / g[2], t0 - h, t0 + h);
      if (std::abs(next - t) <= 1e-15 * l_.period) break;
      t = next;
    }
  }

  // The series scale * x with the extrema already found (no second search: with_extrema).
  FourierProfile scaled_profile(std::span<const double> x, double scale,
                                const detail::Extrema& ey, double peak_acceleration) const {
    const auto n = static_cast<std::size_t>(n_);
    std::vector<double> a(n), b(n);
    for (std::size_t k = 0; k < n; ++k) {
      a[k] = scale * x[k];
      b[k] = scale * x[n + k];
    }
    return FourierProfile::with_extrema(l_.period, std::move(a), std::move(b),
                                        {.y_min = scale * ey.min,
                                         .y_max = scale * ey.max,
                                         .peak_acceleration = peak_acceleration});
  }

  void table(int s, std::vector<double>& c, std::vector<double>& sn) const {
    c.resize(static_cast<std::size_t>(s * n_));
    sn.resize(c.size());
    for (int j = 0; j < s; ++j)
      for (int k = 1; k <= n_; ++k) {
        const double ph = k * w_ * (l_.period * j / s);
        c[static_cast<std::size_t>(j * n_ + k - 1)] = std::cos(ph);
        sn[static_cast<std::size_t>(j * n_ + k - 1)] = std::sin(ph);
      }
  }

  // y, y', y'' on the extrema grid of 32 N points in one pass over the tables: per harmonic
  // and derivative d, (k w)^d times the coefficients rotated by d quarter turns, then dot
  // products with the tabulated cos and sin.
  void sampled_all(std::span<const double> x, std::array<std::vector<double>, 3>& out) const {
    const auto n = static_cast<std::size_t>(n_);
    std::array<std::vector<double>, 3> rc, rs;
    for (int d = 0; d < 3; ++d) {
      rc[d].resize(n);
      rs[d].resize(n);
      for (int k = 1; k <= n_; ++k) {
        const double a = x[k - 1], b = x[n_ + k - 1], p = power(d, k);
        // quarter_turns(a, b, c, s, d) = rc c + rs s
        rc[d][k - 1] = p * quarter_turns(a, b, 1, 0, d);
        rs[d][k - 1] = p * quarter_turns(a, b, 0, 1, d);
      }
    }
    const auto samples = static_cast<std::size_t>(kSamplesPerHarmonic * n_);
    for (auto& o : out) o.resize(samples);
    for (std::size_t j = 0; j < samples; ++j) {
      const double* c = grid_cos_.data() + j * n;
      const double* sn = grid_sin_.data() + j * n;
      double v0 = 0, v1 = 0, v2 = 0;
      for (std::size_t k = 0; k < n; ++k) {
        v0 += rc[0][k] * c[k] + rs[0][k] * sn[k];
        v1 += rc[1][k] * c[k] + rs[1][k] * sn[k];
        v2 += rc[2][k] * c[k] + rs[2][k] * sn[k];
      }
      out[0][j] = v0;
      out[1][j] = v1;
      out[2][j] = v2;
    }
  }

  ActuatorLimits l_;
  FrictionLaw law_;
  int n_;
  double w_;
  std::vector<double> grid_cos_, grid_sin_, powers_;
};

// How the steady states were computed, for the result message.
std::string solver_name(Method method) {
  switch (method) {
    case Method::exact: return "the exact smooth solver";
    case Method::integrator: return "the slip integrator (velocity-dependent law)";
    default: return "time-stepping";
  }
}

// Scales a start so that max |x_i| = 0.5 (inside the [-1, 1] box).
void normalise(std::vector<double>& x) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  if (m > 0)
    for (double& v : x) v *= 0.5 / m;
}

}  // namespace

PiecewisePolynomialProfile fourier_approximation(const TableProfile& profile, int segments) {
  if (segments < 2)
    throw InvalidParameter("segments", static_cast<double>(segments),
                           "must be >= 2");
  const double dt = profile.period(), h = dt / segments;
  std::vector<double> v(static_cast<std::size_t>(segments));
  for (int i = 0; i < segments; ++i) v[static_cast<std::size_t>(i)] = profile.velocity(i * h);
  std::vector<double> d(v.size(), h), a(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) a[i] = (v[(i + 1) % v.size()] - v[i]) / h;
  return PiecewisePolynomialProfile::from_accelerations(d, a, "fourier-approximation");
}

SteadyState approximate_steady_state(const TableProfile& profile, int segments) {
  return steady_state(fourier_approximation(profile, segments));
}

double max_abs_velocity(const FourierProfile& profile) {
  auto yd = [&profile](double t) { return profile.state(t).yd; };
  auto ydd = [&profile](double t) { return profile.state(t).ydd; };
  const detail::Extrema e =
      detail::periodic_extrema(yd, ydd, profile.period(), 128 * profile.order());
  return std::max(-e.min, e.max);
}

void fourier_series_of(const PiecewisePolynomialProfile& profile, int order,
                       std::vector<double>& cos_coeffs, std::vector<double>& sin_coeffs) {
  const double dt = profile.period(), w = 2 * std::numbers::pi / dt;
  const auto segs = profile.segments();
  cos_coeffs.assign(static_cast<std::size_t>(order), 0.0);
  sin_coeffs.assign(static_cast<std::size_t>(order), 0.0);
  for (int k = 1; k <= order; ++k) {
    const double kw = k * w;
    double alpha = 0, beta = 0;  // Fourier coefficients of y''
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const double ta = segs[i].begin, tb = i + 1 < segs.size() ? segs[i + 1].begin : dt;
      alpha += segs[i].accel * (std::sin(kw * tb) - std::sin(kw * ta)) / kw;
      beta += -segs[i].accel * (std::cos(kw * tb) - std::cos(kw * ta)) / kw;
    }
    const double x = k * std::numbers::pi / (order + 1);
    const double sigma = std::sin(x) / x;  // Lanczos factor against Gibbs overshoot
    cos_coeffs[static_cast<std::size_t>(k - 1)] = -sigma * (2 / dt) * alpha / (kw * kw);
    sin_coeffs[static_cast<std::size_t>(k - 1)] = -sigma * (2 / dt) * beta / (kw * kw);
  }
}

OptimizationResult optimize_fourier(const ActuatorLimits& l, const OptimizeOptions& o,
                                    const OptimizationResult* three_phase_start) {
  validate(l);
  validate(o);
  OptimizationResult r;
  r.family = "fourier";
  r.limits = l;
  const int n = o.order;
  const FourierEvaluator evaluator(l, n, o.law);

  LocalSearchProblem problem;
  problem.lower.assign(static_cast<std::size_t>(2 * n), -1.0);
  problem.upper.assign(static_cast<std::size_t>(2 * n), 1.0);
  problem.constraint_names = {"max_velocity", "max_acceleration"};
  problem.gradient_based = true;
  problem.fd_step = o.fd_step;
  problem.max_evaluations = o.max_evaluations;
  problem.feasibility_tol = kFeasibilityTol;
  problem.relative_tol = 1e-9;
  auto design = [&l](const FourierEvaluator::Point& p) {
    DesignEvaluation e;
    if (!p.valid) {
      e.objective = design_objective(-1.0, l.period, l.stroke);
      e.constraints = {1.0, 1.0};
      return e;
    }
    e.objective = design_objective(p.v_bar, l.period, l.stroke);
    e.constraints = {p.max_velocity / l.max_velocity - 1.0,
                     p.max_acceleration / l.max_acceleration - 1.0};
    return e;
  };
  // Sequential evaluations warm-start from the last converged one; a finite-difference stencil
  // from its centre (evaluated just before), on every worker thread alike: deterministic.
  FourierEvaluator::Warm warm;
  problem.evaluate = [&](std::span<const double> x) {
    const FourierEvaluator::Point p = evaluator.evaluate(x, warm);
    if (p.converged) warm = {p.x_dot_0s, p.slope};
    return design(p);
  };
  tbb::task_arena arena(worker_threads(o.threads));
  problem.evaluate_many = [&](const std::vector<std::vector<double>>& points,
                              std::vector<DesignEvaluation>& out,
                              const std::function<void()>& heartbeat) {
    const FourierEvaluator::Warm centre = warm;
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t i) {
        heartbeat();
        out[i] = design(evaluator.evaluate(points[i], centre));
      });
    });
  };

  std::vector<std::vector<double>> starts;
  const OptimizationResult three = three_phase_seed(l, o, three_phase_start, r.evaluations);
  if (three.feasible) {
    std::vector<double> a, b;
    fourier_series_of(*rebuild_profile(three)->piecewise_polynomial(), n, a, b);
    a.insert(a.end(), b.begin(), b.end());
    normalise(a);
    starts.push_back(std::move(a));
  }
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (static_cast<int>(starts.size()) < o.starts) {
    std::vector<double> x(static_cast<std::size_t>(2 * n));
    for (int k = 1; k <= n; ++k) {
      x[static_cast<std::size_t>(k - 1)] = u(rng) / (k * k);
      x[static_cast<std::size_t>(n + k - 1)] = u(rng) / (k * k);
    }
    normalise(x);
    // Mirror (y -> -y, hence v̄ -> -v̄) a start that drives the object backwards.
    if (is_backward_penalty(problem.evaluate(x).objective))
      for (double& v : x) v = -v;
    ++r.evaluations;
    starts.push_back(std::move(x));
  }

  const LocalSearchResult best = local_search(problem, starts, o.progress);
  r.evaluations += best.evaluations;
  r.starts = best.runs;
  if (!best.feasible) {
    r.message = infeasible_message("order-" + std::to_string(n) + " Fourier profile", best);
    return r;
  }
  const FourierEvaluator::Point p = evaluator.evaluate(best.x, {});  // from rest: as reported
  const auto nn = static_cast<long>(n);
  std::vector<double> a(best.x.begin(), best.x.begin() + nn), b(best.x.begin() + nn, best.x.end());
  for (double& v : a) v *= p.scale;
  for (double& v : b) v *= p.scale;
  const FourierProfile profile(l.period, a, b);
  r.parameters = a;
  r.parameters.insert(r.parameters.end(), b.begin(), b.end());
  r.v_bar = p.v_bar;
  r.f = objective_f(p.v_bar);
  r.max_velocity = max_abs_velocity(profile);
  r.max_acceleration = profile.peak_acceleration();
  r.max_jerk = 0;  // |d3y/dt3| sampled at 64 N points of the period (of the scaled series)
  for (int i = 0; i < 64 * n; ++i) {
    const double t = l.period * i / (64.0 * n);
    r.max_jerk = std::max(r.max_jerk, std::abs(p.scale * evaluator.derivative(best.x, 3, t)));
  }
  const double slack = 1 + 1e-9;
  r.feasible = p.v_bar > 0 && r.max_velocity <= l.max_velocity * slack &&
               r.max_acceleration <= l.max_acceleration * slack &&
               r.max_jerk <= l.max_jerk * slack;
  r.message = r.feasible ? "order-" + std::to_string(n) + " optimum by LD_SLSQP (central FD " +
                               "gradients) from " + std::to_string(best.runs) +
                               " starts; f by " + solver_name(p.method)
                         : "no order-" + std::to_string(n) +
                               " Fourier profile moves the object forward within the limits";
  return r;
}

}  // namespace selfalign
