#pragma once
// Internal: the field-level rules every two-column CSV reader of selfalign shares (acceleration
// samples, friction fields): C-locale numbers filling the whole field, an optional header line
// whose first field does not begin like a number, blanks trimmed.

#include <cctype>
#include <charconv>

#include "../double_chars.hpp"
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

namespace selfalign::detail {

enum class CsvField { number, out_of_range, text };

/// One CSV field as a double: a number, a number beyond the range of a double (1e400), or text.
inline CsvField parse_csv_double(const std::string& text, double& out) {
  std::string_view v(text);
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  if (v.empty()) return CsvField::text;
  const auto [end, ec] = detail::double_from_chars(v.data(), v.data() + v.size(), out);
  if (end != v.data() + v.size()) return CsvField::text;
  if (ec == std::errc::result_out_of_range) return CsvField::out_of_range;
  return ec == std::errc{} ? CsvField::number : CsvField::text;
}

/// A header names its columns: its first field does not begin like a number.
inline bool looks_like_csv_header(const std::string& line) {
  const char c = line.empty() ? ' ' : line.front();
  return !(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.');
}

/// The text without leading and trailing blanks (spaces, tabs, carriage returns).
inline std::string trim_csv(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/// The two fields of an "a,b" row, trimmed (text for a row without a comma).
inline std::pair<CsvField, CsvField> parse_csv_pair(const std::string& line, double& a,
                                                    double& b) {
  const auto comma = line.find(',');
  if (comma == std::string::npos) return {CsvField::text, CsvField::text};
  return {parse_csv_double(trim_csv(line.substr(0, comma)), a),
          parse_csv_double(trim_csv(line.substr(comma + 1)), b)};
}

/// Reads the "a,b" rows of a two-column CSV stream: surrounding blanks trimmed, blank lines and
/// '#' comments skipped, one leading header line allowed. Calls row(number, a, b) for each data
/// row (number: its 1-based line), and bad(number, line, out_of_range) for a row that is not two
/// numbers (out_of_range: a number beyond a double); `bad` must throw.
template <class Row, class Bad>
void read_csv_pairs(std::istream& in, Row&& row, Bad&& bad) {
  std::string line;
  int number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    line = trim_csv(line);
    if (line.empty() || line[0] == '#') continue;
    double a = 0, b = 0;
    const auto [fa, fb] = parse_csv_pair(line, a, b);
    if (fa != CsvField::number || fb != CsvField::number) {
      if (header_allowed && looks_like_csv_header(line)) {  // one leading header line
        header_allowed = false;
        continue;
      }
      bad(number, line, fa == CsvField::out_of_range || fb == CsvField::out_of_range);
    }
    header_allowed = false;
    row(number, a, b);
  }
}

}  // namespace selfalign::detail
