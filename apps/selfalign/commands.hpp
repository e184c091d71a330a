#pragma once
// The CLI's subcommands. Each lives in its own cmd_<name>.cpp: it adds a CLI11 subcommand to
// the app, with a callback that parses, calls the library and formats (no physics here).
// A callback reports misuse by throwing (selfalign::InvalidParameter); main.cpp turns any
// exception into one line on stderr and exit code 2.

#include <CLI/CLI.hpp>

namespace selfalign::cli {

/// `selfalign simulate`: one run from a config file and/or flags (cmd_simulate.cpp).
void add_simulate_command(CLI::App& app);

}  // namespace selfalign::cli
