// `selfalign feeder`: a part on a vibratory feeder track (docs/feeder.md) in SI units: the
// sinusoidal drive along the vibration angle on an inclined track, its machine and throw
// numbers, the closed-form onsets, and a run by the exact feeder solver (or the contact core:
// Moreau, Moreau-Jean flight): first event, conveying velocity, stick and flight fractions.

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "feeder_config.hpp"
#include "feeder_flags.hpp"
#include "report.hpp"
#include "selfalign/analysis/feeder.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/run_files.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct FeederFlags {
  double amplitude = 0, frequency = 0, vibration_angle = 0, incline = 0;
  double harmonic_ratio = 0, harmonic_phase = 0;  // the second harmonic (two-frequency drive)
  double mu_static = 0, mu_kinetic = 0, g = 9.81;
  long long periods = 20, steps_per_period = 2000;
  std::string method = "exact";
  double restitution = 0;
  double step_position = 0;  // the friction step: a stopping run when given
  double c_mu = 2.5, start = 0;
  long long max_periods = 1000;
  bool no_flight = false, as_json = false;
  std::optional<std::string> out, config;
  // given by a flag or the config file: the required values, and the stopping run
  bool amplitude_given = false, frequency_given = false, mu_static_given = false,
       mu_kinetic_given = false, stopping = false;
};

// The config file's keys ([drive], [friction], [run], [stop]: docs/feeder.md) and the flags
// they stand for.
std::vector<FeederConfigKey> feeder_keys(FeederFlags& f) {
  return {{"drive", "amplitude", "--amplitude", &f.amplitude, &f.amplitude_given},
          {"drive", "frequency", "--frequency", &f.frequency, &f.frequency_given},
          {"drive", "vibration_angle", "--vibration-angle", &f.vibration_angle},
          {"drive", "incline", "--incline", &f.incline},
          {"drive", "g", "--g", &f.g},
          {"drive", "harmonic_ratio", "--harmonic-ratio", &f.harmonic_ratio},
          {"drive", "harmonic_phase", "--harmonic-phase", &f.harmonic_phase},
          {"friction", "mu_static", "--mu-static", &f.mu_static, &f.mu_static_given},
          {"friction", "mu_kinetic", "--mu-kinetic", &f.mu_kinetic, &f.mu_kinetic_given},
          {"run", "method", "--method", &f.method},
          {"run", "periods", "--periods", &f.periods},
          {"run", "steps_per_period", "--steps-per-period", &f.steps_per_period},
          {"run", "restitution", "--restitution", &f.restitution},
          {"stop", "step_position", "--step-position", &f.step_position, &f.stopping},
          {"stop", "c_mu", "--c-mu", &f.c_mu},
          {"stop", "start", "--start", &f.start},
          {"stop", "max_periods", "--max-periods", &f.max_periods}};
}

// An onset as its machine number and the amplitude that reaches it at this frequency.
json onset_json(double K, double g, double w) {
  if (std::isinf(K)) return {{"machine_number", nullptr}, {"amplitude_m", nullptr}};
  return {{"machine_number", K}, {"amplitude_m", K * g / (w * w)}};
}

