#include "selfalign/io/measured_motion.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "csv_fields.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/run_files.hpp"

namespace selfalign {

namespace {

// The quantities a column can hold, in MeasuredMotion's order.
enum Quantity { kTime, kX, kY, kAngle, kTablePosition, kTableAcceleration, kQuantities };
// Each quantity's kind of unit, for its units' SI factors (named apart from selfalign::Dimension,
// the model's scaling, which a unity build may see beside it).
enum UnitKind { kSeconds, kMetres, kRadians, kMetresPerSecondSquared };

constexpr std::array<UnitKind, kQuantities> kUnitKind{kSeconds, kMetres, kMetres, kRadians,
                                                        kMetres, kMetresPerSecondSquared};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::optional<Quantity> quantity_of(const std::string& name) {
  if (name == "t" || name == "time") return kTime;
  if (name == "x" || name == "position") return kX;
  if (name == "y") return kY;
  if (name == "angle" || name == "theta") return kAngle;
  if (name == "table_x" || name == "table" || name == "table_position") return kTablePosition;
  if (name == "table_a" || name == "table_acceleration") return kTableAcceleration;
  return std::nullopt;
}

// The factor from `unit` to SI for dimension d, or none.
std::optional<double> unit_factor(UnitKind d, const std::string& unit) {
  const double pi = std::acos(-1.0);
  switch (d) {
    case kSeconds:
      if (unit == "s") return 1.0;
      if (unit == "ms") return 1e-3;
      if (unit == "us" || unit == "\xC2\xB5s") return 1e-6;
      if (unit == "min") return 60.0;
      return std::nullopt;
    case kMetres:
      if (unit == "m") return 1.0;
      if (unit == "cm") return 1e-2;
      if (unit == "mm") return 1e-3;
      if (unit == "um" || unit == "\xC2\xB5m") return 1e-6;
      return std::nullopt;
    case kRadians:
      if (unit == "rad") return 1.0;
      if (unit == "deg" || unit == "\xC2\xB0") return pi / 180;
      return std::nullopt;
    case kMetresPerSecondSquared:
      if (unit == "m/s^2" || unit == "m/s2" || unit == "m/s\xC2\xB2") return 1.0;
      if (unit == "mm/s^2" || unit == "mm/s2" || unit == "mm/s\xC2\xB2") return 1e-3;
      if (unit == "g") return 9.80665;
      return std::nullopt;
  }
  return std::nullopt;
}

const char* units_allowed(UnitKind d) {
  switch (d) {
    case kSeconds: return "must be one of: s, ms, us, min";
    case kMetres: return "must be one of: m, cm, mm, um";
    case kRadians: return "must be one of: rad, deg";
    case kMetresPerSecondSquared: return "must be one of: m/s^2, mm/s^2, g";
  }
  return "";
}

// A header field split into its name and unit: "x [mm]", "x (mm)", "x/mm", "x_mm" (the last
// only where the part after '_' is a unit of the name's quantity), or a bare name.
struct Column {
  std::string name, unit;
};

Column split_column(const std::string& field) {
  std::string f = lower(detail::trim_csv(field));
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto o = f.find(open);
    if (o != std::string::npos && !f.empty() && f.back() == close)
      return {detail::trim_csv(f.substr(0, o)), detail::trim_csv(f.substr(o + 1, f.size() - o - 2))};
  }
  if (const auto s = f.find('/'); s != std::string::npos && !quantity_of(f))
    return {detail::trim_csv(f.substr(0, s)), detail::trim_csv(f.substr(s + 1))};
  if (const auto u = f.rfind('_'); u != std::string::npos && !quantity_of(f)) {
    const Column c{f.substr(0, u), f.substr(u + 1)};
    if (const auto q = quantity_of(c.name); q && unit_factor(kUnitKind[*q], c.unit)) return c;
  }
  return {f, ""};
}

// The header's separator: a comma, semicolon or tab if it has one, else runs of spaces (0).
char separator_of(const std::string& header) {
  for (const char c : {',', ';', '\t'})
    if (header.find(c) != std::string::npos) return c;
  return 0;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  if (sep == 0) {
    std::size_t i = 0;
    while (true) {
      i = line.find_first_not_of(" \t\r", i);
      if (i == std::string::npos) break;
      const auto e = line.find_first_of(" \t\r", i);
      out.push_back(line.substr(i, e == std::string::npos ? std::string::npos : e - i));
      if (e == std::string::npos) break;
      i = e;
    }
    return out;
  }
  std::size_t b = 0;
  while (true) {
    const auto e = line.find(sep, b);
    out.push_back(detail::trim_csv(line.substr(b, e == std::string::npos ? std::string::npos : e - b)));
    if (e == std::string::npos) break;
    b = e + 1;
  }
  return out;
}

bool missing(const std::string& field) {
  const std::string f = lower(field);
  return f.empty() || f == "nan" || f == "na" || f == "n/a" || f == "-" || f == "null";
}

bool blank_or_comment(const std::string& line) {
  const std::string t = detail::trim_csv(line);
  return t.empty() || t.front() == '#';
}

}  // namespace

