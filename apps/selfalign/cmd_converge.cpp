// `selfalign converge`: convergence of two velocity responses on the uniform table (Sect. 6.2,
// Fig. 13): v1(t), v2(t) from two initial velocities, the Lyapunov function V = (v1 - v2)^2/2
// of eq. (35), and the '=' / '≠' intervals of the selected friction forces.

#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "config_flags.hpp"
#include "report.hpp"
#include "selfalign/analysis/convergence.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

struct ConvergeFlags {
  double v1 = ConvergenceOptions{}.v1;  // run units; converted when given in an SI run
  double v2 = ConvergenceOptions{}.v2;
  int samples_per_period = ConvergenceOptions{}.samples_per_period;
  CLI::Option* v1_option = nullptr;
  CLI::Option* v2_option = nullptr;
};

// The options in [-]: velocities as given (run units) or the library defaults, t0 and the
// duration (periods * Δt) from the config keys.
ConvergenceOptions convergence_options(const SimulateConfig& resolved, const ProfileModel& model,
                                       const ConvergeFlags& f) {
  ConvergenceOptions o;
  if (f.v1_option->count() > 0) o.v1 = model.to_model_units(D::velocity, f.v1);
  if (f.v2_option->count() > 0) o.v2 = model.to_model_units(D::velocity, f.v2);
  o.t0 = model.to_model_units(D::time, *resolved.t0);
  const double periods = require_positive("periods", *resolved.periods);
  if (periods > 1e6) throw InvalidParameter("periods", periods, "must be in (0, 1e6] for converge");
  o.duration = periods * model.profile->period();
  o.samples_per_period = f.samples_per_period;
  o.integrator = model.integrator;
  return o;
}

// Header "t,v1,v2,V"; V = (v1 - v2)^2/2 has the unit of a velocity squared.
std::string convergence_csv(const VelocityConvergence& r, const OutputUnits& u) {
  const double v_scale = u.velocity(1.0);
  std::string csv = "t,v1,v2,V\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    csv += csv_number(u.time(r.t[i])) + ',' + csv_number(u.velocity(r.v1[i])) + ',' +
           csv_number(u.velocity(r.v2[i])) + ',' +
           csv_number(r.lyapunov[i] * v_scale * v_scale) + '\n';
  return csv;
}

json convergence_json(const ProfileModel& model, double periods, const ConvergenceOptions& o,
                      const VelocityConvergence& r, const OutputPaths& paths) {
  const OutputUnits u = model.output_units();
  const double v_scale = u.velocity(1.0);
  json j;
  j["units"] = to_string(model.units);
  j["profile"] = model.profile->kind();
  j["v1"] = u.velocity(o.v1);
  j["v2"] = u.velocity(o.v2);
  j["t0"] = u.time(o.t0);
  j["duration"] = u.time(o.duration);
  j["periods"] = periods;
  j["samples_per_period"] = o.samples_per_period;
  j["intervals"] = json::array();
  for (const SignInterval& s : r.intervals)
    j["intervals"].push_back(
        {{"t_begin", u.time(s.t_begin)}, {"t_end", u.time(s.t_end)}, {"same", s.same}});
  j["t_coincide"] = r.t_coincide ? json(u.time(*r.t_coincide)) : json(nullptr);
  j["V0"] = r.lyapunov.empty() ? json(nullptr) : json(r.lyapunov.front() * v_scale * v_scale);
  j["V_end"] = r.lyapunov.empty() ? json(nullptr) : json(r.lyapunov.back() * v_scale * v_scale);
  j["csv_file"] = paths.trajectory ? json(*paths.trajectory) : json(nullptr);
  return j;
}

void run_converge(const ConfigFlags& flags, const ConvergeFlags& f) {
  const SimulateConfig config = read_config(flags);
  const OutputPaths paths = resolve_output_paths(config);
  const ProfileModel model = build_profile_model(config);
  const SimulateConfig resolved = resolve_simulate_config(config);  // t0, periods as given
  const ConvergenceOptions options = convergence_options(resolved, model, f);
  const VelocityConvergence r = velocity_convergence(*model.profile, model.law, options);

  const std::string summary =
      convergence_json(model, *resolved.periods, options, r, paths).dump(2) + "\n";
  AtomicFileSet files;  // "-" is standard output, written after the files
  if (paths.trajectory)
    files.add(*paths.trajectory, convergence_csv(r, model.output_units()), "out");
  if (paths.summary) files.add(*paths.summary, summary, "summary");
  files.commit();
}

}  // namespace

void add_converge_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "converge",
      "Convergence of two velocity responses on the uniform table (Sect. 6.2, Fig. 13): "
      "v1(t), v2(t) from initial velocities --v1, --v2 at t0 and the Lyapunov function "
      "V = (v1 - v2)^2/2 (eq. 35); CSV t,v1,v2,V (--out) and a JSON summary. Needs a "
      "piecewise-constant table acceleration.");
  auto flags = add_config_flags(
      *sub, without_uniform_table_keys(
                {{"out", "CSV file of t,v1,v2,V (default: none written)"},
                 {"summary", "summary JSON file, - for stdout (default: <out without extension>"
                             ".summary.json when out is given, else stdout)"},
                 {"v0", ""}},
                {"t0", "periods"}));
  auto f = std::make_shared<ConvergeFlags>();
  const std::string unit = ". Unit: [-], SI [m/s]. Default: ";
  f->v1_option = sub->add_option("--v1", f->v1,
                                 "initial velocity x' of response 1" + unit +
                                     format_number(f->v1) + " [-]")
                     ->type_name("NUMBER")
                     ->group("Initial state");
  f->v2_option = sub->add_option("--v2", f->v2,
                                 "initial velocity x' of response 2" + unit +
                                     format_number(f->v2) + " [-]")
                     ->type_name("NUMBER")
                     ->group("Initial state");
  sub->add_option("--samples-per-period", f->samples_per_period,
                  "uniform samples per table period in the CSV (events are added), in [1, 1e6], "
                  "at most 1e7 over the run. "
                  "Default: " + std::to_string(f->samples_per_period))
      ->type_name("INT")
      ->group("Output");
  sub->callback([flags, f] { run_converge(*flags, *f); });
}

}  // namespace selfalign::cli
