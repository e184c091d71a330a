#include "warnings.hpp"

#include <algorithm>
#include <iostream>
#include <vector>

#include "selfalign/error.hpp"

namespace selfalign::cli {
namespace {
constexpr double kGramsFrom = 10;  // [kg]: a part of 10 kg or more on a vibrating table is rare
std::vector<std::string>& kept() {
  static std::vector<std::string> lines;
  return lines;
}
}  // namespace

void warn(const std::string& message) {
  std::vector<std::string>& lines = kept();
  if (std::find(lines.begin(), lines.end(), message) == lines.end()) lines.push_back(message);
}

void print_warnings() {
  for (const std::string& line : kept()) std::cerr << "selfalign: warning: " << line << '\n';
  std::cerr << std::flush;
}

void warn_default_mu(bool mu_given, double mu, const std::optional<double>& mu_static,
                     const std::optional<double>& mu_backward) {
  if (mu_given || !(mu_static || mu_backward)) return;
  const bool s = mu_static.has_value();
  const double v = s ? *mu_static : *mu_backward;
  warn(std::string(s ? "mu_static" : "mu_backward") + " = " + format_number(v) +
       " is an absolute coefficient, taken relative to the default kinetic coefficient mu = " +
       format_number(mu) + " (ratio " + format_number(v / mu) +
       "); give --mu, your material's kinetic coefficient");
}

void warn_if_millimetres(const std::string& name, double metres, double from) {
  if (!(metres >= from && metres <= 1e50)) return;
  warn(name + " = " + format_number(metres) + " m looks like millimetres: " +
       format_number(metres) + " mm is " + name + " = " + format_number(metres / 1000) +
       " (SI inputs are in m)");
}

void warn_if_grams(const std::string& name, double kilograms) {
  if (!(kilograms >= kGramsFrom && kilograms <= 1e50)) return;
  warn(name + " = " + format_number(kilograms) + " kg looks like grams: " +
       format_number(kilograms) + " g is " + name + " = " + format_number(kilograms / 1000) +
       " (masses are in kg)");
}

void warn_about_config(const SimulateConfig& c) {
  warn_default_mu(c.mu.has_value(), c.mu.value_or(*simulate_config_defaults().mu), c.mu_static,
                  c.mu_backward);
  if (c.mass) warn_if_grams("mass", *c.mass);
  if (c.units != "si") return;
  if (c.width) warn_if_millimetres("width", *c.width, 1);
  if (c.stroke) warn_if_millimetres("stroke", *c.stroke, 1);
}

}  // namespace selfalign::cli
