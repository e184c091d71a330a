// The JSON reader of load_simulate_config (nlohmann): one flat object of keys.

#include <nlohmann/json.hpp>

#include "config_reader.hpp"

namespace selfalign::detail {

SimulateConfig parse_json_config(const std::string& text, const std::string& file) {
  // A config is one object of keys whose values are scalars or arrays of numbers: depth <= 2.
  // Deeper documents are refused while parsing (a 60 000-deep one overflowed the stack when its
  // value was formatted for the error message).
  constexpr int kMaxDepth = 2;
  const nlohmann::json::parser_callback_t flat_only =
      [&file](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
        if (depth >= kMaxDepth && (event == nlohmann::json::parse_event_t::object_start ||
                                   event == nlohmann::json::parse_event_t::array_start))
          throw_malformed(file, "nests too deeply: a config is one object of keys whose values "
                                "are numbers, strings or arrays of numbers");
        return true;
      };
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, flat_only);
  } catch (const nlohmann::json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 1, column 2: ..." -> from "parse".
    std::string message = e.what();
    if (const auto close = message.find("] "); message.rfind("[json.exception", 0) == 0 &&
                                               close != std::string::npos)
      message.erase(0, close + 2);
    throw_malformed(file, message);
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
