#pragma once
/// \file monte_carlo.hpp
/// Monte-Carlo evaluation of a designed process under uncertain inputs (docs/robust-design.md):
/// probability of stopping, probability of ending within the tolerance, and the distributions
/// of the end position and of the process time.
///
/// Run r (r = first_run, ..., first_run + runs - 1) draws its inputs with draw_inputs(seed, r)
/// and runs the exact stopping run of run_process(); runs are spread over threads (oneTBB) and
/// each writes its own slot. The result is therefore identical for any thread count, and the
/// runs may be split into chunks (first_run, runs) computed anywhere (another process, a Dask
/// worker, an MPI rank) and merged with merge_monte_carlo() into the result of one call, bit for bit.

#include <cstdint>
#include <string>
#include <vector>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

struct MonteCarloOptions {
  std::uint64_t seed = 1;       ///< stream of draws
  std::uint64_t first_run = 0;  ///< index of the first run (chunks of one study)
  int runs = 10'000;            ///< number of runs, in [1, 1e7]
  int max_periods = 3000;       ///< a run not stopped after this many table periods: not stopped
  int threads = 0;              ///< workers (0: all cores)
  ProgressCallback progress;    ///< optional (done, total) as runs complete
};

/// The runs of one study: per-run columns (run order) and the counts over them.
struct MonteCarloResult {
  std::uint64_t seed = 1, first_run = 0;
  double target = 0;     ///< desired end position [m]
  double tolerance = 0;  ///< allowed |end - target| [m]
  /// inputs[k][r]: input k (uncertain_inputs() order) of run r.
  std::vector<std::vector<double>> inputs;
  std::vector<StopKind> kind;
  std::vector<double> end_position;  ///< [m]; NaN when not stopped
  std::vector<double> process_time;  ///< [s]; NaN when not stopped
  std::vector<double> entry_time;    ///< [s]; NaN when the object never reaches x_mu
  // Counts (summarize()):
  int runs = 0;
  int stopped = 0;       ///< permanent stick or accumulation
  int within = 0;        ///< stopped with |end - target| <= tolerance
  int never_entered = 0; ///< never reached the rough region (stuck or too slow)
  double p_stop = 0, p_within = 0;
  /// 95% Wilson score interval of p_within.
  double p_within_low = 0, p_within_high = 0;
};

/// Validates and runs the study. Throws InvalidParameter for a bad process, uncertainty or
/// options (runs out of [1, 1e8], tolerance <= 0, ...).
MonteCarloResult monte_carlo(const DesignRequest& request, const Process& process,
                             const ProcessUncertainty& uncertainty,
                             const MonteCarloOptions& options = {});

/// Recomputes the counts and probabilities from the per-run columns.
void summarize(MonteCarloResult& result);

/// Concatenates consecutive chunks of one study (same seed, target, tolerance; each chunk's
/// first_run continuing the previous one) into the result of a single call. Throws
/// InvalidParameter("parts", ...) otherwise.
MonteCarloResult merge_monte_carlo(const std::vector<MonteCarloResult>& parts);

/// The q-quantile (q in (0, 1]) of the process time over all runs, a run that did not stop
/// counting as +inf: the smallest t with at least a fraction q of the runs done by t
/// (inverse of the empirical CDF, no interpolation).
double process_time_quantile(const MonteCarloResult& result, double q);
/// The q-quantile of the end position over the runs that stopped; NaN if none stopped.
double end_position_quantile(const MonteCarloResult& result, double q);

/// The q-quantile (q in (0, 1]) of n values of which `values` are the finite or infinite ones
/// given and the other n - values.size() count as +inf: the smallest v with at least q n values
/// <= v (inverse of the empirical CDF, no interpolation); NaN for n = 0.
double empirical_quantile(std::vector<double> values, double q, std::size_t n);

/// The 95% Wilson score interval of k successes in n trials.
std::pair<double, double> wilson_interval(int k, int n);

/// Equal-width histogram of the finite values: `bins` counts over [lo, hi] (the finite
/// values' range), edges.size() = bins + 1. Empty when no value is finite.
struct Histogram {
  std::vector<double> edges;
  std::vector<int> counts;
};
Histogram histogram(const std::vector<double>& values, int bins);

}  // namespace selfalign