void run_feeder(FeederFlags& f, const CLI::App& command) {
  for (const auto& [flag, given] :
       {std::pair{"--amplitude", &f.amplitude_given}, std::pair{"--frequency", &f.frequency_given},
        std::pair{"--mu-static", &f.mu_static_given}, std::pair{"--mu-kinetic", &f.mu_kinetic_given},
        std::pair{"--step-position", &f.stopping}})
    *given = *given || command.get_option(flag)->count() > 0;
  if (f.config) apply_feeder_config(*f.config, command, feeder_keys(f));
  for (const auto& [name, key, given] :
       {std::tuple{"amplitude", "drive.amplitude", f.amplitude_given},
        std::tuple{"frequency", "drive.frequency", f.frequency_given},
        std::tuple{"mu-static", "friction.mu_static", f.mu_static_given},
        std::tuple{"mu-kinetic", "friction.mu_kinetic", f.mu_kinetic_given}})
    if (!given)
      throw InvalidParameter(name, "missing",
                             std::string("is required: --") + name + " or " + key +
                                 " in --config");
  // Every flag first, by its own name (exit 2, no file).
  require_positive_moderate("amplitude", f.amplitude);
  require_positive_moderate("frequency", f.frequency);
  require_feeder_angle("vibration-angle", f.vibration_angle);
  require_feeder_flags(f.incline, f.mu_static, f.mu_kinetic, f.periods, 1000000,
                       f.steps_per_period, 10000000);
  require_positive_moderate("g", f.g);
  if (!(f.harmonic_ratio >= 0 && f.harmonic_ratio <= 100))
    throw InvalidParameter("harmonic-ratio", f.harmonic_ratio, "must be in [0, 100]");
  require_finite("harmonic-phase", f.harmonic_phase);
  if (!(static_cast<double>(f.periods) * static_cast<double>(f.steps_per_period) <= 1e9))
    throw InvalidParameter("periods", static_cast<double>(f.periods),
                           "periods x steps-per-period must be at most 1e9");
  const Method method = feeder_method(f.method);
  require_restitution(f.restitution);
  if (f.stopping) {
    require_finite("step-position", f.step_position);
    if (!(f.c_mu > 0 && f.c_mu <= 1e6))
      throw InvalidParameter("c-mu", f.c_mu, "must be in (0, 1e6]");
    require_finite("start", f.start);
    if (!(f.max_periods >= 1 && f.max_periods <= 1000000))
      throw InvalidParameter("max-periods", static_cast<double>(f.max_periods),
                             "must be in [1, 1e6]");
  }
  if (f.out) require_output_path("out", *f.out);
  // SI as the model's units: level g makes the friction bound mu (g cos theta + z'').
  const FeederDrive drive{f.amplitude, 1.0 / f.frequency, f.vibration_angle, f.incline, f.g,
                          f.harmonic_ratio, f.harmonic_phase};
  // Without flight the normal load must stay >= 0: |Gamma| <= 1 (docs/feeder.md, onsets).
  if (f.no_flight && std::abs(throw_number(drive)) > 1)
    throw InvalidParameter(
        "amplitude", f.amplitude,
        "makes the normal load m (g cos theta + z'') negative (throw number Gamma = " +
            format_number(throw_number(drive)) + " > 1) while --no-flight forbids a lift-off; "
            "must be <= " + format_number(f.amplitude / std::abs(throw_number(drive))) +
            " m, or drop --no-flight");
  const FeederTable table(drive);
  const FrictionLaw law(f.mu_static, f.mu_kinetic);
  const FeederSolver solver{method, f.steps_per_period, !f.no_flight, f.restitution};
  const FeederRun run = feeder_run(table, law, f.g, f.periods, solver);
  // Stopping at the friction step: the level g before step-position, c_mu g from it on.
  std::optional<FeederStop> stop;
  if (f.stopping) {
    const FrictionField field = FrictionField::steps({f.step_position}, {f.g, f.c_mu * f.g});
    stop = feeder_stop(table, law, field, f.start, f.max_periods, solver);
  }
  const FeederOnsets onsets = feeder_onsets(drive, f.mu_static);
  const double w = 2 * std::numbers::pi * f.frequency;
  const double along = f.amplitude * w * std::cos(f.vibration_angle);  // a0 w cos(psi)
  json r;
  r["command"] = "feeder";
  r["units"] = "si";
  r["drive"] = {{"amplitude_m", f.amplitude},         {"frequency_hz", f.frequency},
                {"vibration_angle_rad", f.vibration_angle}, {"incline_rad", f.incline},
                {"g_m_per_s2", f.g},                  {"mu_static", f.mu_static},
                {"mu_kinetic", f.mu_kinetic},         {"harmonic_ratio", f.harmonic_ratio},
                {"harmonic_phase_rad", f.harmonic_phase}};
  r["machine_number"] = machine_number(drive);
  r["throw_number"] = throw_number(drive);
  r["onsets"] = {{"forward_slip", onset_json(onsets.forward_slip, f.g, w)},
                 {"backward_slip", onset_json(onsets.backward_slip, f.g, w)},
                 {"lift_off", onset_json(onsets.lift_off, f.g, w)}};
  r["method"] = method == Method::exact
                    ? "exact (event-driven: closed-form arcs, certified events)"
                    : "time-stepping (contact core: Moreau, Moreau-Jean flight)";
  r["flight"] = !f.no_flight;
  r["restitution"] = f.restitution;
  r["periods"] = f.periods;
  r["steps_per_period"] =
      method == Method::exact ? json(nullptr) : json(f.steps_per_period);
  r["first_event"] = feeder_event_name(run.first_event);
  r["first_event_time_s"] = number_or_null(run.first_event_time);
  r["lifted_off"] = run.lifted_off;
  r["velocity_m_per_s"] = number_or_null(run.velocity);
  r["dimensionless_speed"] = number_or_null(run.velocity / along);
  r["lift_off_phase_rad"] = number_or_null(run.lift_off_phase);
  r["flight_angle_rad"] = number_or_null(run.flight_angle);
  r["census"] = {{"stick", number_or_null(run.stick_fraction)},
                 {"flight", number_or_null(run.flight_fraction)},
                 {"slip", number_or_null(1 - run.stick_fraction - run.flight_fraction)}};
  if (stop) {
    const FeederOnsets rough = feeder_onsets(drive, f.c_mu * f.mu_static);
    r["stop"] = {{"step_position_m", f.step_position},
                 {"c_mu", f.c_mu},
                 {"start_m", f.start},
                 {"rough_regime", feeder_regime_name(feeder_regime(rough, machine_number(drive)))},
                 {"stopped", stop->stopped},
                 {"end_position_m", number_or_null(stop->end_position)},
                 {"past_step_m", number_or_null(stop->end_position - f.step_position)},
                 {"stop_time_s", number_or_null(stop->stop_time)},
                 {"periods", stop->periods},
                 {"lifted_off", stop->lifted_off}};
  }
  TextTable t;
  t.row("machine number K, throw number Gamma",
        table_text(r["machine_number"]) + ", " + table_text(r["throw_number"]));
  for (const char* kind : {"forward_slip", "backward_slip", "lift_off"})
    t.row(std::string("onset ") + kind + ": K, amplitude [m]",
          table_text(r["onsets"][kind]["machine_number"]) + ", " +
              table_text(r["onsets"][kind]["amplitude_m"]));
  t.row("first event (at [s])",
        table_text(r["first_event"]) + " (" + table_text(r["first_event_time_s"]) + ")");
  t.row("lifted off", table_text(r["lifted_off"]));
  t.row("last period: lift-off phase, flight angle [rad]",
        table_text(r["lift_off_phase_rad"]) + ", " + table_text(r["flight_angle_rad"]));
  t.row("conveying velocity [m/s]", table_text(r["velocity_m_per_s"]));
  t.row("v / (a0 w cos psi)", table_text(r["dimensionless_speed"]));
  t.row("last period: stick / slip / flight",
        table_text(r["census"]["stick"]) + " / " + table_text(r["census"]["slip"]) + " / " +
            table_text(r["census"]["flight"]));
  if (stop) {
    t.row("friction step: position [m], c_mu, rough regime",
          table_text(r["stop"]["step_position_m"]) + ", " + table_text(r["stop"]["c_mu"]) +
              ", " + table_text(r["stop"]["rough_regime"]));
    t.row("stopped (periods)", table_text(r["stop"]["stopped"]) + " (" +
                                   table_text(r["stop"]["periods"]) + ")");
    t.row("end position [m], past the step [m]", table_text(r["stop"]["end_position_m"]) + ", " +
                                                     table_text(r["stop"]["past_step_m"]));
    t.row("stop time [s]", table_text(r["stop"]["stop_time_s"]));
  }
  t.row("method", table_text(r["method"]));
  deliver_report(r, t.str(), f.as_json, f.out);
}

}  // namespace

