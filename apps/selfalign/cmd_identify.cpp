// `selfalign identify`: friction identified from measured motion (identify/identification.hpp,
// docs/identification.md): --data run.csv (repeatable) --config model.toml --free mu,mu_static.
// Writes the JSON report (--out, or a table on stdout), the fit as CSV (--fit-csv) and the
// uncertainty file for design --robust / montecarlo (--uncertainty-out), all together.

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "config_flags.hpp"
#include "report.hpp"
#include "selfalign/error.hpp"
#include "selfalign/identify/identification.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/identification_report.hpp"
#include "selfalign/io/measured_motion.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct IdentifyFlags {
  std::vector<std::string> data;
  std::vector<std::string> data_config;
  std::string free;
  std::vector<std::string> bounds;  // NAME=LO:HI
  double window_periods = 2;
  std::string loss = "squared";
  int starts = 16;
  int global_evaluations = 4000;
  int max_iterations = 100;
  std::string profile = "auto";  // --profile-likelihood
  int profile_points = 13;
  double confidence = 0.95;
  int threads = 2;
  bool as_json = false;
  std::optional<std::string> fit_csv;
  std::optional<std::string> uncertainty_out;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

// "squared" | "huber:SCALE" | "cauchy:SCALE" (SCALE in metres, or the config's length unit).
IdentificationLoss parse_loss(const std::string& text) {
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  if (kind == "squared" && colon == std::string::npos) return SquaredLoss{};
  if ((kind == "huber" || kind == "cauchy") && colon != std::string::npos) {
    const double s = parse_number("loss", text.substr(colon + 1));
    if (!(s > 0) || !std::isfinite(s))
      throw InvalidParameter("loss", text, "the scale must be > 0 (a length)");
    return kind == "huber" ? IdentificationLoss{HuberLoss{s}} : IdentificationLoss{CauchyLoss{s}};
  }
  throw InvalidParameter("loss", text, "must be squared, huber:SCALE or cauchy:SCALE");
}

// "NAME=LO:HI"
std::pair<std::string, IdentificationBounds> parse_bounds(const std::string& text) {
  const auto eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos)
    throw InvalidParameter("bounds", text, "must be NAME=LOWER:UPPER, e.g. --bounds mu=0.2:0.4");
  const std::string name = text.substr(0, eq);
  return {name, {parse_number("bounds " + name, text.substr(eq + 1, colon - eq - 1)),
                 parse_number("bounds " + name, text.substr(colon + 1))}};
}

std::string identify_table(const Identification& r) {
  TextTable t;
  for (const IdentifiedParameter& p : r.parameters) {
    if (!p.identifiable) {
      t.row(p.name, "not identifiable");
      continue;
    }
    std::ostringstream s;
    s.precision(6);
    s << p.estimate << " +- " << p.standard_error << "  (" << p.lower << " .. " << p.upper << ")";
    if (std::isfinite(p.profile_lower) || std::isfinite(p.profile_upper))
      s << "  profile " << table_text(number_or_null(p.profile_lower)) << " .. "
        << table_text(number_or_null(p.profile_upper));
    t.row(p.name, s.str());
  }
  for (const FittedRun& f : r.runs) {
    std::ostringstream s;
    s.precision(4);
    s << f.t.size() << " samples, residual rms " << f.rms;
    if (std::isfinite(f.time_offset_standard_error))
      s << ", time offset " << f.time_offset << " +- " << f.time_offset_standard_error;
    t.row(f.source, s.str());
  }
  t.row("sigma", table_text(number_or_null(r.sigma)));
  t.row("converged", r.converged ? "yes" : "no (" + r.termination + ")");
  std::string out = t.str();
  for (const std::string& w : r.warnings) out += "warning: " + w + "\n";
  return out;
}

void run_identify(const ConfigFlags& flags, const IdentifyFlags& f) {
  const SimulateConfig base = read_config(flags);
  if (base.out) require_output_path("out", *base.out);
  if (f.fit_csv) require_output_path("fit-csv", *f.fit_csv);
  if (f.uncertainty_out) require_output_path("uncertainty-out", *f.uncertainty_out);
  if (!f.data_config.empty() && f.data_config.size() != f.data.size())
    throw InvalidParameter("data-config", std::to_string(f.data_config.size()) + " files",
                           "give none or one per --data (" + std::to_string(f.data.size()) + ")");
  IdentificationOptions o;
  o.free = split_list(f.free);
  for (const std::string& b : f.bounds) o.bounds.insert(parse_bounds(b));
  o.window_periods = f.window_periods;
  o.loss = parse_loss(f.loss);
  o.starts = f.starts;
  o.global_evaluations = f.global_evaluations;
  o.max_iterations = f.max_iterations;
  o.profile_points = f.profile_points;
  o.confidence = f.confidence;
  o.threads = f.threads;
  if (f.profile == "auto") {
    for (const std::string& n : o.free)
      if (n == "mu_static" || n == "mu") o.profile.push_back(n);
  } else if (f.profile != "none") {
    o.profile = split_list(f.profile);
  }
  std::vector<IdentificationRun> runs;
  for (std::size_t i = 0; i < f.data.size(); ++i)
    runs.push_back({read_measured_motion(f.data[i]),
                    f.data_config.empty() ? base : load_simulate_config(f.data_config[i])});
  const Identification r = identify(runs, o);
  const json report = identification_json(r);
  AtomicFileSet files;
  if (f.fit_csv) files.add(*f.fit_csv, identification_csv(r), "fit-csv");
  if (f.uncertainty_out)
    files.add(*f.uncertainty_out,
              identification_uncertainty(r, resolve_simulate_config(runs.front().config).mu.value()),
              "uncertainty-out");
  files.commit();
  deliver_report(report, identify_table(r), f.as_json, base.out);
}

}  // namespace

