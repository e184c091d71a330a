#pragma once
// The parts config of `selfalign parts` (docs/rows.md, "The parts config"): the flags every
// parts subcommand shares and the setup read from the config with them (cmd_parts.cpp).

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "selfalign/analysis/row.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign::cli {

struct PartsFlags {
  std::string config;
  std::optional<std::string> method;
  std::optional<long long> periods, max_periods, steps_per_period, samples_per_period;
  std::optional<double> restitution, frequency;
  bool as_json = false;
  std::optional<std::string> out, csv;
};

struct PartsSetup {
  ThreePhaseParameters table{1.0, 0.084, 3.0, 0.9};
  std::optional<double> step_position;
  double c_mu = 2.5;
  RowQueue queue;
  RowSolver solver;
  long long periods = 20, max_periods = 1000, samples = 20;
};

/// The config's setup, the flags given overriding it. Throws InvalidParameter naming the
/// section and key, or the part (parts[i].length).
PartsSetup read_parts_config(const PartsFlags& flags);

/// `selfalign parts montecarlo` (cmd_parts_montecarlo.cpp), added to the `parts` command.
void add_parts_montecarlo_command(CLI::App& parts);

}  // namespace selfalign::cli
