#pragma once
// What `design` and `montecarlo` share: the request's flags (SI), the uncertainty flags
// (--uncertain NAME=DIST, --uncertainty-file), and the JSON of the robustness results.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "selfalign/robust/fragility.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/robust/worst_case.hpp"

namespace selfalign::cli {

/// The object, friction and positioning flags of a DesignRequest (group "Request"), and the
/// actuator limits (also "Request").
void add_request_flags(CLI::App* sub, DesignRequest& request);

struct UncertaintyFlags {
  std::vector<std::string> uncertain;  ///< NAME=DIST
  std::optional<std::string> file;
  /// The uncertainty: the file's, then each --uncertain over it. Throws InvalidParameter.
  ProcessUncertainty read() const;
};
void add_uncertainty_flags(CLI::App* sub, UncertaintyFlags& flags);
/// The warnings (warnings.hpp) a request may deserve: mu_static or mu_backward without --mu,
/// lengths that look like millimetres (width, stroke-max, tolerance >= 1 m; distance >= 10 m),
/// a mass that looks like grams (>= 10 kg).
void warn_about_request(const DesignRequest& request, bool mu_given);

/// The flags of a Monte-Carlo study's runs (group "Monte Carlo"): --runs (its default shown),
/// --seed, --first-run, --threads; `montecarlo` and `parts montecarlo` share them.
void add_monte_carlo_run_flags(CLI::App* sub, int& runs, std::uint64_t& seed,
                               std::uint64_t& first_run, int& threads);

/// Whether any input of `u` is uncertain (not known).
bool any_uncertain(const ProcessUncertainty& u);

nlohmann::json uncertainty_json(const DesignRequest& request, const ProcessUncertainty& u);
nlohmann::json fragility_json(const Fragility& f);
/// Counts, probabilities (with the Wilson interval), T_p quantiles (0.5, 0.9, 0.99, q) and
/// end-position quantiles, and a histogram of the end positions (`bins`).
nlohmann::json monte_carlo_json(const MonteCarloResult& r, double time_quantile, int bins);
nlohmann::json worst_case_json(const WorstCase& w);

/// Per-run CSV: run, the inputs, kind, end_position_m, process_time_s, entry_time_s.
std::string monte_carlo_csv(const MonteCarloResult& r);

}  // namespace selfalign::cli
