// `selfalign feeder-design`: the least feeder drive for a target conveying speed
// (design/feeder_drive.hpp, docs/feeder.md "Choosing the drive"), in SI: per vibration angle
// the least amplitude that reaches the speed within the flight bound, and the best of them.

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "commands.hpp"
#include "feeder_flags.hpp"
#include "progress_bar.hpp"
#include "report.hpp"
#include "selfalign/design/feeder_drive.hpp"
#include "selfalign/error.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct FeederDesignFlags {
  double target_speed = 0, frequency = 0, incline = 0, mu_static = 0, mu_kinetic = 0, g = 9.81;
  double max_flight_angle = 0, angle_min = 0.1, angle_max = 1.0, k_max = 10, restitution = 0;
  long long angles = 10, k_samples = 48, periods = 20;
  int threads = 0;
  bool as_json = false, quiet = false;
  std::optional<std::string> out;
};

json candidate_json(const FeederDriveCandidate& c) {
  return {{"vibration_angle_rad", c.vibration_angle},
          {"feasible", c.feasible},
          {"amplitude_m", number_or_null(c.amplitude)},
          {"machine_number", number_or_null(c.machine_number)},
          {"throw_number", number_or_null(c.throw_number)},
          {"velocity_m_per_s", number_or_null(c.speed)},
          {"flight_angle_rad", number_or_null(c.flight_angle)},
          {"reason", c.reason.empty() ? json(nullptr) : json(c.reason)}};
}

void run_feeder_design(const FeederDesignFlags& f) {
  require_positive_moderate("target-speed", f.target_speed);
  require_positive_moderate("frequency", f.frequency);
  require_feeder_flags(f.incline, f.mu_static, f.mu_kinetic, f.periods, 100000, 2, 2);
  require_positive_moderate("g", f.g);
  if (!(f.max_flight_angle >= 0 && f.max_flight_angle <= 2 * std::numbers::pi))
    throw InvalidParameter("max-flight-angle", f.max_flight_angle, "must be in [0, 2 pi] rad");
  require_feeder_angle("angle-min", f.angle_min);
  require_feeder_angle("angle-max", f.angle_max);
  if (!(f.angles >= 1 && f.angles <= 1000))
    throw InvalidParameter("angles", static_cast<double>(f.angles), "must be in [1, 1000]");
  require_positive_moderate("k-max", f.k_max);
  if (!(f.k_samples >= 2 && f.k_samples <= 10000))
    throw InvalidParameter("k-samples", static_cast<double>(f.k_samples), "must be in [2, 10000]");
  require_restitution(f.restitution);
  if (f.threads < 0) throw InvalidParameter("threads", f.threads, "must be >= 0");
  if (f.out) require_output_path("out", *f.out);
  FeederDriveOptions o;
  o.incline = f.incline, o.mu_static = f.mu_static, o.mu_kinetic = f.mu_kinetic, o.g = f.g;
  o.period = 1 / f.frequency, o.target_speed = f.target_speed;
  o.max_flight_angle = f.max_flight_angle, o.k_max = f.k_max;
  o.k_samples = static_cast<int>(f.k_samples), o.periods = f.periods;
  o.restitution = f.restitution, o.threads = f.threads;
  o.vibration_angles.clear();
  for (long long i = 0; i < f.angles; ++i)
    o.vibration_angles.push_back(
        f.angles == 1 ? f.angle_min
                      : f.angle_min + (f.angle_max - f.angle_min) * static_cast<double>(i) /
                                          static_cast<double>(f.angles - 1));
  ProgressBar bar(std::cerr, !f.quiet && stderr_is_terminal());
  o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
  const FeederDriveDesign d = design_feeder_drive(o);
  bar.finish();
  json r;
  r["command"] = "feeder-design";
  r["units"] = "si";
  r["target_speed_m_per_s"] = f.target_speed;
  r["frequency_hz"] = f.frequency;
  r["incline_rad"] = f.incline;
  r["mu_static"] = f.mu_static, r["mu_kinetic"] = f.mu_kinetic;
  r["max_flight_angle_rad"] = f.max_flight_angle;
  r["method"] = "exact feeder solver; least machine number per angle by sampling and bisection";
  r["feasible"] = d.feasible;
  r["best"] = candidate_json(d.best);
  r["candidates"] = json::array();
  for (const FeederDriveCandidate& c : d.candidates) r["candidates"].push_back(candidate_json(c));
  TextTable t;
  t.row("target speed [m/s], frequency [Hz]",
        table_text(r["target_speed_m_per_s"]) + ", " + table_text(r["frequency_hz"]));
  t.row("feasible", table_text(r["feasible"]));
  t.row("vibration angle [rad]", table_text(r["best"]["vibration_angle_rad"]));
  t.row("amplitude [m], K, Gamma", table_text(r["best"]["amplitude_m"]) + ", " +
                                       table_text(r["best"]["machine_number"]) + ", " +
                                       table_text(r["best"]["throw_number"]));
  t.row("velocity [m/s], flight angle [rad]", table_text(r["best"]["velocity_m_per_s"]) + ", " +
                                                   table_text(r["best"]["flight_angle_rad"]));
  if (!d.feasible) t.row("why", table_text(r["best"]["reason"]));
  deliver_report(r, t.str(), f.as_json, f.out);
}

}  // namespace

