#include "selfalign/design/piecewise_design.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/design/local_search.hpp"
#include "selfalign/design/three_phase_design.hpp"
#include "selfalign/error.hpp"

namespace selfalign {

namespace {


// Design variables of a profile with segment durations d and accelerations a as a K-segment
// profile (K >= d.size()): the longest segment split in halves until there are K. The same
// profile up to rounding: w_i = d_i/Δt, b_i = a_i/max|a| (piecewise_design_profile restores
// the scale from the exact stroke). Empty when it has more than K segments.
std::vector<double> embed_segments(std::vector<double> d, std::vector<double> a, double period,
                                   int k) {
  while (static_cast<int>(d.size()) < k) {
    const auto i = static_cast<std::size_t>(std::max_element(d.begin(), d.end()) - d.begin());
    d[i] *= 0.5;
    d.insert(d.begin() + static_cast<long>(i), d[i]);
    a.insert(a.begin() + static_cast<long>(i), a[i]);
  }
  if (static_cast<int>(d.size()) > k) return {};
  double amax = 0;
  for (double v : a) amax = std::max(amax, std::abs(v));
  if (!(amax > 0)) return {};
  std::vector<double> x;
  for (double v : d) x.push_back(v / period);
  for (double v : a) x.push_back(v / amax);
  return x;
}

// A three-phase optimum as a K-segment start (K >= 3).
std::vector<double> embed_three_phase(const OptimizationResult& three, int k) {
  const auto profile = rebuild_profile(three);
  const auto segs = profile->piecewise_polynomial()->segments();
  std::vector<double> d, a;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const double end = i + 1 < segs.size() ? segs[i + 1].begin : profile->period();
    d.push_back(end - segs[i].begin);
    a.push_back(segs[i].accel);
  }
  return embed_segments(std::move(d), std::move(a), profile->period(), k);
}

}  // namespace

bool piecewise_design_profile(const ActuatorLimits& l, std::span<const double> x,
                              std::vector<double>& durations, std::vector<double>& accels) {
  const std::size_t k = x.size() / 2;
  const double wsum = std::accumulate(x.begin(), x.begin() + static_cast<long>(k), 0.0);
  if (!(wsum > 0)) return false;
  durations.resize(k);
  accels.resize(k);
  double mean = 0, amax = 0;
  for (std::size_t i = 0; i < k; ++i) {
    durations[i] = l.period * x[i] / wsum;
    mean += x[k + i] * durations[i];
  }
  mean /= std::accumulate(durations.begin(), durations.end(), 0.0);
  for (std::size_t i = 0; i < k; ++i) {
    accels[i] = x[k + i] - mean;  // sum a_i d_i = 0: y' periodic
    amax = std::max(amax, std::abs(accels[i]));
  }
  if (!(amax > 1e-9)) return false;
  for (double& a : accels) a /= amax;
  // The stroke is linear in a common acceleration scale at fixed durations.
  const double s = PiecewisePolynomialProfile::from_accelerations(durations, accels).stroke();
  if (!(s > 0)) return false;
  for (double& a : accels) a *= l.stroke / s;
  return true;
}

double max_abs_velocity(const PiecewisePolynomialProfile& profile) {
  double m = 0;  // y' is piecewise linear and periodic: its extrema are at segment starts
  for (const AccelerationSegment& s : profile.segments()) m = std::max(m, std::abs(s.yd));
  return m;
}

