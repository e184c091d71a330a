// selfalign: the command-line front door. Parses, dispatches to a subcommand, reports errors
// as exactly one line "selfalign: error: <message>" on stderr with exit code 2.

#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace {

constexpr int kUsageError = 2;  // exit code for every error: bad input, bad config, I/O

// The one-line error report: newlines (from a parser's message) become spaces.
int report_error(const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "selfalign: error: " << line << '\n';
  return kUsageError;
}

// Subcommands, in help order. A new subcommand adds its cmd_<name>.cpp and one line here.
constexpr void (*kCommands[])(CLI::App&) = {
    &selfalign::cli::add_simulate_command,
    &selfalign::cli::add_steady_command,
    &selfalign::cli::add_floquet_command,
    &selfalign::cli::add_converge_command,
    &selfalign::cli::add_stop_command,
    &selfalign::cli::add_accuracy_command,
    &selfalign::cli::add_accumulation_command,
    &selfalign::cli::add_sweep_command,
    &selfalign::cli::add_optimize_command,
    &selfalign::cli::add_design_command,
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Vibrational self-alignment of a rigid object on a periodically moving table with "
      "Coulomb stick-slip friction (Hunnekens et al. 2010).",
      "selfalign"};
  app.set_version_flag("--version", std::string("selfalign ") + SELFALIGN_VERSION);
  app.require_subcommand(1);
  for (auto add : kCommands) add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version: print and exit 0
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return report_error(e.what());
  } catch (const std::exception& e) {  // selfalign::InvalidParameter and everything else
    return report_error(e.what());
  } catch (...) {
    return report_error("unknown failure");
  }
  return 0;
}