void add_feeder_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "feeder",
      "A part on a vibratory feeder track in SI units (docs/feeder.md): the track moves along "
      "a line at the vibration angle to its surface, x = a0 cos(psi) sin(w t), z = a0 sin(psi) "
      "sin(w t), on an incline; reports the machine number K = a0 w^2 / g and throw number "
      "Gamma, the closed-form onsets of forward slip, backward slip and lift-off, and a run "
      "from rest (exact by default; --method time-stepping: the contact core, Moreau-Jean "
      "flight): first event, conveying velocity and v / (a0 w cos psi), stick / slip / flight "
      "fractions of the last period, its lift-off phase and flight angle.");
  auto f = std::make_shared<FeederFlags>();
  sub->add_option("--config", f->config,
                  "a TOML or JSON file of these settings in [drive], [friction], [run] and "
                  "[stop] (docs/feeder.md, Config keys); flags override it")
      ->type_name("FILE");
  sub->add_option("--amplitude", f->amplitude,
                  "a0 along the vibration line [m], > 0 (required: here or in --config)")
      ->group("Drive");
  sub->add_option("--frequency", f->frequency,
                  "drive frequency [Hz], > 0 (required: here or in --config)")
      ->group("Drive");
  sub->add_option("--vibration-angle", f->vibration_angle,
                  "psi, the drive line's angle to the track [rad], in (-pi/2, pi/2). Default: 0")
      ->group("Drive");
  sub->add_option("--incline", f->incline,
                  "theta, the track's incline [rad], in (-pi/2, pi/2); > 0: the track rises in "
                  "the conveying direction. Default: 0")
      ->group("Drive");
  add_friction_flags(*sub, f->mu_static, f->mu_kinetic, false);
  sub->add_option("--g", f->g, "gravity [m/s^2], > 0. Default: 9.81")->group("Drive");
  sub->add_option("--harmonic-ratio", f->harmonic_ratio,
                  "r: a second harmonic along the vibration line, a0 (sin w t + r sin(2 w t + "
                  "phi2)), in [0, 100] (0: the classic sinusoid). Default: 0")
      ->group("Drive");
  sub->add_option("--harmonic-phase", f->harmonic_phase,
                  "phi2, the second harmonic's phase [rad]. Default: 0")
      ->group("Drive");
  sub->add_option("--periods", f->periods, "periods from rest, in [1, 1e6]. Default: 20")
      ->group("Solver");
  add_feeder_solver_flags(*sub, f->method, f->restitution);
  sub->add_option("--steps-per-period", f->steps_per_period,
                  "Moreau steps per period (time-stepping), in [2, 1e7]. Default: 2000")
      ->group("Solver");
  sub->add_flag("--no-flight", f->no_flight,
                "forbid lift-off: a drive whose throw number exceeds 1 is refused (exit 2)")
      ->group("Solver");
  sub->add_option("--step-position", f->step_position,
                  "a friction step at this position on the track [m]: the report adds a "
                  "stopping run from --start (friction mu before it, c_mu mu from it on)")
      ->group("Stopping");
  sub->add_option("--c-mu", f->c_mu, "the rough side's friction over the smooth side's, in "
                                     "(0, 1e6]. Default: 2.5")
      ->group("Stopping");
  sub->add_option("--start", f->start, "where the part is released at rest [m]. Default: 0")
      ->group("Stopping");
  sub->add_option("--max-periods", f->max_periods,
                  "periods before a part that still moves is reported as not stopped, in "
                  "[1, 1e6]. Default: 1000")
      ->group("Stopping");
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE (nothing printed)")
      ->type_name("FILE")
      ->group("Output");
  sub->callback([f, sub] { run_feeder(*f, *sub); });
}

}  // namespace selfalign::cli
