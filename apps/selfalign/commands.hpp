#pragma once
// The CLI's subcommands. Each lives in its own cmd_<name>.cpp: it adds a CLI11 subcommand to
// the app, with a callback that parses, calls the library and formats (no physics here).
// A callback reports misuse by throwing (selfalign::InvalidParameter); main.cpp turns any
// exception into one line on stderr and exit code 2.
//
// Files: an option naming a file has type_name("FILE"); one that the command writes is in
// group("Output"), any other is an input. main.cpp registers every such value in the run's
// file registry (io/run_files.hpp) while parsing, so an output naming an input or another
// output's file is refused before the callback runs; files named inside a config are
// registered by read_config (config_flags.hpp) and inside other documents by their readers.

#include <CLI/CLI.hpp>

namespace selfalign::cli {

/// `selfalign simulate`: one run from a config file and/or flags (cmd_simulate.cpp).
void add_simulate_command(CLI::App& app);
/// `selfalign steady`: steady state, motion case, v̄ and f on the uniform table (cmd_steady.cpp).
void add_steady_command(CLI::App& app);
/// `selfalign floquet`: Floquet multipliers of the steady state, three ways (cmd_floquet.cpp).
void add_floquet_command(CLI::App& app);
/// `selfalign converge`: convergence of two velocity responses, eq. (35) (cmd_converge.cpp).
void add_converge_command(CLI::App& app);
/// `selfalign stop`: one stopping run on the two-region table, Sect. 7 (cmd_stop.cpp).
void add_stop_command(CLI::App& app);
/// `selfalign accuracy`: positioning accuracy, Sect. 7.1, eq. (39) (cmd_accuracy.cpp).
void add_accuracy_command(CLI::App& app);
/// `selfalign accumulation`: the stick-position map, eqs. (59), (60) (cmd_accumulation.cpp).
void add_accumulation_command(CLI::App& app);
/// `selfalign sweep accelerations|period|stroke|positioning`: parameter studies
/// (cmd_sweep*.cpp).
void add_sweep_command(CLI::App& app);
void add_optimize_command(CLI::App& app);
void add_design_command(CLI::App& app);
/// `selfalign montecarlo`: a designed process under uncertain inputs (cmd_montecarlo.cpp).
void add_montecarlo_command(CLI::App& app);
/// `selfalign planar simulate|steady|field|stop`: planar rigid-part motion (cmd_planar.cpp).
void add_planar_command(CLI::App& app);
/// `selfalign feeder`: a part on a vibratory feeder track, SI (cmd_feeder.cpp).
void add_feeder_command(CLI::App& app);
/// `selfalign regimes`: the feeder's regime chart, CSV rows (cmd_regimes.cpp).
void add_regimes_command(CLI::App& app);
/// `selfalign feeder-design`: the least feeder drive for a target speed (cmd_feeder_design.cpp).
void add_feeder_design_command(CLI::App& app);
/// `selfalign parts simulate|stop`: a queue of 1-D parts, [[parts]] config (cmd_parts.cpp).
void add_parts_command(CLI::App& app);
/// `selfalign parameters`: the model's named parameter view, --set NAME=VALUE (cmd_parameters.cpp).
void add_parameters_command(CLI::App& app);
/// `selfalign identify`: friction identified from measured motion (cmd_identify.cpp).
void add_identify_command(CLI::App& app);
/// Hidden `selfalign completion bash|zsh` and `selfalign man`: completion scripts and a man
/// page generated from the app's own tree of subcommands and flags (cmd_completion.cpp).
void add_completion_command(CLI::App& app);

}  // namespace selfalign::cli
