// load_simulate_config: the 1-D config is one flat key table (section "") read by the one
// config reader (config_reader.hpp) from a JSON or TOML document (io/document.hpp).

#include "selfalign/error.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {
namespace {

// A config is one table of keys whose values are numbers, strings or arrays of numbers.
const DocumentKind kConfigDocument{"config file", "--config", 2};

}  // namespace

void set_simulate_config_value(SimulateConfig& config, const ConfigKey& key, ConfigValue value) {
  std::visit(
      [&](auto field) {
        using Value = typename std::remove_reference_t<decltype(config.*field)>::value_type;
        config.*field = std::get<Value>(std::move(value));
      },
      key.field);
}

SimulateConfig load_simulate_config(const std::string& path) {
  const nlohmann::json doc = read_document(path, kConfigDocument);
  if (!doc.is_object())
    throw InvalidParameter("config file", path, "must contain one JSON object of keys");
  return simulate_config_from_json(doc, path);
}

SimulateConfig simulate_config_from_json(const nlohmann::json& doc, const std::string& source) {
  if (!doc.is_object())
    throw InvalidParameter("config", source, "must be one JSON object of keys");
  SimulateConfig config;
  const ConfigValues values = read_config_values(doc, simulate_config_key_table(), source);
  for (const ConfigValues::Entry& entry : values.entries())
    set_simulate_config_value(config, *find_simulate_config_key(entry.key->name),
                              entry.value);
  return config;
}

}  // namespace selfalign
