// `selfalign simulate`: one flag per config key (key c_mu <-> --c-mu), optional --config FILE;
// flags override the file. Everything is computed and formatted before any file is written,
// and the files are committed together (AtomicFileSet), so a failed run leaves none behind.

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/io/trajectory_csv.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::cli {
namespace {

struct SimulateFlags {
  std::string config_file;
  std::vector<std::string> values;     // one per simulate_config_keys() entry, as typed
  std::vector<CLI::Option*> options;   // the matching flags (count() > 0: given)
};

std::string group_title(std::string_view group) {
  if (group == "run") return "Run";
  if (group == "profile") return "Table profile";
  if (group == "friction") return "Friction map";
  if (group == "scales") return "Scales (SI conversion)";
  if (group == "initial") return "Initial state";
  if (group == "solver") return "Solver";
  return "Output";
}

std::string_view type_name(const ConfigKey& key) {
  switch (key.field.index()) {
    case 0: return key.name == "out" || key.name == "summary" || key.name == "samples" ? "FILE"
                                                                                       : "TEXT";
    case 1: return "NUMBER";
    default: return "LIST";
  }
}

void run_simulate(const SimulateFlags& flags) {
  SimulateConfig config;
  if (!flags.config_file.empty()) config = load_simulate_config(flags.config_file);
  const auto keys = simulate_config_keys();
  SimulateConfig overrides;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (flags.options[i]->count() > 0)
      set_simulate_config_value(overrides, keys[i].name, flags.values[i]);
  config = merge(config, overrides);

  const OutputPaths paths = resolve_output_paths(config);
  const SimulateModel model = build_simulate_model(config);
  const SimulationResult result =
      simulate(*model.profile, *model.friction, model.initial, model.options);

  const std::string summary =
      simulate_summary_json(model, result, paths.trajectory).dump(2) + "\n";
  AtomicFileSet files;
  if (paths.trajectory)
    files.add(*paths.trajectory, format_trajectory_csv(result.trajectory, model.output_units()));
  if (!paths.summary_to_stdout()) files.add(paths.summary, summary);
  files.commit();
  if (paths.summary_to_stdout()) std::cout << summary << std::flush;
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Simulate the object on the moving table (exact event-driven or time-stepping solver); "
      "write the trajectory CSV (--out) and a JSON summary. Inputs in dimensionless units "
      "(Sect. 3.2) unless --units si. Defaults: the paper's Sect. 7.2 setting.");
  auto flags = std::make_shared<SimulateFlags>();
  sub->add_option("--config", flags->config_file,
                  "JSON (.json) or TOML (.toml) file of config keys (docs/config.md); flags "
                  "override its values")
      ->type_name("FILE");
  const auto keys = simulate_config_keys();
  flags->values.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    flags->options.push_back(sub->add_option(config_flag(keys[i]), flags->values[i],
                                             config_help(keys[i]))
                                 ->type_name(std::string(type_name(keys[i])))
                                 ->group(group_title(keys[i].group)));
  sub->callback([flags] { run_simulate(*flags); });
}

}  // namespace selfalign::cli