namespace {

// Progress over the chain K = 2 .. K_max: each level reports runs as done out of the chain's
// total (every level counted as `per_level` runs; a level with fewer completes its share).
struct ChainProgress {
  const std::function<void(int, int)>* report = nullptr;
  int per_level = 0, total = 0;
  int offset(int k) const { return (k - 2) * per_level; }
};

OptimizationResult optimize_segments(const ActuatorLimits& l, const OptimizeOptions& o, int k,
                                     const OptimizationResult& three,
                                     const ChainProgress& progress) {
  OptimizationResult r;
  r.family = "piecewise-constant";
  r.limits = l;
  const auto n = static_cast<std::size_t>(2 * k);

  // The warm start: the (K-1)-segment optimum, one segment split in two. The K family holds
  // every (K-1) profile, so with that start (which local_search keeps if nothing beats it) the
  // optimum never falls as K grows (issue 9). K = 3 also starts from the three-phase optimum.
  std::vector<std::vector<double>> starts;
  std::string warm;
  if (k > 2) {
    const OptimizationResult smaller = optimize_segments(l, o, k - 1, three, progress);
    r.evaluations += smaller.evaluations;
    r.starts += smaller.starts;
    if (smaller.feasible) {
      const auto m = smaller.parameters.size() / 2;
      std::vector<double> x = embed_segments(
          std::vector<double>(smaller.parameters.begin(),
                              smaller.parameters.begin() + static_cast<long>(m)),
          std::vector<double>(smaller.parameters.begin() + static_cast<long>(m),
                              smaller.parameters.end()),
          l.period, k);
      if (!x.empty()) {
        starts.push_back(std::move(x));
        warm = "the " + std::to_string(k - 1) + "-segment optimum";
      }
    }
  }
  if (k == 3 && three.feasible) {
    std::vector<double> x = embed_three_phase(three, k);
    if (!x.empty()) {
      starts.push_back(std::move(x));
      warm += std::string(warm.empty() ? "" : " and ") + "the three-phase optimum";
    }
  }

  LocalSearchProblem problem;
  problem.lower.assign(n, -1.0);
  problem.upper.assign(n, 1.0);
  std::fill(problem.lower.begin(), problem.lower.begin() + k, 0.0);
  problem.constraint_names = {"max_velocity", "max_acceleration"};
  problem.max_evaluations = o.max_evaluations;
  problem.feasibility_tol = kFeasibilityTol;
  problem.evaluate = [&l, &o, d = std::vector<double>(), a = std::vector<double>()](
                         std::span<const double> x) mutable {
    DesignEvaluation e;
    if (!piecewise_design_profile(l, x, d, a)) {
      e.objective = design_objective(-1.0, l.period, l.stroke);
      e.constraints = {1.0, 1.0};
      return e;
    }
    const auto profile = PiecewisePolynomialProfile::from_accelerations(d, a, "piecewise-constant");
    e.objective = design_objective(
        trusted_v_bar(steady_state(profile, o.law), max_abs_velocity(profile), l.period), l.period,
        l.stroke);
    e.constraints = {max_abs_velocity(profile) / l.max_velocity - 1.0,
                     profile.peak_acceleration() / l.max_acceleration - 1.0};
    return e;
  };

  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> uw(0.1, 1.0), ub(-1.0, 1.0);
  while (static_cast<int>(starts.size()) < o.starts) {
    std::vector<double> x(n);
    for (int i = 0; i < k; ++i) x[static_cast<std::size_t>(i)] = uw(rng);
    for (std::size_t i = static_cast<std::size_t>(k); i < n; ++i) x[i] = ub(rng);
    // Mirror (y -> -y, hence v̄ -> -v̄) a start that drives the object backwards.
    if (is_backward_penalty(problem.evaluate(x).objective))
      for (std::size_t i = static_cast<std::size_t>(k); i < n; ++i) x[i] = -x[i];
    ++r.evaluations;
    starts.push_back(std::move(x));
  }

  std::function<void(int, int)> level_progress;
  if (progress.report && *progress.report)
    level_progress = [&progress, k](int done, int total) {
      const int share = total > 0 ? done * progress.per_level / total : progress.per_level;
      (*progress.report)(progress.offset(k) + share, progress.total);
    };
  const LocalSearchResult best = local_search(problem, starts, level_progress);
  r.evaluations += best.evaluations;
  r.starts += best.runs;
  if (!best.feasible) {
    r.message = infeasible_message(std::to_string(k) + "-segment profile", best);
    return r;
  }
  std::vector<double> d, a;
  piecewise_design_profile(l, best.x, d, a);
  const auto profile = PiecewisePolynomialProfile::from_accelerations(d, a, "piecewise-constant");
  const SteadyState st = steady_state(profile, o.law);
  r.parameters = d;
  r.parameters.insert(r.parameters.end(), a.begin(), a.end());
  r.v_bar = st.v_bar;
  r.f = st.f;
  r.max_velocity = max_abs_velocity(profile);
  r.max_acceleration = profile.peak_acceleration();
  r.feasible = trusted_v_bar(st, r.max_velocity, l.period) > 0;
  r.message = r.feasible ? std::to_string(k) + "-segment optimum by LN_COBYLA from " +
                               std::to_string(best.runs) + " starts" +
                               (warm.empty() ? "" : " (warm: " + warm + ")")
                         : "no " + std::to_string(k) +
                               "-segment profile moves the object forward within the limits";
  return r;
}

}  // namespace

OptimizationResult optimize_piecewise_constant(const ActuatorLimits& l, const OptimizeOptions& o,
                                               const OptimizationResult* three_phase_start) {
  validate(l);
  validate(o);
  if (std::isfinite(l.max_jerk)) {  // its accelerations jump: infinite jerk
    OptimizationResult r;
    r.family = "piecewise-constant";
    r.limits = l;
    r.message = "no feasible piecewise-constant profile: max_jerk = " +
                format_number(l.max_jerk) +
                " is binding (piecewise-constant accelerations jump: infinite jerk)";
    return r;
  }
  const int k = o.segments;
  OptimizationResult three;
  int evaluations = 0;
  if (k >= 3) three = three_phase_seed(l, o, three_phase_start, evaluations);
  ChainProgress progress;
  progress.report = &o.progress;
  progress.per_level = std::max(o.starts, 2);
  progress.total = (k - 1) * progress.per_level;
  OptimizationResult r = optimize_segments(l, o, k, three, progress);
  r.evaluations += evaluations;
  if (o.progress) o.progress(progress.total, progress.total);
  return r;
}

}  // namespace selfalign
