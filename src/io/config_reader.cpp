// The one config reader: a document's values checked against a key table, command-line text
// parsed by the same table, values converted to model units by the table's dimensions.

#include "selfalign/io/config_reader.hpp"

#include "../double_chars.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "selfalign/error.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/spelling.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

constexpr std::size_t kKeysListed = 7;  // an unknown-key message names a section's first keys

std::string where(const std::string& file) { return file.empty() ? "" : " (in " + file + ")"; }

// Whether table `sub` lies under `section` ("table.x" under "table"; every table under "").
bool is_under(std::string_view sub, std::string_view section) {
  if (section.empty()) return !sub.empty();
  return sub.size() > section.size() && sub.starts_with(section) && sub[section.size()] == '.';
}

}  // namespace

bool KeyTable::has_section(std::string_view section) const {
  for (const KeySpec& k : keys)
    if (k.section == section || is_under(k.section, section)) return true;
  return false;
}

namespace {

// The names a user may write in `section`: its keys, then the tables directly under it.
std::vector<std::string> names_in(const KeyTable& table, std::string_view section) {
  std::vector<std::string> names;
  const auto add = [&names](std::string name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
  };
  for (const KeySpec& k : table.keys)
    if (k.section == section) add(std::string(k.name));
  for (const KeySpec& k : table.keys) {
    if (!is_under(k.section, section)) continue;
    const std::string_view rest = k.section.substr(section.empty() ? 0 : section.size() + 1);
    add(std::string(rest.substr(0, rest.find('.'))));
  }
  return names;
}

std::string type_text(const KeySpec& key) {
  switch (key.type) {
    case ValueType::text: return "a string";
    case ValueType::number: return "a number";
    case ValueType::numbers:
      return key.shape.empty() ? "an array of numbers" : std::string(key.shape) + " (numbers)";
    case ValueType::rows:
      return "an array of " + (key.shape.empty() ? std::string("arrays of numbers")
                                                 : std::string(key.shape) + " (numbers)");
  }
  return "";
}

std::string count_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " value" : " values"); }

// The numbers of an array, or nullopt when `node` is not an array of numbers.
std::optional<std::vector<double>> numbers_of(const json& node) {
  if (!node.is_array()) return std::nullopt;
  std::vector<double> out;
  out.reserve(node.size());
  for (const json& v : node) {
    if (!v.is_number()) return std::nullopt;
    out.push_back(v.get<double>());  // TOML nan and inf included
  }
  return out;
}

void require_length(const KeySpec& key, std::string_view section, const std::vector<double>& v,
                    const std::string& file) {
  if (!key.components.empty() && v.size() != key.components.size())
    throw InvalidParameter(qualified_key(section, key.name), count_text(v.size()),
                           "must be " + std::string(key.shape) + where(file));
}

ConfigValue value_of(const KeySpec& key, const json& node, const std::string& file) {
  const auto wrong = [&] {
    return InvalidParameter(qualified_key(key.section, key.name), document_value_text(node),
                            "must be " + type_text(key) + where(file));
  };
  switch (key.type) {
    case ValueType::text:
      if (!node.is_string()) throw wrong();
      return node.get<std::string>();
    case ValueType::number:
      if (!node.is_number()) throw wrong();
      return node.get<double>();
    case ValueType::numbers: {
      auto v = numbers_of(node);
      if (!v) throw wrong();
      require_length(key, key.section, *v, file);
      return std::move(*v);
    }
    case ValueType::rows: {
      if (!node.is_array()) throw wrong();
      std::vector<std::vector<double>> rows;
      for (const json& row : node) {
        auto v = numbers_of(row);
        if (!v) throw wrong();
        require_length(key, key.section, *v, file);
        rows.push_back(std::move(*v));
      }
      return rows;
    }
  }
  throw wrong();
}

void read_table(const json& node, std::string_view section, const KeyTable& table,
                const std::string& file, std::vector<ConfigValues::Entry>& entries,
                std::vector<std::string>& sections) {
  for (const auto& [name, value] : node.items()) {
    if (const KeySpec* key = table.find(section, name)) {
      entries.push_back({key, value_of(*key, value, file)});
      continue;
    }
    const std::string sub = qualified_key(section, name);
    if (table.has_section(sub)) {
      if (!value.is_object())
        throw InvalidParameter(sub, document_value_text(value), "must be a table" + where(file));
      sections.push_back(sub);
      read_table(value, sub, table, file, entries, sections);
      continue;
    }
    throw InvalidParameter("config key", sub,
                           unknown_key_message(table, section, name) + where(file));
  }
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1));
}

// C-locale number, whole text (surrounding blanks and a leading '+' allowed); "nan" and "inf"
// parse.
bool parse_c_number(std::string_view text, double& out) {
  std::string t = trim(text);
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  if (t.empty()) return false;
  const auto [end, ec] = detail::double_from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc{} && end == t.data() + t.size();
}

}  // namespace

const KeySpec* KeyTable::find(std::string_view section, std::string_view name) const {
  for (const KeySpec& k : keys)
    if (k.section == section && k.name == name) return &k;
  return nullptr;
}

std::string qualified_key(std::string_view section, std::string_view name) {
  std::string s(section);
  if (!s.empty()) s += '.';
  s += name;
  return s;
}

