#include "selfalign/error.hpp"

#include "double_chars.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace selfalign {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  auto [end, ec] = detail::double_to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

namespace {
// what() is one short line: a long value is shown by its head and tail (a 10 MB value echoed
// back helps nobody; the tail keeps a path's file name), and line breaks become spaces.
std::string one_line(std::string text, std::size_t max_size) {
  if (text.size() > max_size)
    text = text.substr(0, max_size / 2) + "..." + text.substr(text.size() - max_size / 2) + " (" +
           std::to_string(text.size()) + " characters)";
  for (char& c : text)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  return text;
}
constexpr std::size_t kShownValue = 100;
constexpr std::size_t kShownText = 240;
}  // namespace

InvalidParameter::InvalidParameter(std::string name, std::string value, std::string allowed)
    : std::invalid_argument("invalid " + one_line(name, kShownValue) + " = " +
                            one_line(value, kShownValue) + ": " + one_line(allowed, kShownText)),
      name_(std::move(name)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InvalidParameter::InvalidParameter(std::string name, double value, std::string allowed)
    : InvalidParameter(std::move(name), format_number(value), std::move(allowed)) {}

double parse_number(const std::string& name, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw InvalidParameter(name, text, "must be a number");
  return v;
}

double require_finite(std::string_view name, double value) {
  if (!std::isfinite(value)) throw InvalidParameter(std::string(name), value, "must be a finite number");
  return value;
}

double require_positive(std::string_view name, double value) {
  if (!(std::isfinite(value) && value > 0)) throw InvalidParameter(std::string(name), value, "must be > 0");
  return value;
}

double require_non_negative(std::string_view name, double value) {
  if (!(std::isfinite(value) && value >= 0)) throw InvalidParameter(std::string(name), value, "must be >= 0");
  return value;
}

double require_moderate(std::string_view name, double value) {
  if (!(std::abs(value) <= kMaxMagnitude))
    throw InvalidParameter(std::string(name), value, "must be a finite number with |value| <= 1e50");
  return value;
}

double require_positive_moderate(std::string_view name, double value) {
  if (!(value >= 1.0 / kMaxMagnitude && value <= kMaxMagnitude))
    throw InvalidParameter(std::string(name), value, "must be > 0, within [1e-50, 1e50]");
  return value;
}

double require_greater(std::string_view name, double value, double bound) {
  if (!(std::isfinite(value) && value > bound))
    throw InvalidParameter(std::string(name), value, "must be > " + format_number(bound));
  return value;
}

double require_in_half_open(std::string_view name, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value > lo && value <= hi))
    throw InvalidParameter(std::string(name), value,
                           "must be in (" + format_number(lo) + ", " + format_number(hi) + "]");
  return value;
}

InvalidParameter renamed(const InvalidParameter& e, std::span<const UserName> names,
                         std::string_view prefix) {
  const auto rename = [&](std::string_view part) {
    const std::string_view base = part.substr(0, part.find('['));
    for (const UserName& n : names)
      if (n.library == base) return std::string(n.user) + std::string(part.substr(base.size()));
    // A name the front end already gave in its own words ("field.nx") keeps them: the prefix
    // goes before library names only (it once made "field.field.nx").
    if (!prefix.empty() && part.starts_with(prefix)) return std::string(part);
    return std::string(prefix) + std::string(part);
  };
  std::string name;
  const std::string_view all = e.name();
  for (std::size_t begin = 0;;) {
    const std::size_t comma = all.find(", ", begin);
    if (!name.empty()) name += ", ";
    name += rename(all.substr(begin, comma - begin));
    if (comma == std::string_view::npos) break;
    begin = comma + 2;
  }
  return InvalidParameter(name, e.value(), e.allowed());
}

}  // namespace selfalign