std::map<std::string, std::string> parse_measured_units(std::istream& in,
                                                        const std::string& source) {
  std::map<std::string, std::string> units;
  std::string text;
  long long number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (blank_or_comment(text)) continue;
    const auto eq = text.find('=');
    const std::string name = eq == std::string::npos ? "" : lower(detail::trim_csv(text.substr(0, eq)));
    std::string unit = eq == std::string::npos ? "" : lower(detail::trim_csv(text.substr(eq + 1)));
    if (unit.size() >= 2 && (unit.front() == '"' || unit.front() == '\'') && unit.back() == unit.front())
      unit = unit.substr(1, unit.size() - 2);
    if (name.empty() || unit.empty())
      throw InvalidParameter(source + ":" + std::to_string(number), "'" + detail::trim_csv(text) + "'",
                             "must be 'column = unit' (e.g. x = mm)");
    if (units.count(name))
      throw InvalidParameter(source + ":" + std::to_string(number), name,
                             "gives a unit for a column a line before it already does");
    units[name] = unit;
  }
  return units;
}

MeasuredMotion parse_measured_motion(std::istream& in, const std::string& source,
                                     const std::map<std::string, std::string>& units,
                                     const std::string& units_source) {
  MeasuredMotion out;
  out.source = source;
  const auto where = [&](long long n) { return source + ":" + std::to_string(n); };
  std::string text;
  long long number = 0;
  // the header: the first line with a time column; title lines above it
  std::vector<std::optional<Quantity>> roles;
  std::array<double, kQuantities> factor{};
  std::array<bool, kQuantities> present{};
  char sep = 0;
  std::size_t width = 0;
  while (std::getline(in, text)) {
    ++number;
    if (blank_or_comment(text)) continue;
    if (!detail::looks_like_csv_header(detail::trim_csv(text)))
      throw InvalidParameter(where(number), "'" + detail::trim_csv(text) + "'",
                             "data before a header naming a time column (t or time)");
    sep = separator_of(text);
    const std::vector<std::string> fields = split(text, sep);
    std::vector<Column> columns;
    for (const std::string& f : fields) columns.push_back(split_column(f));
    const auto side = [&](const Column& c) {
      const auto u = units.find(c.name);
      return u == units.end() ? std::string() : u->second;
    };
    if (std::none_of(columns.begin(), columns.end(),
                     [](const Column& c) { return quantity_of(c.name) == kTime; })) {
      out.title += (out.title.empty() ? "" : "; ") + detail::trim_csv(text);
      continue;
    }
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const auto q = quantity_of(columns[i].name);
      roles.push_back(q);
      if (!q) {
        out.ignored_columns.push_back(detail::trim_csv(fields[i]));
        continue;
      }
      if (present[*q])
        throw InvalidParameter(where(number) + " column " + std::to_string(i + 1),
                               "'" + detail::trim_csv(fields[i]) + "'",
                               "names a quantity a column before it already holds");
      present[*q] = true;
      if (const std::string u = side(columns[i]); !u.empty()) {
        if (!columns[i].unit.empty() && columns[i].unit != u)
          throw InvalidParameter(units_source + " " + columns[i].name, u,
                                 "disagrees with the header's unit '" + columns[i].unit + "' (" +
                                     where(number) + ")");
        columns[i].unit = u;
      }
      const auto f = columns[i].unit.empty() ? std::optional<double>(1.0)
                                             : unit_factor(kUnitKind[*q], columns[i].unit);
      if (!f)
        throw InvalidParameter(where(number) + " column '" + columns[i].name + "' unit",
                               columns[i].unit, units_allowed(kUnitKind[*q]));
      factor[*q] = *f;
    }
    for (const auto& [name, unit] : units)
      if (std::none_of(columns.begin(), columns.end(),
                       [&name = name](const Column& c) { return c.name == name; }))
        throw InvalidParameter(units_source + " " + name, unit,
                               "names a column the header of " + source + " does not have");
    width = fields.size();
    break;
  }
  if (roles.empty())
    throw InvalidParameter(source, "no time column",
                           "needs a header line naming a time column (t or time)");
  if (!present[kX])
    throw InvalidParameter(source + " header", "no x column",
                           "needs the part's position: a column x (or position)");
  std::array<std::vector<double>*, kQuantities> target{&out.t, &out.x, &out.y, &out.angle,
                                                       &out.table_position,
                                                       &out.table_acceleration};
  while (std::getline(in, text)) {
    ++number;
    if (blank_or_comment(text)) continue;
    std::vector<std::string> fields = split(text, sep);
    while (fields.size() > width && fields.back().empty()) fields.pop_back();
    if (fields.size() > width)
      throw InvalidParameter(where(number), "'" + detail::trim_csv(text) + "'",
                             "has " + std::to_string(fields.size()) + " fields; the header has " +
                                 std::to_string(width));
    std::array<double, kQuantities> row{};
    bool complete = fields.size() == width;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (!roles[i]) continue;
      if (missing(fields[i])) {
        complete = false;
        continue;
      }
      double v = 0;
      const detail::CsvField kind = detail::parse_csv_double(fields[i], v);
      if (kind != detail::CsvField::number || !std::isfinite(v))
        throw InvalidParameter(where(number) + " column " + std::to_string(i + 1),
                               "'" + fields[i] + "'",
                               "must be a finite number, or empty / nan / NA / - for missing");
      row[*roles[i]] = v * factor[*roles[i]];
    }
    if (!complete) {
      ++out.skipped;
      continue;
    }
    if (!out.t.empty() && !(row[kTime] > out.t.back()))
      throw InvalidParameter(where(number) + " time", row[kTime],
                             "must be > the previous time " + format_number(out.t.back()) +
                                 " s at line " + std::to_string(out.line.back()) +
                                 " (time strictly increasing)");
    for (int q = 0; q < kQuantities; ++q)
      if (present[static_cast<std::size_t>(q)])
        target[static_cast<std::size_t>(q)]->push_back(row[static_cast<std::size_t>(q)]);
    out.line.push_back(number);
  }
  if (out.t.empty())
    throw InvalidParameter(source, std::to_string(out.skipped) + " rows skipped",
                           "needs at least one complete row under its header");
  return out;
}

MeasuredMotion read_measured_motion(const std::string& path) {
  constexpr std::uintmax_t kMaxBytes = 512u << 20;
  require_input_file("data", path, "data", kMaxBytes);
  std::map<std::string, std::string> units;
  const std::string side = path + ".units";
  if (std::ifstream u(side); u) {
    require_input_file("data units", side, "data", 1u << 20);
    units = parse_measured_units(u, side);
  }
  std::ifstream in(path);
  if (!in) throw InvalidParameter("data", path, "must be a readable CSV file");
  return parse_measured_motion(in, path, units, side);
}

}  // namespace selfalign
