#pragma once
/// \file config_reader.hpp
/// The one config reader (issue 21, item 6): a key table describes every key of a config —
/// its section, name, type, dimension, unit and meaning — and drives reading the config from a
/// document (read_config_values), setting a key from command-line text (parse_config_value),
/// the unknown-key message with its "did you mean" (unknown_key_message) and the conversion of
/// a value to model units (ConfigSection). The 1-D config (simulate_config.hpp: one flat
/// table, section "") and the planar config (planar_config.hpp: sections [scales], [table.x],
/// [part], ...) are both key tables read by this reader.
///
/// Messages name a key as the file spells it, with its section ("part.radius", "run.step"),
/// and end with the file they came from: `invalid part.colour = unknown key: of [part] (did you
/// mean color?); keys of [part]: mass, inertia, ..., every one in docs/planar.md (in p.toml)`.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "selfalign/io/unit_system.hpp"

namespace selfalign {

/// The type of a key's value.
enum class ValueType {
  text,     ///< a string
  number,   ///< a number (TOML nan and inf included: ranges are the model's to check)
  numbers,  ///< an array of numbers
  rows      ///< an array of arrays of numbers (e.g. [stop] entries)
};

/// What a key is to the model: a parameter (a number the model depends on: the parameter view
/// lists it) or a setting (a solver, output, unit or discretisation choice).
enum class KeyRole { parameter, setting };

/// One key of a config.
struct KeySpec {
  std::string_view section;  ///< "" at the top level; "scales", "table.x", ... (dotted: nested)
  std::string_view name;     ///< the key in its section, e.g. "radius"
  ValueType type;
  /// How a number (each element of an array) converts to model units (Sect. 3.2); none: as
  /// given (angles [rad], ratios) or converted by the model's builder (the planar inertia).
  Dimension dimension = Dimension::none;
  /// For an array (each row of `rows`) of a fixed length whose elements differ in dimension:
  /// one dimension per element (a pose [x, y, angle]: length, length, none); empty: any
  /// length, every element of `dimension`.
  std::span<const Dimension> components = {};
  std::string_view shape = {};  ///< the components named for messages, e.g. "[x, y, angle]"
  std::string_view unit = {};   ///< in SI runs, e.g. "[m]" (docs and help)
  std::string_view help = {};   ///< meaning, default, range
  KeyRole role = KeyRole::parameter;  ///< number keys: parameter or setting
};

/// A config's keys and where a user reads them.
struct KeyTable {
  std::span<const KeySpec> keys;
  std::string_view documented_in;  ///< e.g. "docs/planar.md"

  /// The key `name` of `section`, or nullptr.
  const KeySpec* find(std::string_view section, std::string_view name) const;
  /// Whether `section` ("table.x", "table", "" the top level) is a table of the config: some
  /// key lives in it or in a table under it.
  bool has_section(std::string_view section) const;
};

/// A value as read: one alternative per ValueType, in its order.
using ConfigValue =
    std::variant<std::string, double, std::vector<double>, std::vector<std::vector<double>>>;

/// "section.name", or name at the top level: how messages name a key.
std::string qualified_key(std::string_view section, std::string_view name);

/// The message for a key unknown to `table` in `section`: the closest key of the section
/// when it looks like a typo, and its first keys: "unknown key (did you mean width?); keys:
/// units, method, ..., every one in docs/config.md".
std::string unknown_key_message(const KeyTable& table, std::string_view section,
                                std::string_view name);

/// The values of a document, each checked against its key in the table (known, of its type,
/// of its length). Values are as written (file units), in the document's order.
class ConfigValues {
 public:
  struct Entry {
    const KeySpec* key;
    ConfigValue value;
  };
  /// The value of `key`'s entry, or nullptr when the document does not set it.
  const ConfigValue* find(std::string_view section, std::string_view name) const;
  /// Whether the document has the table `section` (possibly empty).
  bool has_section(std::string_view section) const;
  const std::vector<Entry>& entries() const noexcept { return entries_; }
  const std::string& file() const noexcept { return file_; }
  const KeyTable& table() const noexcept { return *table_; }

