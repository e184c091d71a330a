#include "document_depth.hpp"

#include <vector>

namespace selfalign::detail {
namespace {

// The index of the quote closing the TOML string that opens at s[i] ('"' or '\'', single or
// triple), or of the line break ending an unterminated single-line string, or s.size() - 1.
std::size_t skip_toml_string(std::string_view s, std::size_t i) {
  const char quote = s[i];
  const bool escapes = quote == '"';
  const std::string_view triple = quote == '"' ? std::string_view("\"\"\"") : "'''";
  if (s.substr(i, 3) == triple) {
    for (std::size_t j = i + 3; j < s.size(); ++j) {
      if (escapes && s[j] == '\\') {
        ++j;
        continue;
      }
      if (s.substr(j, 3) == triple) {
        j += 3;
        while (j < s.size() && s[j] == quote) ++j;  // up to two quotes end the content
        return j - 1;
      }
    }
    return s.size() - 1;
  }
  for (std::size_t j = i + 1; j < s.size(); ++j) {
    if (escapes && s[j] == '\\') ++j;
    else if (s[j] == quote) return j;
    else if (s[j] == '\n') return j - 1;  // unterminated: the line break is read again
  }
  return s.size() - 1;
}

}  // namespace

std::size_t json_too_deep_at(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return text.size();
}

std::size_t toml_too_deep_at(std::string_view s, int max_depth) {
  // An open array or inline table: its depth, and (inline tables) the depth of the table that
  // holds the value being read (the table's own, plus the dots of the value's key).
  struct Open {
    char kind;  // '[' or '{'
    int depth;
    int value_table = 0;
  };
  std::vector<Open> open;
  int section = 1;      // depth of the table the current header opened (1: the root)
  int top_table = 1;    // depth of the table holding the current top-level value
  bool in_key = true;   // reading a key (up to '='), else a value
  int dots = 0;         // dots of the key being read
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '"' || c == '\'') {
      i = skip_toml_string(s, i);
      continue;
    }
    if (c == '#') {
      while (i + 1 < s.size() && s[i + 1] != '\n') ++i;
      continue;
    }
    if (c == '\n') {
      if (open.empty()) {  // a top-level value ends with its line
        in_key = true;
        dots = 0;
      }
      continue;
    }
    const int key_table = open.empty() ? section : open.back().depth;
    if (in_key) {
      if (c == '.') {
        if (key_table + ++dots > max_depth) return i;  // the tables a dotted key makes
      } else if (c == '=') {
        in_key = false;
        if (open.empty()) top_table = section + dots;
        else open.back().value_table = open.back().depth + dots;
      } else if (c == '[' && open.empty()) {  // a header: [a.b] or [[a.b]]
        const bool array = i + 1 < s.size() && s[i + 1] == '[';
        const std::size_t start = i;
        int header_dots = 0;
        for (i += array ? 2 : 1; i < s.size() && s[i] != ']' && s[i] != '\n'; ++i) {
          if (s[i] == '"' || s[i] == '\'') i = skip_toml_string(s, i);
          else if (s[i] == '.') ++header_dots;
        }
        if (array && i + 1 < s.size() && s[i + 1] == ']') ++i;
        section = 1 + header_dots + 1 + (array ? 1 : 0);
        if (section > max_depth) return start;
      } else if (c == '}' && !open.empty()) {  // an empty inline table
        open.pop_back();
        in_key = false;
      }
      continue;
    }
    if (c == '[' || c == '{') {
      const int holder = open.empty()             ? top_table
                         : open.back().kind == '[' ? open.back().depth
                                                   : open.back().value_table;
      if (holder + 1 > max_depth) return i;
      open.push_back({c, holder + 1});
      if (c == '{') {
        in_key = true;
        dots = 0;
      }
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
    } else if (c == ',' && !open.empty() && open.back().kind == '{') {
      in_key = true;
      dots = 0;
    }
  }
  return s.size();
}

}  // namespace selfalign::detail
