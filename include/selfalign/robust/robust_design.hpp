#pragma once
/// \file robust_design.hpp
/// `selfalign design --robust`: the fastest process that still works when the friction data
/// and the geometry are uncertain (docs/robust-design.md). Minimises a quantile of the
/// process time T_p (e.g. the 99th percentile) subject to P(|end - target| <= tolerance) >=
/// a target probability, under a ProcessUncertainty.
///
/// The search, over design_process's candidate grid (nominal mu and width):
///  1. a closed-form screen: with the same `screening_runs` draws for every candidate, the
///     fraction of draws in which the part can both slip forward (y2'' > mu_static g) and stop
///     for good (max(y2'', y3'') <= mu_static c_mu g, eq. 40) bounds P(within) from above;
///     candidates whose bound is below the target are dropped (if every one is, the best
///     bounds are kept to find the best achievable probability);
///  2. one run per candidate at the nominal inputs (candidates that do not stop are dropped),
///     then a Monte-Carlo screen on those draws in the order of the nominal T_p, in batches; a
///     screening run may take slow_factor x the nominal T_p. The rough region's start x_mu is
///     placed to put the most end positions within the tolerance (a window of width 2 x
///     tolerance slid over the sorted ends). Once a candidate qualifies with screened T_p
///     quantile T*, later batches skip candidates whose nominal T_p exceeds T*;
///  3. a verification Monte Carlo (another seed, `verification_runs` runs) of the best
///     `finalists`: the fastest whose 95% Wilson lower bound of P(within) reaches the target
///     is the design; if none does, the result says so and gives the best probability found.

#include <cmath>
#include <cstdint>
#include <string>

#include "selfalign/robust/monte_carlo.hpp"

namespace selfalign {

struct RobustOptions {
  double probability_target = 0.99;  ///< required P(within tolerance), in (0, 1)
  double time_quantile = 0.99;       ///< the quantile of T_p minimised, in (0, 1)
  int screening_runs = 200;          ///< draws per candidate in the screen, in [10, 1e5]
  int verification_runs = 4000;      ///< runs of each finalist's verification, in [100, 1e7]
  int finalists = 6;                 ///< candidates verified, in [1, 1000]
  std::uint64_t seed = 1;            ///< screening seed (verification: a stream derived from it)
  int max_periods = 3000;            ///< per run
  /// A screening run not stopped after slow_factor x the candidate's nominal T_p counts as
  /// failed (too slow; verification runs get max_periods), >= 1.
  double slow_factor = 4;
  int threads = 0;
  ProgressCallback progress;         ///< screening progress (done, total candidates)
};

/// Why runs of a design fail, counted over its verification.
struct FailureCounts {
  int no_motion = 0;  ///< never reached the rough region (y2'' too close to mu_static g)
  int no_stop = 0;    ///< reached it but never stopped (peak too close to mu_static c_mu g)
  int outside = 0;    ///< stopped outside the tolerance (spread of the end position)
  /// Counts one run: not stopped (no_motion when it never entered, else no_stop), or stopped
  /// at `end` farther than `tolerance` from `target` (outside).
  void add(StopKind kind, double entry_time, double end, double target, double tolerance) {
    if (kind == StopKind::not_stopped) (std::isnan(entry_time) ? no_motion : no_stop) += 1;
    else if (std::abs(end - target) > tolerance) ++outside;
  }
};

struct RobustDesignResult {
  /// A design whose verification reaches the target (Wilson 95% lower bound >= target).
  bool meets_target = false;
  std::string message;  ///< what was found, or why no design reaches the target
  /// The failure mode limiting the design: "end-position spread", "stopping", "motion" (or
  /// "none" when no run failed).
  std::string binding;
  DesignResult design;    ///< the chosen profile (the best found when !meets_target), SI
  Process process;        ///< the same as a Process (with the placed x_mu)
  MonteCarloResult verification;  ///< its verification runs
  FailureCounts failures;         ///< over the verification
  double time_quantile_value = 0; ///< the T_p quantile of the verification [s] (inf: > 1 - q fail)
  int candidates = 0, screened = 0, verified = 0;
};

/// Throws InvalidParameter on bad input (target or quantile outside (0, 1), a tolerance <= 0,
/// runs out of range, an invalid uncertainty).
RobustDesignResult design_robust(const DesignRequest& request,
                                 const ProcessUncertainty& uncertainty,
                                 const RobustOptions& options = {});

/// The failure counts of a Monte-Carlo result.
FailureCounts failure_counts(const MonteCarloResult& result);

}  // namespace selfalign
