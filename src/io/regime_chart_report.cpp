// The feeder's regime chart as a request and a report: io/regime_chart_report.hpp.
#include "selfalign/io/regime_chart_report.hpp"

#include <cmath>
#include <utility>

#include "selfalign/error.hpp"

namespace selfalign {

using nlohmann::json;

void require_feeder_flags(double incline, double mu_static, double mu_kinetic, long long periods,
                          long long max_periods, long long steps_per_period, long long max_steps) {
  require_feeder_angle("incline", incline);
  require_positive_moderate("mu-static", mu_static);
  require_positive_moderate("mu-kinetic", mu_kinetic);
  if (mu_kinetic > mu_static)
    throw InvalidParameter("mu-kinetic", mu_kinetic,
                           "must be <= mu-static (" + format_number(mu_static) + ")");
  if (!(periods >= 1 && periods <= max_periods))
    throw InvalidParameter("periods", static_cast<double>(periods),
                           "must be in [1, " + format_number(static_cast<double>(max_periods)) + "]");
  if (!(steps_per_period >= 2 && steps_per_period <= max_steps))
    throw InvalidParameter("steps-per-period", static_cast<double>(steps_per_period),
                           "must be in [2, " + format_number(static_cast<double>(max_steps)) + "]");
}

Method feeder_method(const std::string& text) {
  if (text == "exact") return Method::exact;
  if (text == "time-stepping") return Method::time_stepping;
  throw InvalidParameter("method", text, "must be exact or time-stepping");
}

void require_restitution(double e) {
  if (!(e >= 0 && e <= 1)) throw InvalidParameter("restitution", e, "must be in [0, 1]");
}

namespace {

// n points from lo to hi (n = 1: lo), linear or geometric.
std::vector<double> chart_axis(double lo, double hi, long long n, bool geometric) {
  std::vector<double> v;
  for (long long i = 0; i < n; ++i) {
    const double f = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
    v.push_back(geometric ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f);
  }
  return v;
}

}  // namespace

std::vector<FeederChartCell> regime_chart(const RegimeChartRequest& f, ProgressCallback progress) {
  for (const auto& [name, n] :
       {std::pair{"angles", f.angles}, std::pair{"machine-numbers", f.machine_numbers}})
    if (!(n >= 1 && n <= 2000))
      throw InvalidParameter(name, static_cast<double>(n), "must be in [1, 2000]");
  require_feeder_angle("angle-min", f.angle_min);
  require_feeder_angle("angle-max", f.angle_max);
  require_positive_moderate("k-min", f.k_min);
  require_positive_moderate("k-max", f.k_max);
  require_feeder_flags(f.incline, f.mu_static, f.mu_kinetic, f.periods, 10000,
                       f.steps_per_period, 100000);
  const Method method = feeder_method(f.method);
  require_restitution(f.restitution);
  if (f.threads < 0) throw InvalidParameter("threads", f.threads, "must be >= 0");
  FeederChartOptions o;
  o.incline = f.incline, o.mu_static = f.mu_static, o.mu_kinetic = f.mu_kinetic;
  o.periods = f.periods, o.steps_per_period = f.steps_per_period, o.threads = f.threads;
  o.method = method, o.restitution = f.restitution;
  o.progress = std::move(progress);
  return feeder_regime_chart(chart_axis(f.angle_min, f.angle_max, f.angles, false),
                             chart_axis(f.k_min, f.k_max, f.machine_numbers, true), o);
}

json regime_chart_summary_json(const RegimeChartRequest& f,
                               const std::vector<FeederChartCell>& cells) {
  long long counts[5] = {}, failed = 0;
  for (const FeederChartCell& c : cells) {
    ++counts[static_cast<int>(c.regime)];
    failed += !c.failure.empty();
  }
  const bool exact = feeder_method(f.method) == Method::exact;
  json r;
  r["command"] = "regimes";
  r["angles"] = {{"min_rad", f.angle_min}, {"max_rad", f.angle_max}, {"count", f.angles}};
  r["machine_numbers"] = {{"min", f.k_min}, {"max", f.k_max}, {"count", f.machine_numbers},
                          {"spacing", "geometric"}};
  r["incline_rad"] = f.incline;
  r["mu_static"] = f.mu_static, r["mu_kinetic"] = f.mu_kinetic;
  r["method"] = exact ? "closed-form regimes; runs by the exact feeder solver"
                      : "closed-form regimes; runs by the contact core with Moreau-Jean flight";
  r["restitution"] = f.restitution;
  r["periods"] = f.periods;
  r["steps_per_period"] = exact ? json(nullptr) : json(f.steps_per_period);
  r["cells"] = cells.size();
  r["regimes"] = json::object();
  for (int k = 0; k < 5; ++k) r["regimes"][feeder_regime_name(static_cast<FeederRegime>(k))] = counts[k];
  r["failed"] = failed;
  return r;
}

}  // namespace selfalign