void add_identify_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "identify",
      "Friction identified from measured motion (docs/identification.md): the free parameters "
      "of the config's model (any of `selfalign parameters`, e.g. mu, mu_static, c_mu, x_mu, "
      "width, amplitude_scale, and time_offset) fitted to measured positions by least squares "
      "with multiple shooting (each window restarts from its own estimated state): a global "
      "stage (NLopt MLSL) and Ceres' Levenberg-Marquardt; standard errors, correlations, "
      "profile-likelihood intervals and identifiability warnings; the uncertainty file for "
      "design --robust and montecarlo.");
  auto flags = add_config_flags(
      *sub, without_groups({{"out", "write the JSON report to this file instead of printing "
                                    "the table (nothing printed)"},
                            {"summary", ""},
                            {"periods", ""},
                            {"output_step", ""},
                            {"mass", ""}},
                           {}));
  auto f = std::make_shared<IdentifyFlags>();
  sub->add_option("--data", f->data,
                  "a measured run: CSV with a header naming t and x (units as suffixes or a "
                  "<FILE>.units side file; docs/identification.md); repeatable: all in one fit")
      ->type_name("FILE")
      ->required()
      ->group("Data");
  sub->add_option("--data-config", f->data_config,
                  "the model config of each --data run, in order (runs at different drive "
                  "settings); default: every run uses --config and the flags")
      ->type_name("FILE")
      ->group("Data");
  sub->add_option("--free", f->free,
                  "comma-separated free parameters: names of `selfalign parameters` and "
                  "time_offset (the data's clock against the model's, one per run) [required]")
      ->type_name("LIST")
      ->required()
      ->group("Fit");
  sub->add_option("--bounds", f->bounds,
                  "NAME=LOWER:UPPER, the box of a free parameter for the global stage and the "
                  "fit (repeatable). Default: the config's value +-30 %; time_offset +-period/2")
      ->type_name("NAME=LO:HI")
      ->group("Fit");
  sub->add_option("--window-periods", f->window_periods,
                  "length of a shooting window in table periods, > 0. Default: 2")
      ->group("Fit");
  sub->add_option("--loss", f->loss,
                  "squared, huber:SCALE or cauchy:SCALE (SCALE a length in the data's units, "
                  "m: residuals beyond it count less). Default: squared")
      ->group("Fit");
  sub->add_option("--starts", f->starts,
                  "global stage: MLSL low-discrepancy starting points, >= 0 (0: start the "
                  "local fit at the config's values). Default: 16")
      ->group("Fit");
  sub->add_option("--global-evaluations", f->global_evaluations,
                  "global stage budget of model evaluations (each a pass of position-reset shooting over the data), >= 1. Default: 4000")
      ->group("Fit");
  sub->add_option("--max-iterations", f->max_iterations,
                  "Levenberg-Marquardt iterations, >= 1. Default: 100")
      ->group("Fit");
  sub->add_option("--profile-likelihood", f->profile,
                  "comma-separated parameters whose profile likelihood is computed, or none. "
                  "Default: auto (mu_static and mu when free)")
      ->type_name("LIST")
      ->group("Uncertainty");
  sub->add_option("--profile-points", f->profile_points,
                  "grid points of each profile, >= 3. Default: 13")
      ->group("Uncertainty");
  sub->add_option("--confidence", f->confidence,
                  "level of the intervals, in (0, 1). Default: 0.95")
      ->group("Uncertainty");
  sub->add_option("--threads", f->threads, "evaluation threads, >= 1. Default: 2")->group("Fit");
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->add_option("--fit-csv", f->fit_csv,
                  "write the fit per sample: run,t,x_measured,x_fitted,residual,window,stick")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--uncertainty-out", f->uncertainty_out,
                  "write the identified inputs as an uncertainty file (TOML) for design "
                  "--robust --uncertainty-file and montecarlo --uncertainty-file")
      ->type_name("FILE")
      ->group("Output");
  sub->callback([flags, f] { run_identify(*flags, *f); });
}

}  // namespace selfalign::cli
