// The TOML reader of load_simulate_config (toml++): top-level key = value pairs only.

#include <sstream>

#include <toml++/toml.h>

#include "config_reader.hpp"

namespace selfalign::detail {
namespace {

// How a node is shown in a wrong-type message: scalars as written, containers by kind.
std::string describe(const toml::node& node) {
  if (node.is_table()) return "a table";
  if (node.is_array()) return "an array";
  std::ostringstream s;
  node.visit([&s](const auto& value) { s << value; });
  return s.str();
}

std::optional<double> number(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

}  // namespace

SimulateConfig parse_toml_config(const std::string& text, const std::string& file) {
  toml::table doc;
  try {
    doc = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw_malformed(file, std::string(e.description()) + " (line " + std::to_string(at.line) +
                              ", column " + std::to_string(at.column) + ")");
  }
  SimulateConfig config;
  for (const auto& [name, node] : doc) {
    const ConfigKey& key = require_config_key(name.str(), file);
    if (auto* text_field = std::get_if<TextField>(&key.field)) {
      const auto* s = node.as_string();
      if (!s) throw_wrong_type(key, describe(node), file);
      config.**text_field = s->get();
    } else if (auto* number_field = std::get_if<NumberField>(&key.field)) {
      const std::optional<double> v = number(node);
      if (!v) throw_wrong_type(key, describe(node), file);
      config.**number_field = *v;
    } else {
      const auto* list = std::get_if<NumberListField>(&key.field);
      const auto* array = node.as_array();
      if (!array) throw_wrong_type(key, describe(node), file);
      std::vector<double> numbers;
      for (const toml::node& item : *array) {
        const std::optional<double> v = number(item);
        if (!v) throw_wrong_type(key, "an array holding " + describe(item), file);
        numbers.push_back(*v);
      }
      config.**list = std::move(numbers);
    }
  }
  return config;
}

}  // namespace selfalign::detail
