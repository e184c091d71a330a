// `selfalign simulate`: one flag per config key (key c_mu <-> --c-mu), optional --config FILE;
// flags override the file. Everything is computed and formatted before any file is written,
// and the files are committed together (AtomicFileSet), so a failed run leaves none behind.

#include <iostream>
#include <string>

#include "commands.hpp"
#include "config_flags.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/io/trajectory_csv.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::cli {
namespace {

void run_simulate(const ConfigFlags& flags) {
  const SimulateConfig config = read_config(flags);
  const OutputPaths paths = resolve_output_paths(config);
  const SimulateModel model = build_simulate_model(config);
  SimulationOptions options = model.options;
  options.record = paths.trajectory.has_value();  // samples only when a CSV is written (P01)
  const SimulationResult result = simulate(*model.profile, *model.friction, model.law, model.initial, options);

  const std::string summary =
      simulate_summary_json(model, result, paths.trajectory).dump(2) + "\n";
  AtomicFileSet files;  // "-" is standard output, written after the files
  if (paths.trajectory)
    files.add(*paths.trajectory, format_trajectory_csv(result.trajectory, model.output_units()),
              "out");
  if (paths.summary) files.add(*paths.summary, summary, "summary");
  files.commit();
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Simulate the object on the moving table (exact event-driven or time-stepping solver); "
      "write the trajectory CSV (--out) and a JSON summary. Inputs in dimensionless units "
      "(Sect. 3.2) unless --units si. Defaults: the paper's Sect. 7.2 setting.");
  auto flags = add_config_flags(*sub);
  sub->callback([flags] { run_simulate(*flags); });
}

}  // namespace selfalign::cli
