// load_simulate_config: read the file, pick the parser by extension.

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config_reader.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {
namespace detail {

const ConfigKey& require_config_key(std::string_view name, const std::string& file) {
  const ConfigKey* key = find_simulate_config_key(name);
  if (!key)
    throw InvalidParameter("config key", std::string(name),
                           unknown_config_key_hint(name) + " (in " + file + ")");
  return *key;
}

void throw_wrong_type(const ConfigKey& key, const std::string& value_text,
                      const std::string& file) {
  constexpr std::size_t kMaxShown = 60;  // keep the message one short line
  std::string shown = value_text.size() > kMaxShown ? value_text.substr(0, kMaxShown) + "..."
                                                    : value_text;
  throw InvalidParameter(std::string(key.name), shown,
                         std::string(key.field.index() == 2 ? "must be an " : "must be a ") +
                             std::string(config_type_name(key)) + " (in " + file + ")");
}

void throw_malformed(const std::string& file, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  throw InvalidParameter("config file", file, line);
}

}  // namespace detail

SimulateConfig load_simulate_config(const std::string& path) {
  if (path.empty()) throw InvalidParameter("config file", "\"\"", "must name a .json or .toml file");
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension != ".json" && extension != ".toml")
    throw InvalidParameter("config file", path, "must end in .json or .toml");
  constexpr std::uintmax_t kMaxConfigBytes = 16u << 20;  // a config is a few hundred bytes
  require_input_file("config file", path, "--config", kMaxConfigBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) detail::throw_malformed(path, std::string("cannot be read: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) detail::throw_malformed(path, "cannot be read");
  return extension == ".json" ? detail::parse_json_config(text.str(), path)
                              : detail::parse_toml_config(text.str(), path);
}

}  // namespace selfalign
