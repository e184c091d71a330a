// selfalign: the command-line front door. Parses, dispatches to a subcommand, reports errors
// as exactly one line "selfalign: error: <message>" on stderr with exit code 2.

#include <charconv>
#include <cmath>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "typo_hint.hpp"
#include "warnings.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/run_files.hpp"

namespace {

constexpr int kUsageError = 2;  // exit code for every error: bad input, bad config, I/O
constexpr std::size_t kMaxErrorLine = 300;  // one short line, whatever a parser echoes

// The one-line error report: newlines (from a parser's message) become spaces, and a message
// that echoes a huge value is cut.
int report_error(const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (line.size() > kMaxErrorLine) line = line.substr(0, kMaxErrorLine) + "...";
  std::cerr << "selfalign: error: " << line << '\n';
  return kUsageError;
}

// Values CLI11 would accept silently: "" (read as 0 by a number option, or as "no file"), and
// for FILE options a value that is another flag (`--out= --json` made a file named --json).
const CLI::Validator kNotEmpty(
    [](std::string& value) { return value.empty() ? std::string("must not be empty") : ""; },
    "", "NotEmpty");
const CLI::Validator kNotAFlag(
    [](std::string& value) {
      return value.size() > 1 && value[0] == '-'
                 ? "'" + value + "' looks like a flag, not a file (write ./" + value + ")"
                 : std::string();
    },
    "", "NotAFlag");

// A number beyond the range of a double (1e-999, 1e999) that CLI11 would round to 0 or inf.
const CLI::Validator kRepresentable(
    [](std::string& value) {
      double v = 0;
      const char* begin = value.data() + (!value.empty() && value[0] == '+');
      const auto [end, ec] = std::from_chars(begin, value.data() + value.size(), v);
      return ec == std::errc::result_out_of_range && end == value.data() + value.size()
                 ? "'" + value + "' is beyond the range of a double"
                 : std::string();
    },
    "", "Representable");

// Every number given to a flag is a finite number within ±1e50 (error.hpp, kMaxMagnitude),
// whether the run uses the flag or not: NaN is never "not given" (a flag not given is), and
// 1e60 and inf are typos or probes. Each flag's own range is checked where it is used.
CLI::Validator moderate_number(const std::string& flag) {
  return CLI::Validator(
      [flag](std::string& value) {
        double v = 0;
        const char* begin = value.data() + (!value.empty() && value[0] == '+');
        const auto [end, ec] = std::from_chars(begin, value.data() + value.size(), v);
        if (ec == std::errc() && end == value.data() + value.size() &&
            !(std::abs(v) <= selfalign::kMaxMagnitude))
          throw selfalign::InvalidParameter(flag, value,
                                            "must be a finite number with |value| <= 1e50");
        return std::string();  // not a number: the option's own conversion says so
      },
      "", "ModerateNumber");
}

// Every FILE option registers its file in the run's registry (io/run_files.hpp) as it is
// parsed, before any subcommand runs: an output (an option of the group "Output") may not be an
// input nor another output's file, however spelled; an input (any other FILE option) may not be
// an output's file. A new subcommand's FILE options are registered without a line of its own.
CLI::Validator run_file(const CLI::Option& option) {
  const bool output = option.get_group() == "Output";
  const std::string name = option.get_lnames().empty() ? option.get_name() : option.get_lnames()[0];
  return CLI::Validator(
      [output, name](std::string& path) {
        if (output) selfalign::require_output_path(name, path);
        else selfalign::register_input_file(path, "--" + name);
        return std::string();
      },
      "", "RunFile");
}

void guard_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size() == 0) continue;  // a flag takes no value
    option->check(kNotEmpty);
    option->check(kRepresentable);
    if (option->get_type_name() == "FLOAT" || option->get_type_name() == "NUMBER")
      option->check(moderate_number(option->get_name()));
    if (option->get_type_name() == "FILE") {
      option->check(kNotAFlag);
      option->check(run_file(*option));  // after the checks above: only plausible paths
    }
    if (option->get_type_name() == "INT" || option->get_type_name() == "UINT") {
      // CLI11's own refusal ("Could not convert") names no range: name it from the help text.
      const std::string help = option->get_description();
      option->check(CLI::Validator(
          [help](std::string& value) {
            long long n = 0;
            const char* begin = value.data() + (!value.empty() && value[0] == '+');
            const auto [end, ec] = std::from_chars(begin, value.data() + value.size(), n);
            return ec == std::errc() && end == value.data() + value.size()
                       ? std::string()
                       : "'" + value + "' is not a whole number (" + help + ")";
          },
          "", "WholeNumber"));
    }
  }
  for (CLI::App* sub : app.get_subcommands({})) guard_values(*sub);
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
    &selfalign::cli::add_montecarlo_command,
    &selfalign::cli::add_planar_command,
    &selfalign::cli::add_feeder_command,
    &selfalign::cli::add_regimes_command,
    &selfalign::cli::add_feeder_design_command,
    &selfalign::cli::add_parts_command,
    &selfalign::cli::add_parameters_command,
    &selfalign::cli::add_identify_command,
    &selfalign::cli::add_completion_command,  // hidden: completion bash|zsh, man
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
  guard_values(app);
  selfalign::remove_temporaries_on_signals();  // Ctrl-C leaves no half-written *.tmp-* behind
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version: print and exit 0
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown subcommand or flag: name the one that was most likely meant.
    const bool unknown = dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr ||
                         dynamic_cast<const CLI::RequiredError*>(&e) != nullptr;
    const std::string hint = unknown ? selfalign::cli::typo_hint(app, argc, argv) : "";
    return report_error(hint.empty() ? e.what() : hint);
  } catch (const std::exception& e) {  // selfalign::InvalidParameter and everything else
    return report_error(e.what());
  } catch (...) {
    return report_error("unknown failure");
  }
  selfalign::cli::print_warnings();
  return 0;
}
