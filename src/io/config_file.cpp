// load_simulate_config: one flat table of config keys from a JSON or TOML document
// (io/document.hpp), each value checked against its key's type.

#include "selfalign/error.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

// A config is one table of keys whose values are numbers, strings or arrays of numbers.
const DocumentKind kConfigDocument{"config file", "--config", 2};

const ConfigKey& require_config_key(std::string_view name, const std::string& file) {
  const ConfigKey* key = find_simulate_config_key(name);
  if (!key)
    throw InvalidParameter("config key", std::string(name),
                           unknown_config_key_hint(name) + " (in " + file + ")");
  return *key;
}

[[noreturn]] void throw_wrong_type(const ConfigKey& key, const json& value,
                                   const std::string& file) {
  throw InvalidParameter(std::string(key.name), document_value_text(value),
                         std::string(key.field.index() == 2 ? "must be an " : "must be a ") +
                             std::string(config_type_name(key)) + " (in " + file + ")");
}

}  // namespace

SimulateConfig load_simulate_config(const std::string& path) {
  const json doc = read_document(path, kConfigDocument);
  if (!doc.is_object())
    throw InvalidParameter("config file", path, "must contain one JSON object of keys");
  SimulateConfig config;
  for (const auto& [name, value] : doc.items()) {
    const ConfigKey& key = require_config_key(name, path);
    if (auto* text_field = std::get_if<TextField>(&key.field)) {
      if (!value.is_string()) throw_wrong_type(key, value, path);
      config.**text_field = value.get<std::string>();
    } else if (auto* number_field = std::get_if<NumberField>(&key.field)) {
      if (!value.is_number()) throw_wrong_type(key, value, path);
      config.**number_field = value.get<double>();
    } else {
      const auto* list = std::get_if<NumberListField>(&key.field);
      if (!value.is_array()) throw_wrong_type(key, value, path);
      std::vector<double> numbers;
      for (const auto& item : value) {
        if (!item.is_number()) throw_wrong_type(key, value, path);
        numbers.push_back(item.get<double>());
      }
      config.**list = std::move(numbers);
    }
  }
  return config;
}

}  // namespace selfalign
