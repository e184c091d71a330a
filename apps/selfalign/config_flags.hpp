#pragma once
// The config keys of include/selfalign/io/simulate_config.hpp as CLI flags (key c_mu <-> flag
// --c-mu) plus --config FILE, shared by every subcommand that describes a table motion, so all
// take the same flags. Flags override the file.

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "selfalign/io/simulate_config.hpp"

namespace selfalign::cli {

/// The flags' values as typed, filled in by CLI11 during parsing.
struct ConfigFlags {
  std::string config_file;
  CLI::Option* config_option = nullptr;  // --config
  std::vector<std::string> values;    // one per simulate_config_keys() entry
  std::vector<CLI::Option*> options;  // the matching flags; nullptr: not offered for this command
};

/// A command's own wording for a key (e.g. what --out writes), or leaving a key out.
struct KeyFlag {
  std::string_view key;   ///< config key name, e.g. "out"
  std::string_view help;  ///< help text replacing the key table's; empty: no flag for this key
};

/// `overrides` plus a flag-less entry for every key of `groups` except those in `keep`: how a
/// command that reads no friction map (steady, floquet, ...) leaves those flags out instead of
/// offering flags it would ignore. Typing one is then an error that says the command does not
/// use it (typo_hint); a --config file shared between commands may still hold the keys.
std::vector<KeyFlag> without_groups(std::vector<KeyFlag> overrides,
                                    std::initializer_list<std::string_view> groups,
                                    const std::vector<std::string_view>& keep = {});

/// `overrides` without the keys a steady-state analysis on the uniform table does not read:
/// the friction map, the initial state, the solver choice and its time-stepping keys (the slip
/// integrator's tolerances stay: Stribeck and viscous laws use them), except those in `keep`.
/// Used by steady, floquet, converge and the sweeps.
std::vector<KeyFlag> without_uniform_table_keys(std::vector<KeyFlag> overrides,
                                                std::vector<std::string_view> keep = {});

/// Adds --config and one flag per config key to `command`, in the key table's groups.
/// `overrides` rewords or removes keys whose meaning differs for this command (a key without a
/// flag is still accepted, and ignored, in a --config file).
std::shared_ptr<ConfigFlags> add_config_flags(CLI::App& command,
                                              const std::vector<KeyFlag>& overrides = {});

/// The config file (if any) with the given flags applied over it; the files it names are
/// registered as inputs of the run (register_config_files).
SimulateConfig read_config(const ConfigFlags& flags);

}  // namespace selfalign::cli