 private:
  friend ConfigValues read_config_values(const nlohmann::json&, const KeyTable&,
                                         const std::string&);
  const KeyTable* table_ = nullptr;
  std::string file_;
  std::vector<Entry> entries_;
  std::vector<std::string> sections_;
};

/// Reads `doc` (a document's top-level table, read_document) against `table`: every key known
/// (in its section), every section a table, every value of its key's type and length. Throws
/// InvalidParameter naming the key as "section.name", ending "(in <file>)": ("config key",
/// "part.colour", unknown_key_message(...)), ("part.radius", "\"a\"", "must be a number"),
/// ("scales", "3", "must be a table"), ("field.centre", "1 value", "must be [x, y]").
/// `table` must outlive the result.
ConfigValues read_config_values(const nlohmann::json& doc, const KeyTable& table,
                                const std::string& file);

/// A key's value from command-line text: a number as C-locale text ("nan" and "inf" parse;
/// ranges are the model's to check); numbers comma-separated, optionally in brackets
/// ("0.3,0.2" or "[0.3, 0.2]"); rows as JSON ("[[0, 0, 0], [1, 0, 0]]"); text as given.
/// Throws InvalidParameter(qualified name, text, "must be ...") when the text is not of the
/// key's type or length.
ConfigValue parse_config_value(const KeySpec& key, const std::string& text);

/// A value as JSON (to set a key of a document before reading it).
nlohmann::json to_json(const ConfigValue& value);

/// One section of read values, converted to model units on access by each key's dimension
/// (InputUnits: the identity in dimensionless runs). Accessing a key the table does not have
/// in this section is a programming error (std::logic_error).
class ConfigSection {
 public:
  ConfigSection(const ConfigValues& values, std::string section, const InputUnits& units)
      : values_(&values), section_(std::move(section)), units_(units) {}

  const std::string& name() const noexcept { return section_; }
  /// "section.k": the key as messages name it.
  std::string key(std::string_view k) const { return qualified_key(section_, k); }
  bool has(std::string_view k) const;
  /// The number (fallback when unset, in file units), in model units.
  double number(std::string_view k, double fallback) const;
  /// The number, in model units; InvalidParameter(key, "missing", "is required") when unset.
  double required(std::string_view k) const;
  /// A whole number in [lo, hi] (fallback when unset); InvalidParameter otherwise.
  int integer(std::string_view k, int fallback, int lo, int hi) const;
  std::string text(std::string_view k, const std::string& fallback) const;
  /// The array (fallback when unset, in file units), each element in model units.
  std::vector<double> list(std::string_view k, std::vector<double> fallback = {}) const;
  /// The rows (empty when unset), each element in model units.
  std::vector<std::vector<double>> rows(std::string_view k) const;

  /// One key the section was asked for, with its numbers as the config gives them (file units;
  /// the fallback where the config does not set it): what the model read, for its parameter
  /// view and for the keys a config gives but nothing reads.
  struct Read {
    const KeySpec* key;
    std::vector<double> values;  ///< one value for a number key; none for text and rows
  };
  /// Records every access (number(), required(), integer(), list(), text(), rows()) into `log`
  /// from now on (nullptr: stop). `log` must outlive the reads.
  void record_reads(std::vector<Read>* log) noexcept { reads_ = log; }

 private:
  const KeySpec& spec(std::string_view k, ValueType type) const;
  const ConfigValue* value(std::string_view k) const;
  std::vector<double> converted(const KeySpec& key, std::vector<double> v) const;
  void note(const KeySpec& key, std::vector<double> values) const;
  const ConfigValues* values_;
  std::string section_;
  InputUnits units_;
  std::vector<Read>* reads_ = nullptr;
};

}  // namespace selfalign
