#pragma once
// Internal: the parts of config loading shared by the JSON and TOML readers.

#include <string>
#include <string_view>

#include "selfalign/io/simulate_config.hpp"

namespace selfalign::detail {

/// The key named `name`; throws InvalidParameter("config key", name, "unknown key in <file>;
/// allowed: ...") when there is none.
const ConfigKey& require_config_key(std::string_view name, const std::string& file);

/// Throws InvalidParameter(key, value_text, "must be a <type> (in <file>)").
[[noreturn]] void throw_wrong_type(const ConfigKey& key, const std::string& value_text,
                                   const std::string& file);

/// Throws InvalidParameter("config file", file, message) with message on one line.
[[noreturn]] void throw_malformed(const std::string& file, const std::string& message);

/// Parsers of one file's text; `file` names it in messages.
SimulateConfig parse_json_config(const std::string& text, const std::string& file);
SimulateConfig parse_toml_config(const std::string& text, const std::string& file);

}  // namespace selfalign::detail
