#include "selfalign/design/optimize.hpp"

#include <cmath>

#include "selfalign/design/fourier_design.hpp"
#include "selfalign/design/piecewise_design.hpp"
#include "selfalign/design/three_phase_design.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

namespace {
void require_in(const std::string& name, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw InvalidParameter(name, static_cast<double>(value),
                           "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}
}  // namespace

void validate(const ActuatorLimits& l) {
  // Positive scales within [1e-50, 1e50] (error.hpp): a limit of 1e195 made the scan run for
  // minutes on steady states of absurd accelerations.
  require_positive_moderate("period", l.period);
  require_positive_moderate("stroke", l.stroke);
  require_positive_moderate("max_velocity", l.max_velocity);
  require_positive_moderate("max_acceleration", l.max_acceleration);
  if (!(l.max_jerk > 0) || !(l.max_jerk >= 1 / kMaxMagnitude))
    throw InvalidParameter("max_jerk", l.max_jerk, "must be in [1e-50, +inf] (+inf: no limit)");
}

void validate(const OptimizeOptions& o) {
  // Upper bounds keep one call within minutes and its memory small (the paper's Fig. 6 uses
  // order 12; order 100 already has 200 design variables).
  require_in("order", o.order, 1, 100);
  require_in("segments", o.segments, 2, 64);
  require_in("starts", o.starts, 1, 1000);
  require_in("max_evaluations", o.max_evaluations, 1, 1'000'000);
  require_in("grid", o.grid, 2, 2000);
  require_in("polish", o.polish, 1, 1000);
  require_positive("fd_step", o.fd_step);
  if (o.threads < 0) throw InvalidParameter("threads", o.threads, "must be >= 0 (0: all cores)");
}

std::unique_ptr<TableProfile> rebuild_profile(const OptimizationResult& r) {
  if (!r.feasible)
    throw InvalidParameter("result", "infeasible", "rebuild needs a feasible optimum");
  const auto& x = r.parameters;
  if (r.family == "three-phase" && x.size() == 2)
    return make_three_phase_profile({r.limits.period, r.limits.stroke, x[0], x[1]},
                                    r.limits.max_jerk);
  if (r.family == "piecewise-constant" && x.size() >= 4 && x.size() % 2 == 0) {
    const std::size_t k = x.size() / 2;
    return std::make_unique<PiecewisePolynomialProfile>(PiecewisePolynomialProfile::from_accelerations(
        std::span<const double>(x.data(), k), std::span<const double>(x.data() + k, k),
        "piecewise-constant"));
  }
  if (r.family == "fourier" && x.size() >= 2 && x.size() % 2 == 0) {
    const std::size_t n = x.size() / 2;
    return std::make_unique<FourierProfile>(
        r.limits.period, std::vector<double>(x.begin(), x.begin() + static_cast<long>(n)),
        std::vector<double>(x.begin() + static_cast<long>(n), x.end()));
  }
  throw InvalidParameter("family", r.family,
                         "one of three-phase (2 parameters), piecewise-constant (2K), fourier (2N)");
}

std::vector<OptimizationResult> compare_families(const ActuatorLimits& limits,
                                                 const OptimizeOptions& options) {
  validate(limits);
  validate(options);
  std::vector<OptimizationResult> rows;
  rows.reserve(3);
  rows.push_back(optimize_three_phase(limits, options));
  rows.push_back(optimize_piecewise_constant(limits, options, &rows[0]));
  rows.push_back(optimize_fourier(limits, options, &rows[0]));
  return rows;
}

}  // namespace selfalign
