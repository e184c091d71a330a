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
  RegimeChartRequest request;
  bool as_json = false, quiet = false;
  std::optional<std::string> out, csv;
};

void run_regimes(const RegimesFlags& f) {
  require_report_paths(f.out, ExtraFile{"csv", f.csv});
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  const std::vector<FeederChartCell> cells = regime_chart(
      f.request, [&bar](std::size_t done, std::size_t total) { bar.update(done, total); });
  bar.finish();
  std::ostringstream csv;
  csv << "vibration_angle_rad,machine_number,throw_number,regime,first_event,lifted_off,"
         "dimensionless_speed,stick_fraction,flight_fraction,status\n";
  for (const FeederChartCell& c : cells) {
    csv << csv_number(c.vibration_angle) << ',' << csv_number(c.machine_number) << ','
        << csv_number(c.throw_number) << ',' << feeder_regime_name(c.regime) << ','
        << feeder_event_name(c.run.first_event) << ',' << (c.run.lifted_off ? "true" : "false")
        << ',' << csv_number(c.dimensionless_speed) << ',' << csv_number(c.run.stick_fraction)
        << ',' << csv_number(c.run.flight_fraction) << ','
        << (c.failure.empty() ? "ok" : "failed") << '\n';
  }
  json r = regime_chart_summary_json(f.request, cells);
  r["csv_file"] = f.csv ? json(*f.csv) : json(nullptr);
  TextTable t;
  t.row("cells (angles x K)",
        std::to_string(f.request.angles) + " x " + std::to_string(f.request.machine_numbers));
  for (int k = 0; k < 5; ++k) {
    const char* name = feeder_regime_name(static_cast<FeederRegime>(k));
    t.row(std::string("cells ") + name, table_text(r["regimes"][name]));
  }
  t.row("failed", table_text(r["failed"]));
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
  sub->add_option("--angle-min", f->request.angle_min, "least vibration angle [rad]. Default: 0")
      ->group("Chart");
  sub->add_option("--angle-max", f->request.angle_max, "largest vibration angle [rad]. Default: 1.2")
      ->group("Chart");
  sub->add_option("--angles", f->request.angles, "vibration angles, in [1, 2000]. Default: 25")
      ->group("Chart");
  sub->add_option("--k-min", f->request.k_min, "least machine number, > 0. Default: 0.1")->group("Chart");
  sub->add_option("--k-max", f->request.k_max, "largest machine number. Default: 10")->group("Chart");
  sub->add_option("--machine-numbers", f->request.machine_numbers, "machine numbers, in [1, 2000]. Default: 25")
      ->group("Chart");
  sub->add_option("--incline", f->request.incline, "track incline [rad], in (-pi/2, pi/2). Default: 0")
      ->group("Friction");
  add_friction_flags(*sub, f->request.mu_static, f->request.mu_kinetic);
  sub->add_option("--periods", f->request.periods, "periods from rest per cell, in [1, 1e4]. Default: 10")
      ->group("Solver");
  add_feeder_solver_flags(*sub, f->request.method, f->request.restitution);
  sub->add_option("--steps-per-period", f->request.steps_per_period,
                  "Moreau steps per period (time-stepping), in [2, 1e5]. Default: 200")
      ->group("Solver");
  sub->add_option("--threads", f->request.threads, "worker threads, >= 0 (0: all cores). Default: 0")
      ->group("Solver");
  sub->add_option("--csv", f->csv, "write the cells to FILE")->type_name("FILE")->group("Output");
  sub->add_flag("--json", f->as_json, "print the summary as JSON")->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON summary to FILE")->type_name("FILE")->group("Output");
  sub->callback([f] { run_regimes(*f); });
}

}  // namespace selfalign::cli
