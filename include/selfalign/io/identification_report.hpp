#pragma once
/// \file identification_report.hpp
/// What an identification (identify/identification.hpp) writes: the JSON report, the fit as a
/// CSV (the data, the fitted positions and the residuals per sample), and the uncertainty file
/// that `design --robust --uncertainty-file` and `montecarlo --uncertainty-file` read
/// (io/uncertainty_file.hpp). docs/identification.md, "Out".

#include <string>

#include <nlohmann/json.hpp>

#include "selfalign/identify/identification.hpp"

namespace selfalign {

/// The report: per parameter its estimate, standard error, Wald and profile intervals and
/// whether it is identifiable (with the reason); covariance and correlation; per run the time
/// offset and residual RMS; residual statistics; the stages' outcome; the warnings. Absent
/// values (a parameter not identifiable, an interval not computed) are null.
nlohmann::json identification_json(const Identification& result);

/// The fit as CSV: run,t,x_measured,x_fitted,residual,window,stick (SI or the config's units),
/// one row per sample, runs in order.
std::string identification_csv(const Identification& result);

/// The uncertainty file (TOML) of the identified inputs, each a normal distribution of the
/// estimate and its standard error: mu; c_mu; static_ratio = mu_static / mu (the delta method
/// with their covariance; mu_static alone free: its se over mu); width; x_mu_offset = normal
/// about 0 with x_mu's se; amplitude (amplitude_scale) and period_factor (time_scale). A
/// parameter that is not identifiable, or has no uncertain input, is listed in a comment.
/// `mu_config`: the config's mu, for static_ratio when mu is not free. The inputs are drawn
/// independently: the correlations in the report are not carried (a comment says so).
std::string identification_uncertainty(const Identification& result, double mu_config);

}  // namespace selfalign
