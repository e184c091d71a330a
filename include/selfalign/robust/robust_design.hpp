#pragma once
/// \file robust_design.hpp
/// `selfalign design --robust`: the fastest process that still works when the friction data
/// and the geometry are uncertain (docs/robust-design.md). Minimises a quantile of the
/// process time T_p (e.g. the 99th percentile) subject to P(|end - target| <= tolerance) >=
/// a target probability, under a ProcessUncertainty.
///
/// The search, over design_process's candidate grid (DesignGrid: nominal mu and width), uses
/// three independent sets of draws: screening (seed), selection and verification (streams
/// derived from it):
///  1. a closed-form prune: on 2048 screening draws, the fraction in which the part can both
///     slip forward (y2'' > mu_static g) and stop for good (max(y2'', y3'') <= mu_static c_mu
///     g, eq. 40) bounds P(within) from above; candidates whose 95% Wilson upper bound of it is
///     below the target are dropped (if every one is, the 256 best bounds are kept to find the
///     best achievable probability); then one run at the nominal inputs (candidates that do
///     not stop are dropped), whose T_p orders the screen and bounds a screening run's periods
///     (slow_factor);
///  2. the Monte-Carlo screen (src/robust/robust_screen.hpp, docs/robust-design.md): in rungs
///     of 25, 50, 100, ... screening draws up to `screening_runs`, each candidate at a lattice
///     of trial x_mu values, every outcome an exact stopping run (ProcessWalk), for every stop
///     kind; each rung contributes its `finalists` fastest candidates among those that qualify
///     (screened P(within) high enough for the selection to pass) and its `finalists` surest;
///  3. selection: a Monte Carlo of `verification_runs` runs of every finalist on the selection
///     stream; the design is the fastest (T_p quantile) whose 95% Wilson lower bound of
///     P(within) reaches the target, else the most probable;
///  4. verification: a Monte Carlo of `verification_runs` runs of the chosen design on the
///     verification stream, independent of every draw that chose it: its P(within), interval
///     and T_p quantile are the result's claim.
/// With screening_runs on the ladder 25 x 2^j (25, 50, 100, 200 = the default, ...) a search
/// with more screening runs and as many or more finalists repeats every rung of the smaller
/// one and selects from a superset of its finalists on the same selection draws: its selection
/// is never worse (met and no slower, or a P at least as high).

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "selfalign/robust/monte_carlo.hpp"

namespace selfalign {

struct RobustOptions {
  double probability_target = 0.99;  ///< required P(within tolerance), in (0, 1)
  double time_quantile = 0.99;       ///< the quantile of T_p minimised, in (0, 1)
  int screening_runs = 200;          ///< draws per candidate in the screen, in [10, 1e5]
  /// Runs of each finalist's selection Monte Carlo and of the chosen design's verification,
  /// in [100, 1e7].
  int verification_runs = 4000;
  int finalists = 6;                 ///< finalists per rung of the screen, in [1, 1000]
  /// Screening seed; the selection and verification draw from streams derived from it.
  std::uint64_t seed = 1;
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
  /// The design met the target: its selection runs' 95% Wilson lower bound of P(within) and
  /// its independent verification's P(within) both reach it.
  bool meets_target = false;
  std::string message;  ///< what was found, or why no design reaches the target
  /// The failure mode limiting the design: "end-position spread", "stopping", "motion",
  /// "actuator limits" (the fastest of the grid), or "none" when no run failed.
  std::string binding;
  DesignResult design;    ///< the chosen profile (the best found when !meets_target), SI
  Process process;        ///< the same as a Process (with the placed x_mu)
  MonteCarloResult selection;     ///< the runs that chose it (selection stream)
  MonteCarloResult verification;  ///< its independent verification runs: the claim
  FailureCounts failures;         ///< over the verification
  /// The T_p quantile of the verification [s] (inf: more than 1 - q runs do not stop).
  double time_quantile_value = 0;
  /// What this design achieves at the target probability: the smallest tolerance [m] within
  /// which a fraction probability_target of its verification runs end (the target-quantile
  /// of |end - distance|; inf when more than 1 - target of them do not stop).
  double achievable_tolerance = 0;
  /// The request limits the chosen profile sits on (DesignGrid::pinned_limits; the same as
  /// design.limits), e.g. "frequency at frequency_min = 5 Hz (the default)".
  std::vector<std::string> limits;
  std::vector<int> rungs;  ///< screening draws of each rung of the screen
  /// Grid candidates; those screened; finalists verified by a selection Monte Carlo.
  int candidates = 0, screened = 0, verified = 0;
};

/// The most grid points design_robust takes: acceleration_grid^2 x period_grid x stroke_grid
/// <= 1e7 (the prune runs 2048 closed-form draws on each, and keeps the candidates it passes).
inline constexpr double kMaxRobustCandidates = 1e7;

/// Throws InvalidParameter on bad input (target or quantile outside (0, 1), a tolerance <= 0,
/// runs out of range, an invalid uncertainty, a grid beyond kMaxRobustCandidates).
RobustDesignResult design_robust(const DesignRequest& request,
                                 const ProcessUncertainty& uncertainty,
                                 const RobustOptions& options = {});

/// The failure counts of a Monte-Carlo result.
FailureCounts failure_counts(const MonteCarloResult& result);

/// The smallest tolerance [m] within which a fraction `probability` of the runs end: the
/// probability-quantile of |end - target|, a run that did not stop counting as +inf.
double tolerance_at_probability(const MonteCarloResult& result, double probability);

}  // namespace selfalign