std::string unknown_key_message(const KeyTable& table, std::string_view section,
                                std::string_view name) {
  const std::vector<std::string> names = names_in(table, section);
  const std::string of = section.empty() ? "" : " of [" + std::string(section) + "]";
  std::string message = "unknown key" + of;
  if (const std::string best = closest_name(name, names); !best.empty())
    message += " (did you mean " + best + "?)";
  message += "; keys" + of + ": ";
  for (std::size_t i = 0; i < names.size() && i < kKeysListed; ++i) {
    if (i > 0) message += ", ";
    message += names[i];
  }
  message += names.size() > kKeysListed ? ", ..., every one in " : "; every one in ";
  return message + std::string(table.documented_in);
}

const ConfigValue* ConfigValues::find(std::string_view section, std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.key->section == section && e.key->name == name) return &e.value;
  return nullptr;
}

bool ConfigValues::has_section(std::string_view section) const {
  return std::find(sections_.begin(), sections_.end(), section) != sections_.end();
}

ConfigValues read_config_values(const json& doc, const KeyTable& table, const std::string& file) {
  ConfigValues values;
  values.table_ = &table;
  values.file_ = file;
  if (!doc.is_object())
    throw InvalidParameter("config file", file, "must contain one table of keys");
  read_table(doc, "", table, file, values.entries_, values.sections_);
  return values;
}

ConfigValue parse_config_value(const KeySpec& key, const std::string& text) {
  const std::string name = qualified_key(key.section, key.name);
  switch (key.type) {
    case ValueType::text: return text;
    case ValueType::number: {
      double v = 0;
      if (!parse_c_number(text, v)) throw InvalidParameter(name, text, "must be a number");
      return v;
    }
    case ValueType::numbers: {
      std::string list = trim(text);
      if (list.size() >= 2 && list.front() == '[' && list.back() == ']')
        list = list.substr(1, list.size() - 2);
      std::vector<double> values;
      if (!trim(list).empty()) {
        for (std::size_t begin = 0;;) {
          const std::size_t comma = list.find(',', begin);
          double v = 0;
          if (!parse_c_number(std::string_view(list).substr(begin, comma - begin), v))
            throw InvalidParameter(name, text, "must be a comma-separated list of numbers");
          values.push_back(v);
          if (comma == std::string::npos) break;
          begin = comma + 1;
        }
      }
      require_length(key, key.section, values, "");
      return values;
    }
    case ValueType::rows: {
      const json node = json::parse(text, nullptr, /*allow_exceptions=*/false);
      if (node.is_discarded())
        throw InvalidParameter(name, text, "must be " + type_text(key) + ", as JSON");
      return value_of(key, node, "");
    }
  }
  throw std::logic_error("parse_config_value: unknown value type");
}

json to_json(const ConfigValue& value) {
  return std::visit([](const auto& v) { return json(v); }, value);
}

// ---- ConfigSection ----

const KeySpec& ConfigSection::spec(std::string_view k, ValueType type) const {
  const KeySpec* found = values_->table().find(section_, k);
  if (!found || found->type != type)
    throw std::logic_error("config key " + key(k) + " is not in the key table with this type");
  return *found;
}

const ConfigValue* ConfigSection::value(std::string_view k) const {
  return values_->find(section_, k);
}

bool ConfigSection::has(std::string_view k) const { return value(k) != nullptr; }

std::vector<double> ConfigSection::converted(const KeySpec& key, std::vector<double> v) const {
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = units_(key.components.empty() ? key.dimension : key.components[i], v[i]);
  return v;
}

void ConfigSection::note(const KeySpec& key, std::vector<double> values) const {
  if (reads_) reads_->push_back({&key, std::move(values)});
}

double ConfigSection::number(std::string_view k, double fallback) const {
  const KeySpec& key = spec(k, ValueType::number);
  const ConfigValue* v = value(k);
  const double given = v ? std::get<double>(*v) : fallback;
  note(key, {given});
  return units_(key.dimension, given);
}

double ConfigSection::required(std::string_view k) const {
  const KeySpec& key = spec(k, ValueType::number);
  const ConfigValue* v = value(k);
  if (!v) throw InvalidParameter(this->key(k), "missing", "is required");
  note(key, {std::get<double>(*v)});
  return units_(key.dimension, std::get<double>(*v));
}

int ConfigSection::integer(std::string_view k, int fallback, int lo, int hi) const {
  const double v = number(k, fallback);
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    throw InvalidParameter(key(k), v,
                           "must be a whole number in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "]");
  return static_cast<int>(v);
}

std::string ConfigSection::text(std::string_view k, const std::string& fallback) const {
  note(spec(k, ValueType::text), {});
  const ConfigValue* v = value(k);
  return v ? std::get<std::string>(*v) : fallback;
}

std::vector<double> ConfigSection::list(std::string_view k, std::vector<double> fallback) const {
  const KeySpec& key = spec(k, ValueType::numbers);
  const ConfigValue* v = value(k);
  std::vector<double> given = v ? std::get<std::vector<double>>(*v) : std::move(fallback);
  note(key, given);
  return converted(key, std::move(given));
}

std::vector<std::vector<double>> ConfigSection::rows(std::string_view k) const {
  const KeySpec& key = spec(k, ValueType::rows);
  const ConfigValue* v = value(k);
  note(key, {});
  std::vector<std::vector<double>> out;
  if (v)
    for (const auto& row : std::get<std::vector<std::vector<double>>>(*v))
      out.push_back(converted(key, row));
  return out;
}

}  // namespace selfalign
