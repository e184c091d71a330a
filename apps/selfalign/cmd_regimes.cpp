// `selfalign regimes`: the feeder's regime chart (docs/feeder.md) over vibration angles x
// machine numbers: the closed-form regime of each cell and a run by the exact feeder solver
// (or the contact core with Moreau-Jean flight), as CSV rows and a JSON summary.

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "feeder_flags.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "selfalign/analysis/feeder.hpp"
#include "selfalign/error.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct RegimesFlags {
  double angle_min = 0, angle_max = 1.2;
  long long angles = 25;
  double k_min = 0.1, k_max = 10;
  long long ks = 25;
  double incline = 0, mu_static = 0, mu_kinetic = 0;
  long long periods = 10, steps_per_period = 200;
  std::string method = "exact";
  double restitution = 0;
  int threads = 0;
  bool as_json = false, quiet = false;
  std::optional<std::string> out, csv;
};

// n points from lo to hi (n = 1: lo), linear or geometric.
std::vector<double> axis(double lo, double hi, long long n, bool geometric) {
  std::vector<double> v;
  for (long long i = 0; i < n; ++i) {
    const double f = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
    v.push_back(geometric ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f);
  }
  return v;
}

void run_regimes(const RegimesFlags& f) {
  for (const auto& [name, n] : {std::pair{"angles", f.angles}, std::pair{"machine-numbers", f.ks}})
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
  require_report_paths(f.out, ExtraFile{"csv", f.csv});
  const std::vector<double> angles = axis(f.angle_min, f.angle_max, f.angles, false);
  const std::vector<double> ks = axis(f.k_min, f.k_max, f.ks, true);
  FeederChartOptions o;
  o.incline = f.incline, o.mu_static = f.mu_static, o.mu_kinetic = f.mu_kinetic;
  o.periods = f.periods, o.steps_per_period = f.steps_per_period, o.threads = f.threads;
  o.method = method, o.restitution = f.restitution;
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
  const std::vector<FeederChartCell> cells = feeder_regime_chart(angles, ks, o);
  bar.finish();
  std::ostringstream csv;
  csv << "vibration_angle_rad,machine_number,throw_number,regime,first_event,lifted_off,"
         "dimensionless_speed,stick_fraction,flight_fraction,status\n";
  long long counts[5] = {}, failed = 0;
  for (const FeederChartCell& c : cells) {
    ++counts[static_cast<int>(c.regime)];
    failed += !c.failure.empty();
    csv << csv_number(c.vibration_angle) << ',' << csv_number(c.machine_number) << ','
        << csv_number(c.throw_number) << ',' << feeder_regime_name(c.regime) << ','
        << feeder_event_name(c.run.first_event) << ',' << (c.run.lifted_off ? "true" : "false")
        << ',' << csv_number(c.dimensionless_speed) << ',' << csv_number(c.run.stick_fraction)
        << ',' << csv_number(c.run.flight_fraction) << ','
        << (c.failure.empty() ? "ok" : "failed") << '\n';
  }
  json r;
  r["command"] = "regimes";
  r["angles"] = {{"min_rad", f.angle_min}, {"max_rad", f.angle_max}, {"count", f.angles}};
  r["machine_numbers"] = {{"min", f.k_min}, {"max", f.k_max}, {"count", f.ks},
                          {"spacing", "geometric"}};
  r["incline_rad"] = f.incline;
  r["mu_static"] = f.mu_static, r["mu_kinetic"] = f.mu_kinetic;
  r["method"] = method == Method::exact
                    ? "closed-form regimes; runs by the exact feeder solver"
                    : "closed-form regimes; runs by the contact core with Moreau-Jean flight";
  r["restitution"] = f.restitution;
  r["periods"] = f.periods;
  r["steps_per_period"] = method == Method::exact ? json(nullptr) : json(f.steps_per_period);
  r["cells"] = cells.size();
  r["regimes"] = json::object();
  for (int k = 0; k < 5; ++k) r["regimes"][feeder_regime_name(static_cast<FeederRegime>(k))] = counts[k];
  r["failed"] = failed;
  r["csv_file"] = f.csv ? json(*f.csv) : json(nullptr);
  TextTable t;
  t.row("cells (angles x K)", std::to_string(f.angles) + " x " + std::to_string(f.ks));
  for (int k = 0; k < 5; ++k)
    t.row(std::string("cells ") + feeder_regime_name(static_cast<FeederRegime>(k)),
          std::to_string(counts[k]));
  t.row("failed", std::to_string(failed));
  deliver_report_with_file(r, t.str(), f.as_json, f.out, ExtraFile{"csv", f.csv}, csv.str());
}

}  // namespace

void add_regimes_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "regimes",
      "The vibratory feeder's regime chart (docs/feeder.md) over vibration angles (linear) x "
      "machine numbers K = a0 w^2 / g (geometric): per cell the closed-form regime (stick, "
      "forward, backward, both, hopping) and a run from rest, exact by default (--method "
      "time-stepping: the contact core with Moreau-Jean flight): dimensionless speed "
      "v / (a0 w cos psi), stick and flight fractions of the last period; rows to --csv, the "
      "summary as a table or JSON.");
  auto f = std::make_shared<RegimesFlags>();
  sub->add_option("--angle-min", f->angle_min, "least vibration angle [rad]. Default: 0")
      ->group("Chart");
  sub->add_option("--angle-max", f->angle_max, "largest vibration angle [rad]. Default: 1.2")
      ->group("Chart");
  sub->add_option("--angles", f->angles, "vibration angles, in [1, 2000]. Default: 25")
      ->group("Chart");
  sub->add_option("--k-min", f->k_min, "least machine number, > 0. Default: 0.1")->group("Chart");
  sub->add_option("--k-max", f->k_max, "largest machine number. Default: 10")->group("Chart");
  sub->add_option("--machine-numbers", f->ks, "machine numbers, in [1, 2000]. Default: 25")
      ->group("Chart");
  sub->add_option("--incline", f->incline, "track incline [rad], in (-pi/2, pi/2). Default: 0")
      ->group("Friction");
  add_friction_flags(*sub, f->mu_static, f->mu_kinetic);
  sub->add_option("--periods", f->periods, "periods from rest per cell, in [1, 1e4]. Default: 10")
      ->group("Solver");
  add_feeder_solver_flags(*sub, f->method, f->restitution);
  sub->add_option("--steps-per-period", f->steps_per_period,
                  "Moreau steps per period (time-stepping), in [2, 1e5]. Default: 200")
      ->group("Solver");
  sub->add_option("--threads", f->threads, "worker threads, >= 0 (0: all cores). Default: 0")
      ->group("Solver");
  sub->add_option("--csv", f->csv, "write the cells to FILE")->type_name("FILE")->group("Output");
  sub->add_flag("--json", f->as_json, "print the summary as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON summary to FILE")->type_name("FILE")->group("Output");
  sub->callback([f] { run_regimes(*f); });
}

}  // namespace selfalign::cli
