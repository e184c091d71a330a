// The identification's report, fit CSV and uncertainty file (io/identification_report.hpp).

#include "selfalign/io/identification_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/io/summary_json.hpp"

namespace selfalign {
namespace {

nlohmann::json matrix_json(const std::vector<double>& m, std::size_t n) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t a = 0; a < n; ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t b = 0; b < n; ++b)
      row.push_back(m.size() == n * n ? number_or_null(m[a * n + b]) : nlohmann::json(nullptr));
    rows.push_back(row);
  }
  return rows;
}

// A number for CSV and TOML: 17 significant digits ("nan" where absent).
std::string number(double v) {
  if (std::isnan(v)) return "nan";
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

const IdentifiedParameter* find(const Identification& r, const std::string& name) {
  for (const IdentifiedParameter& p : r.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

nlohmann::json identification_json(const Identification& r) {
  nlohmann::json j;
  j["parameters"] = nlohmann::json::array();
  for (const IdentifiedParameter& p : r.parameters)
    j["parameters"].push_back({{"name", p.name},
                               {"initial", number_or_null(p.initial)},
                               {"estimate", number_or_null(p.estimate)},
                               {"standard_error", number_or_null(p.standard_error)},
                               {"interval", {number_or_null(p.lower), number_or_null(p.upper)}},
                               {"profile_interval",
                                {number_or_null(p.profile_lower), number_or_null(p.profile_upper)}},
                               {"identifiable", p.identifiable},
                               {"reason", p.identifiable ? nlohmann::json(nullptr)
                                                         : nlohmann::json(p.reason)}});
  nlohmann::json names = nlohmann::json::array();
  for (const IdentifiedParameter& p : r.parameters) names.push_back(p.name);
  j["names"] = names;
  j["covariance"] = matrix_json(r.covariance, r.parameters.size());
  j["correlation"] = matrix_json(r.correlation, r.parameters.size());
  j["confidence_z"] = r.z;
  j["profiles"] = nlohmann::json::array();
  for (const ProfileLikelihood& pl : r.profiles) {
    nlohmann::json rss = nlohmann::json::array();
    for (double v : pl.rss) rss.push_back(number_or_null(v));
    j["profiles"].push_back({{"name", pl.name}, {"values", pl.values}, {"rss", rss}});
  }
  j["runs"] = nlohmann::json::array();
  for (const FittedRun& f : r.runs)
    j["runs"].push_back({{"source", f.source},
                         {"samples", f.t.size()},
                         {"skipped_rows", f.skipped},
                         {"time_offset", number_or_null(f.time_offset)},
                         {"time_offset_standard_error", number_or_null(f.time_offset_standard_error)},
                         {"residual_rms", number_or_null(f.rms)}});
  j["residuals"] = {{"samples", r.samples},
                    {"estimated_parameters", r.estimated},
                    {"shooting_windows", r.windows},
                    {"rss", number_or_null(r.rss)},
                    {"sigma", number_or_null(r.sigma)},
                    {"max_abs", number_or_null(r.max_abs_residual)}};
  j["fit"] = {{"iterations", r.iterations},
              {"converged", r.converged},
              {"termination", r.termination},
              {"global_best_rss", number_or_null(r.global_best_rss)},
              {"global_evaluations", r.global_evaluations}};
  j["warnings"] = r.warnings;
  return j;
}

std::string identification_csv(const Identification& r) {
  std::ostringstream s;
  s << "run,t,x_measured,x_fitted,residual,window,stick\n";
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    const FittedRun& f = r.runs[k];
    for (std::size_t i = 0; i < f.t.size(); ++i)
      s << k << ',' << number(f.t[i]) << ',' << number(f.x_measured[i]) << ','
        << number(f.x_fitted[i]) << ',' << number(f.residual[i]) << ',' << f.window[i] << ','
        << int(f.stick[i]) << '\n';
  }
  return s.str();
}

std::string identification_uncertainty(const Identification& r, double mu_config) {
  std::ostringstream s;
  s << "# Identified by selfalign identify (docs/identification.md): normal:ESTIMATE,SE per\n"
       "# input. Inputs are drawn independently: the correlations of the report are not\n"
       "# carried over.\n";
  const auto normal = [&](const std::string& key, double mean, double sd) {
    s << key << " = \"normal:" << number(mean) << ',' << number(sd) << "\"\n";
  };
  const auto note = [&](const IdentifiedParameter& p, const std::string& why) {
    s << "# " << p.name << ": " << why << "\n";
  };
  const IdentifiedParameter* mu = find(r, "mu");
  const std::size_t n = r.parameters.size();
  for (std::size_t j = 0; j < n; ++j) {
    const IdentifiedParameter& p = r.parameters[j];
    if (!p.identifiable) {
      note(p, "not identifiable (" + p.reason + ")");
      continue;
    }
    if (p.name == "mu" || p.name == "c_mu" || p.name == "width")
      normal(p.name, p.estimate, p.standard_error);
    else if (p.name == "x_mu")
      normal("x_mu_offset", 0.0, p.standard_error);
    else if (p.name == "amplitude_scale")
      normal("amplitude", p.estimate, p.standard_error);
    else if (p.name == "time_scale")
      normal("period_factor", p.estimate, p.standard_error);
    else if (p.name == "mu_static") {
      // static_ratio = s / m: var = v_s/m^2 + s^2 v_m/m^4 - 2 s c_sm/m^3 (delta method).
      const double sv = p.estimate;
      double m = mu_config, vm = 0, c = 0;
      if (mu && mu->identifiable) {
        const std::size_t i = static_cast<std::size_t>(mu - r.parameters.data());
        m = mu->estimate, vm = r.covariance[i * n + i], c = r.covariance[i * n + j];
      }
      const double vs = r.covariance[j * n + j];
      const double var = vs / (m * m) + sv * sv * vm / (m * m * m * m) - 2 * sv * c / (m * m * m);
      normal("static_ratio", sv / m, std::sqrt(std::max(var, 0.0)));
    } else {
      note(p, "estimate " + number(p.estimate) + " +- " + number(p.standard_error) +
                  " (no uncertain input of that name in robust design)");
    }
  }
  return s.str();
}

}  // namespace selfalign
