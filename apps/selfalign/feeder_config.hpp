#pragma once
// The config file of `selfalign feeder` (--config FILE, TOML or JSON; docs/feeder.md, "Config
// keys"): the flags' values as keys in the sections [drive], [friction], [run] and [stop], in
// SI. A flag given on the command line overrides the file's key.

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

namespace selfalign::cli {

/// One key of the file and the flag it stands for: where the value goes.
struct FeederConfigKey {
  std::string_view section, name, flag;  ///< e.g. "drive", "amplitude", "--amplitude"
  std::variant<double*, long long*, std::string*> target;
  bool* given = nullptr;  ///< set when the file or the flag gives the value (optional keys)
};

/// Reads `path` (read_document: one clean error line naming the file and where) against the
/// keys: unknown keys are refused with the spelling hint of the config reader (naming the key
/// as "section.name"); every key whose flag was not given on `command`'s line is set from
/// the file.
void apply_feeder_config(const std::string& path, const CLI::App& command,
                         const std::vector<FeederConfigKey>& keys);

}  // namespace selfalign::cli