void add_feeder_design_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "feeder-design",
      "The least feeder drive for a target conveying speed in SI (docs/feeder.md, Choosing the "
      "drive): at the given frequency, per vibration angle the least amplitude whose steady "
      "speed (the exact feeder solver) reaches --target-speed, with no lift-off "
      "(--max-flight-angle 0, the default) or a flight angle at most that per period; reports "
      "the angle with the least machine number and every candidate (--json).");
  auto f = std::make_shared<FeederDesignFlags>();
  sub->add_option("--target-speed", f->target_speed, "the conveying speed wanted [m/s], > 0")
      ->required()
      ->group("Target");
  sub->add_option("--frequency", f->frequency, "drive frequency [Hz], > 0")
      ->required()
      ->group("Target");
  sub->add_option("--max-flight-angle", f->max_flight_angle,
                  "the flight allowed per period [rad], in [0, 2 pi]; 0: never leave the "
                  "track. Default: 0")
      ->group("Target");
  sub->add_option("--incline", f->incline, "track incline [rad], in (-pi/2, pi/2). Default: 0")
      ->group("Friction");
  add_friction_flags(*sub, f->mu_static, f->mu_kinetic);
  sub->add_option("--g", f->g, "gravity [m/s^2], > 0. Default: 9.81")->group("Friction");
  sub->add_option("--angle-min", f->angle_min, "least vibration angle [rad]. Default: 0.1")
      ->group("Search");
  sub->add_option("--angle-max", f->angle_max, "largest vibration angle [rad]. Default: 1.0")
      ->group("Search");
  sub->add_option("--angles", f->angles, "candidate angles, in [1, 1000]. Default: 10")
      ->group("Search");
  sub->add_option("--k-max", f->k_max, "the largest machine number a0 w^2 / g. Default: 10")
      ->group("Search");
  sub->add_option("--k-samples", f->k_samples,
                  "machine numbers sampled per angle before bisection, in [2, 10000]. "
                  "Default: 48")
      ->group("Search");
  sub->add_option("--periods", f->periods, "periods from rest per run, in [1, 1e5]. Default: 20")
      ->group("Search");
  sub->add_option("--restitution", f->restitution,
                  "Newton's restitution e at a landing, in [0, 1]. Default: 0")
      ->group("Search");
  sub->add_option("--threads", f->threads, "worker threads, >= 0 (0: all cores). Default: 0")
      ->group("Search");
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->add_flag("--quiet", f->quiet, "no progress bar")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE (nothing printed)")
      ->type_name("FILE")
      ->group("Output");
  sub->callback([f] { run_feeder_design(*f); });
}

}  // namespace selfalign::cli
