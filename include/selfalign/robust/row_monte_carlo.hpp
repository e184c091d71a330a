#pragma once
/// \file row_monte_carlo.hpp
/// Monte Carlo of a queue stopping at the friction step (issue 24, docs/rows.md section 11)
/// under the robust-design uncertainty model (robust/process_uncertainty.hpp): the same
/// ProcessUncertainty, the same draws (uniform_draw with the seed convention of
/// draw_inputs) and the same uncertainty file as `selfalign montecarlo`.
///
/// How the inputs map onto a queue (dimensionless units of the parts config):
///   mu            per part: its coefficients (static, forward, backward) x mu_i / nominal(mu)
///   static_ratio  per part: static = ratio_i x forward kinetic, backward kinetic capped by it
///                 (as the single-part model: mu_backward = min(ratio, s) mu)
///   c_mu          per run: the level beyond the step
///   x_mu_offset   per run: the step moves by it [the config's length unit]
///   amplitude a,  per run: the table y(t) -> a y(t / p): stroke x a, a2 and a3 x a / p^2,
///   period_factor p        period x p
///   width         refused: a queue's parts have their own lengths, and the exact row
///                 solver's footprint is a point (no transition width to draw)
/// Part i of run r draws input k from uniform_draw(seed, r, kUncertainInputs i + k)
/// (draw_inputs with stream kUncertainInputs i): part 0 draws exactly what the single-part
/// study draws, and the per-run inputs are part 0's. Runs are spread over threads (oneTBB),
/// each writing its own slots: the result is the same for any thread count.

#include <cstdint>
#include <vector>

#include "selfalign/analysis/row.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

/// A queue stopping process (dimensionless, the parts config's): the three-phase table, the
/// friction step from level 1 to `c_mu` at `step_position`, and the queue.
struct RowProcess {
  ThreePhaseParameters table{1.0, 0.084, 3.0, 0.9};
  double step_position = 0;  ///< x_mu [-]
  double c_mu = 2.5;         ///< the level beyond the step [-]
  RowQueue queue;
};

/// One run's draw: the process it runs, and the inputs each part took (parts x
/// kUncertainInputs, uncertain_inputs() order): mu as the factor on the part's coefficients
/// (1 when mu is known), static_ratio the part's static / forward kinetic coefficient as run,
/// width NaN (not drawn), the per-run inputs as drawn (known: c_mu the process's, offset 0,
/// factors 1).
struct RowDraw {
  RowProcess process;
  std::vector<InputValues> inputs;
};

/// The draw of run `run` for `seed`. Throws InvalidParameter("width.uncertain", ...) for an
/// uncertain width; `u` is not otherwise validated here (row_monte_carlo does).
RowDraw draw_row_process(const RowProcess& nominal, const ProcessUncertainty& u,
                         std::uint64_t seed, std::uint64_t run);

struct RowMonteCarloOptions {
  std::uint64_t seed = 1;       ///< stream of draws
  std::uint64_t first_run = 0;  ///< index of the first run (chunks of one study)
  int runs = 1000;              ///< number of runs, in [1, 1e7]
  long long max_periods = 1000; ///< a run not stopped after this many periods: not stopped
  double tolerance = 0.01;      ///< allowed |positioning error| [-], > 0
  RowSolver solver{};           ///< exact (default) or Moreau
  int threads = 0;              ///< workers (0: all cores)
  ProgressCallback progress;    ///< optional (done, total) as runs complete
};

/// One part over the runs. Means and standard deviations are over the runs where the queue
/// stopped (NaN when none; a standard deviation, n - 1 in the denominator, NaN below two).
struct RowPartSummary {
  int within = 0;                ///< runs that stopped with |error| <= tolerance
  double p_within = 0;           ///< within / runs
  double p_within_low = 0, p_within_high = 0;  ///< its 95% Wilson score interval
  double end_mean = 0, end_sd = 0;             ///< end position [-]
  double error_mean = 0, error_sd = 0;         ///< positioning error [-]
  double process_time_mean = 0, process_time_sd = 0;  ///< last motion [-] (runs where it moved)
};

/// The runs of one study. Per-run per-part columns are run-major: value (r, i) at
/// r * parts + i. A part counts as stopped only when the whole queue stopped (row_stop's
/// criterion: no part moved through a whole period); until then a part at rest may still be
/// pushed. Absent values are NaN, never 0.
struct RowMonteCarloResult {
  std::uint64_t seed = 1, first_run = 0;
  double tolerance = 0;      ///< allowed |error| [-]
  double step_position = 0;  ///< the nominal step the errors refer to [-]
  int runs = 0, parts = 0;
  /// inputs[(r * parts + i) * kUncertainInputs + k]: input k of part i in run r (RowDraw).
  std::vector<double> inputs;
  std::vector<std::uint8_t> queue_stopped;  ///< per run: 1 when the queue stopped
  std::vector<std::uint8_t> accumulated;    ///< per run: 1 when it stopped packed behind the front part
  std::vector<std::uint8_t> stopped;        ///< runs x parts: 1 when the queue stopped
  /// runs x parts, NaN where the queue did not stop: the end position [-]; the positioning
  /// error x - target [-], target = the nominal step for the front part and the nominal step
  /// less the lengths of the parts ahead for the others (row_stop's targets at the nominal step:
  /// a drawn x_mu_offset is an error of the process); the part's last motion [-] (also NaN for
  /// a part that never moved).
  std::vector<double> end_position, error, process_time;
  // Summary (summarize()):
  int queue_stops = 0;   ///< runs where the queue stopped
  int all_within = 0;    ///< runs where every part ended within the tolerance
  double p_stop = 0, p_all_within = 0;
  double p_all_within_low = 0, p_all_within_high = 0;  ///< 95% Wilson interval of p_all_within
  std::vector<RowPartSummary> summary;  ///< per part, rear to front
};

/// Validates and runs the study: run r draws draw_row_process(nominal, u, seed, r) and runs
/// row_stop on it. Throws InvalidParameter for a bad process (row_model's names, "table",
/// "step_position", "c_mu"), uncertainty (validate(ProcessUncertainty), an uncertain width,
/// a draw whose table or law the model refuses, checked at the ends of the draws' box) or
/// options ("runs" in [1, 1e7], "max_periods", "tolerance" > 0).
RowMonteCarloResult row_monte_carlo(const RowProcess& nominal, const ProcessUncertainty& u,
                                    const RowMonteCarloOptions& options = {});

/// Recomputes the counts, probabilities and per-part summaries from the per-run columns.
void summarize(RowMonteCarloResult& result);

/// The q-quantile (q in (0, 1]) of part `part`'s end position over the runs where the queue
/// stopped (NaN if none), inverse empirical CDF (empirical_quantile).
double row_end_position_quantile(const RowMonteCarloResult& result, int part, double q);
/// The q-quantile of part `part`'s positioning error over the runs where the queue stopped.
double row_error_quantile(const RowMonteCarloResult& result, int part, double q);
/// The q-quantile of part `part`'s process time over all runs, a run where the queue did not
/// stop counting as +inf (process_time_quantile's convention); a part that never moved in a
/// stopped run counts as 0.
double row_process_time_quantile(const RowMonteCarloResult& result, int part, double q);

}  // namespace selfalign
