#include "selfalign/io/document.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "document_depth.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/run_files.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

// "line L, column C" of the character at byte `index` of `text` (both from 1).
std::string place(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  const std::size_t line = 1 + static_cast<std::size_t>(
                                   std::count(text.begin(), text.begin() + index, '\n'));
  const std::size_t line_start = index == 0 ? std::string_view::npos : text.rfind('\n', index - 1);
  const std::size_t column = line_start == std::string_view::npos ? index + 1 : index - line_start;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

[[noreturn]] void too_deep(const DocumentKind& kind, const std::string& path,
                           const std::string& where) {
  throw InvalidParameter(kind.name, path,
                         "nests too deeply at " + where + ": at most " +
                             std::to_string(kind.max_depth) +
                             " levels of tables and arrays (the top level counts 1)");
}

// ---- JSON ------------------------------------------------------------------------------------

// Builds the tree as nlohmann's own DOM parser does, but refuses a container nested deeper
// than max_depth before reading into it (the parse stops there), and keeps where a syntax
// error or a number overflow happened (nlohmann's exceptions give no position for the latter).
class Builder final : public nlohmann::json_sax<json> {
 public:
  explicit Builder(int max_depth) : max_depth_(max_depth) {}

  json root;
  bool nests_too_deeply = false;
  std::size_t error_position = 0;  // characters read when the parser failed
  std::string error;               // the parser's message

  bool null() override { return add(nullptr); }
  bool boolean(bool v) override { return add(v); }
  bool number_integer(number_integer_t v) override { return add(v); }
  bool number_unsigned(number_unsigned_t v) override { return add(v); }
  bool number_float(number_float_t v, const string_t&) override { return add(v); }
  bool string(string_t& v) override { return add(std::move(v)); }
  bool binary(binary_t& v) override { return add(json::binary(std::move(v))); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool key(string_t& k) override {
    key_ = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& e) override {
    error_position = position;
    error = e.what();
    return false;
  }

 private:
  // Only the innermost open container grows, so the pointers to the outer ones stay valid.
  json* place_value(json v) {
    if (open_.empty()) {
      root = std::move(v);
      return &root;
    }
    json& parent = *open_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    json& slot = parent[key_];  // a repeated key: the last value wins, as nlohmann's parser
    slot = std::move(v);
    return &slot;
  }
  bool add(json v) {
    place_value(std::move(v));
    return true;
  }
  bool open(json container) {
    if (static_cast<int>(open_.size()) >= max_depth_) {
      nests_too_deeply = true;
      return false;
    }
    open_.push_back(place_value(std::move(container)));
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }

  int max_depth_;
  std::vector<json*> open_;
  std::string key_;
};

// nlohmann's message without its internals: "[json.exception.parse_error.101] parse error at
// line 1, column 2: syntax error while parsing value - invalid literal; last read: 'x'" ->
// "invalid literal; last read: 'x'".
std::string clean_json_message(std::string message) {
  if (message.rfind("[json.exception", 0) == 0)
    if (const auto close = message.find("] "); close != std::string::npos)
      message.erase(0, close + 2);
  if (message.rfind("parse error", 0) == 0)
    if (const auto colon = message.find(": "); colon != std::string::npos)
      message.erase(0, colon + 2);
  if (message.rfind("syntax error while parsing", 0) == 0)
    if (const auto dash = message.find(" - "); dash != std::string::npos)
      message.erase(0, dash + 3);
  return message;
}

// A parser's message as one short printable line: bytes outside printable ASCII (an echoed
// invalid byte, a line break) shown as \xNN, at most 120 characters (it may echo a long token).
std::string printable(const std::string& message) {
  constexpr std::size_t kMaxShown = 120;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string line;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) line += c;
    else line += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    if (line.size() > kMaxShown) return line.substr(0, kMaxShown) + "...";
  }
  return line;
}

json parse_json(const std::string& text, const DocumentKind& kind, const std::string& path) {
  Builder builder(kind.max_depth);
  if (json::sax_parse(text, &builder)) return std::move(builder.root);
  if (builder.nests_too_deeply)
    too_deep(kind, path, place(text, detail::json_too_deep_at(text, kind.max_depth)));
  throw InvalidParameter(kind.name, path,
                         "is not valid JSON at " +
                             place(text, builder.error_position == 0
                                             ? 0
                                             : builder.error_position - 1) +
                             ": " + printable(clean_json_message(builder.error)));
}

// ---- TOML ------------------------------------------------------------------------------------

// `node` at nesting level `depth` (the top-level table is 1). toml_too_deep_at bounded the
// document's depth before toml++ read it (at most twice the limit), so this recursion is
// bounded; the exact limit is checked here, where arrays of tables are known.
json from_toml(const toml::node& node, int depth, const DocumentKind& kind,
               const std::string& path) {
  if ((node.is_table() || node.is_array()) && depth > kind.max_depth) {
    const auto& at = node.source().begin;
    too_deep(kind, path,
             "line " + std::to_string(at.line) + ", column " + std::to_string(at.column));
  }
  if (const auto* t = node.as_table()) {
    json o = json::object();
    for (const auto& [k, v] : *t) o[std::string(k.str())] = from_toml(v, depth + 1, kind, path);
    return o;
  }
  if (const auto* a = node.as_array()) {
    json o = json::array();
    for (const auto& v : *a) o.push_back(from_toml(v, depth + 1, kind, path));
    return o;
  }
  if (const auto* v = node.as_floating_point()) return v->get();
  if (const auto* v = node.as_integer()) return v->get();
  if (const auto* v = node.as_string()) return v->get();
  if (const auto* v = node.as_boolean()) return v->get();
  std::ostringstream text;  // date, time, date-time
  node.visit([&text](const auto& value) { text << value; });
  return text.str();
}

json parse_toml(const std::string& text, const DocumentKind& kind, const std::string& path) {
  // toml++ parses recursively and frees its tree recursively: nothing much deeper than the
  // kind allows reaches it (a dotted key of 1e5 parts overflowed the stack).
  if (const std::size_t at = detail::toml_too_deep_at(text, kind.max_depth); at < text.size())
    too_deep(kind, path, place(text, at));
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw InvalidParameter(kind.name, path,
                           "is not valid TOML at line " + std::to_string(at.line) +
                               ", column " + std::to_string(at.column) + ": " +
                               printable(std::string(e.description())));
  }
  return from_toml(doc, 1, kind, path);
}

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

json read_document(const std::string& path, const DocumentKind& kind) {
  if (path.empty()) throw InvalidParameter(kind.name, "\"\"", "must name a .json or .toml file");
  const bool is_json = ends_with(path, ".json");
  if (!is_json && !ends_with(path, ".toml"))
    throw InvalidParameter(kind.name, path, "must end in .json or .toml");
  require_input_file(kind.name, path, kind.flag, kMaxDocumentBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InvalidParameter(kind.name, path, std::string("cannot be read: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InvalidParameter(kind.name, path, "cannot be read");
  return is_json ? parse_json(text.str(), kind, path) : parse_toml(text.str(), kind, path);
}

std::string document_value_text(const json& value) {
  constexpr std::size_t kMaxShown = 60;  // keep the message one short line
  std::string text = value.dump();
  return text.size() > kMaxShown ? text.substr(0, kMaxShown) + "..." : text;
}

}  // namespace selfalign
