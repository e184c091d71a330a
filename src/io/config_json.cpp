// The JSON reader of load_simulate_config (nlohmann): one flat object of keys.

#include <nlohmann/json.hpp>

#include "config_reader.hpp"

namespace selfalign::detail {

SimulateConfig parse_json_config(const std::string& text, const std::string& file) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw_malformed(file, e.what());
  }
  if (!doc.is_object()) throw_malformed(file, "must contain one JSON object of keys");
  SimulateConfig config;
  for (const auto& [name, value] : doc.items()) {
    const ConfigKey& key = require_config_key(name, file);
    if (auto* text_field = std::get_if<TextField>(&key.field)) {
      if (!value.is_string()) throw_wrong_type(key, value.dump(), file);
      config.**text_field = value.get<std::string>();
    } else if (auto* number_field = std::get_if<NumberField>(&key.field)) {
      if (!value.is_number()) throw_wrong_type(key, value.dump(), file);
      config.**number_field = value.get<double>();
    } else {
      const auto* list = std::get_if<NumberListField>(&key.field);
      if (!value.is_array()) throw_wrong_type(key, value.dump(), file);
      std::vector<double> numbers;
      for (const auto& item : value) {
        if (!item.is_number()) throw_wrong_type(key, value.dump(), file);
        numbers.push_back(item.get<double>());
      }
      config.**list = std::move(numbers);
    }
  }
  return config;
}

}  // namespace selfalign::detail
