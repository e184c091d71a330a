#pragma once
// "Did you mean ...?" for a command line CLI11 refused: the first unknown subcommand or flag,
// and the subcommand or flag of the same command it most likely stands for.

#include <string>

#include <CLI/CLI.hpp>

namespace selfalign::cli {

/// After a failed app.parse(argc, argv), the message for the first unknown word that looks like
/// a typo: "unknown subcommand desing (did you mean design?)", "unknown flag --c_mu (did you
/// mean --c-mu?)", a retired flag and its replacement; "" when there is none.
std::string typo_hint(CLI::App& app, int argc, const char* const* argv);

}  // namespace selfalign::cli
