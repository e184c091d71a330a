#pragma once
/// \file regime_chart_report.hpp
/// The feeder's regime chart as a request and a report (`selfalign regimes`, and the
/// WebAssembly core's `regimes`, wasm/api.cpp; docs/feeder.md): the grid of vibration angles
/// (linear) x machine numbers K = a0 w^2 / g (geometric), the track and friction, the runs'
/// solver; its checks name the CLI's flags. Also the feeder flags' shared checks.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/simulate/method.hpp"

namespace selfalign {

/// --incline in (-pi/2, pi/2), --mu-static > 0, --mu-kinetic in (0, mu-static], --periods in
/// [1, max_periods], --steps-per-period in [2, max_steps]. InvalidParameter naming the flag.
void require_feeder_flags(double incline, double mu_static, double mu_kinetic, long long periods,
                          long long max_periods, long long steps_per_period, long long max_steps);

/// The feeder runs' method: "exact" (the exact feeder solver, feeder_run_exact) or
/// "time-stepping" (the contact core, Moreau-Jean). InvalidParameter naming "method" otherwise.
Method feeder_method(const std::string& text);

/// --restitution in [0, 1]. InvalidParameter naming it otherwise.
void require_restitution(double e);

/// A regime chart's request, with the CLI's defaults. The friction coefficients have no
/// default (0 is refused).
struct RegimeChartRequest {
  double angle_min = 0, angle_max = 1.2;  ///< vibration angles [rad], in (-pi/2, pi/2)
  long long angles = 25;                  ///< in [1, 2000]
  double k_min = 0.1, k_max = 10;         ///< machine numbers, > 0
  long long machine_numbers = 25;         ///< in [1, 2000]
  double incline = 0;                     ///< [rad]
  double mu_static = 0, mu_kinetic = 0;   ///< absolute, 0 < mu_kinetic <= mu_static
  long long periods = 10;                 ///< from rest per cell, in [1, 1e4]
  long long steps_per_period = 200;       ///< Moreau (time-stepping), in [2, 1e5]
  std::string method = "exact";           ///< "exact" or "time-stepping"
  double restitution = 0;                 ///< Newton's e at a landing, in [0, 1]
  int threads = 0;                        ///< >= 0 (0: all cores)
};

/// Checks the request (InvalidParameter naming the CLI's flag: "angles", "k-min", "mu-kinetic",
/// ...) and runs feeder_regime_chart over its grid; `progress` (optional) is called as cells
/// are done. Cells in the chart's order (machine number fastest).
std::vector<FeederChartCell> regime_chart(const RegimeChartRequest& request,
                                          ProgressCallback progress = {});

/// The chart's summary (`selfalign regimes --json`, without "csv_file"): the grid, the track,
/// the method, the count of cells in each regime and of failed cells.
nlohmann::json regime_chart_summary_json(const RegimeChartRequest& request,
                                         const std::vector<FeederChartCell>& cells);

}  // namespace selfalign
