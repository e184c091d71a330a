// The key table of SimulateConfig and what derives from it: names, flags, help texts.

#include <algorithm>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {
namespace {

using C = SimulateConfig;
using D = Dimension;

// The key table: one row per key, in documentation order. Units: [-] in dimensionless runs,
// the SI unit in SI runs; keys with Dimension::none have the same value in both systems.
const ConfigKey kKeys[] = {
    {"units", &C::units, D::none, "", "", "run",
     "unit system of every input and output: dimensionless (Sect. 3.2) or si"},
    {"method", &C::method, D::none, "", "", "run",
     "solver: exact (event-driven; piecewise-constant or piecewise-linear y'', or fourier on "
     "any piecewise-affine friction), integrator (exact sticks, Dormand-Prince slips; what exact "
     "runs under a Stribeck or viscous law) or time-stepping (Moreau)"},
    {"profile", &C::profile, D::none, "", "", "profile",
     "table motion: three-phase (Sect. 4.4.3; with jerk: trapezoidal acceleration), "
     "quadratic-sequence (durations, accelerations), piecewise-linear (times, accelerations, "
     "period), fourier (fourier_cos, fourier_sin), samples (CSV file)"},
    {"period", &C::period, D::time, "[-]", "[s]", "profile",
     "table period Δt (three-phase, fourier), > 0"},
    {"stroke", &C::stroke, D::length, "[-]", "[m]", "profile",
     "table stroke Δy = max y - min y (three-phase), > 0"},
    {"a2", &C::a2, D::acceleration, "[-]", "[m/s^2]", "profile",
     "y2'': the table accelerates with -y2'' on [t1, t2] (three-phase), > 0"},
    {"a3", &C::a3, D::acceleration, "[-]", "[m/s^2]", "profile",
     "y3'': the table accelerates with +y3'' on [t2, t3] (three-phase), > 0"},
    {"jerk", &C::jerk, D::jerk, "[-]", "[m/s^3]", "profile",
     "jerk limit j of the three-phase profile: each switch becomes a ramp of duration "
     "Δa/j (docs/jerk-limited-three-phase.md), > 0; unset: jump accelerations (the paper's)"},
    {"durations", &C::durations, D::time, "[-]", "[s]", "profile",
     "durations of the constant-acceleration segments of one period (quadratic-sequence), "
     "comma-separated"},
    {"accelerations", &C::accelerations, D::acceleration, "[-]", "[m/s^2]", "profile",
     "table acceleration y'' on each segment (quadratic-sequence; sum of "
     "acceleration*duration must be 0) or at each breakpoint (piecewise-linear), "
     "comma-separated"},
    {"times", &C::times, D::time, "[-]", "[s]", "profile",
     "breakpoint times of a piecewise-linear (finite-jerk) table acceleration "
     "(piecewise-linear): 0 first, increasing, < period; y'' goes linearly between breakpoints "
     "and back to the first value at period; comma-separated"},
    {"fourier_cos", &C::fourier_cos, D::length, "[-]", "[m]", "profile",
     "cosine coefficients A_1..A_N of y(t) (fourier), comma-separated"},
    {"fourier_sin", &C::fourier_sin, D::length, "[-]", "[m]", "profile",
     "sine coefficients B_1..B_N of y(t) (fourier), comma-separated"},
    {"samples", &C::samples, D::none, "", "", "profile",
     "CSV file of one period of 't,y''' samples, t from 0 to Δt (samples); [-] or, in SI, "
     "[s] and [m/s^2]"},
    {"interpolation", &C::interpolation, D::none, "", "", "profile",
     "interpolation of the samples: constant (exact solver applies) or linear"},
    {"friction", &C::friction, D::none, "", "", "friction",
     "friction map: two-region (eqs. 7-9), uniform (mu_1 everywhere), or field (a measured or "
     "designed mu(xi)/mu_1 from field_file, averaged over the footprint: eq. 7)"},
    {"field_file", &C::field_file, D::none, "", "", "friction",
     "CSV of 'position,level' rows (field): the table's mu/mu_1 over table position, positions "
     "[-] or, in SI, [m], strictly increasing; levels finite, >= 0 (docs/friction-field.md)"},
    {"field_positions", &C::field_positions, D::length, "[-]", "[m]", "friction",
     "the field's sample positions in the config instead of field_file (field): strictly "
     "increasing, comma-separated; with field_levels they are the rows of a field_file (their "
     "levels are parameters of the model: selfalign parameters)"},
    {"field_levels", &C::field_levels, D::none, "[-]", "[-]", "friction",
     "mu/mu_1 at each of field_positions (field): finite, >= 0, > 0 somewhere, comma-separated"},
    {"field_interpolation", &C::field_interpolation, D::none, "", "", "friction",
     "how the field's samples fill the table (field): steps (each level holds to the next "
     "position) or linear (ramps)"},
    {"footprint", &C::footprint, D::none, "", "", "friction",
     "the object's contact (field): uniform (pressure spread over its width w: the field "
     "averaged over [x - w, x]) or point (m = the field at x)"},
    {"x_mu", &C::x_mu, D::length, "[-]", "[m]", "friction",
     "start x_mu of the high-friction region (two-region)"},
    {"width", &C::width, D::length, "[-]", "[m]", "friction",
     "object width w (two-region), > 0"},
    {"c_mu", &C::c_mu, D::none, "[-]", "[-]", "friction",
     "friction ratio c_mu = mu_2/mu_1 (two-region), > 1"},
    {"mu_static", &C::mu_static, D::none, "[-]", "[-]", "law",
     "static friction coefficient, absolute like mu (give mu with it), >= mu and mu_backward "
     "(default: mu, static = kinetic); it holds a part at rest: stick while |y''| <= "
     "mu_static/mu m(x)"},
    {"mu_backward", &C::mu_backward, D::none, "[-]", "[-]", "law",
     "kinetic friction coefficient of backward slip (x' < 0), absolute like mu, > 0 (default: "
     "mu; the forward one is mu)"},
    {"stribeck_velocity", &C::stribeck_velocity, D::velocity, "[-]", "[m/s]", "law",
     "Stribeck velocity v_s, > 0: the kinetic coefficient falls from mu_static at rest to mu "
     "(mu_backward) as mu + (mu_static - mu) exp(-(|x'|/v_s)^delta) (default: none, Coulomb); "
     "solved by the slip integrator"},
    {"stribeck_exponent", &C::stribeck_exponent, D::none, "[-]", "[-]", "law",
     "Stribeck exponent delta, in (0, 100] (with stribeck_velocity)"},
    {"viscous", &C::viscous, D::rate, "[-]", "[1/s]", "law",
     "viscous friction rate c >= 0: a force -m c x' while slipping (default: none); solved by "
     "the slip integrator"},
    {"mu", &C::mu, D::none, "[-]", "[-]", "scales",
     "low-friction coefficient mu_1, the kinetic coefficient of forward slip: in every run the "
     "unit of mu_static and mu_backward (their ratios to mu); in SI runs, with g and "
     "length_scale, T = sqrt(L/(mu g)), > 0"},
    {"g", &C::g, D::none, "[m/s^2]", "[m/s^2]", "scales", "gravitational acceleration, > 0"},
    {"length_scale", &C::length_scale, D::none, "[m]", "[m]", "scales",
     "characteristic length L of the dimensionless model, > 0"},
    {"mass", &C::mass, D::none, "[kg]", "[kg]", "scales",
     "object mass, > 0; reported only (it cancels from eq. 6)"},
    {"t0", &C::t0, D::time, "[-]", "[s]", "initial", "initial time"},
    {"x0", &C::x0, D::length, "[-]", "[m]", "initial", "initial position x"},
    {"v0", &C::v0, D::velocity, "[-]", "[m/s]", "initial",
     "initial velocity x' relative to the table"},
    {"periods", &C::periods, D::none, "[-]", "[-]", "solver",
     "number of table periods simulated (duration = periods * Δt), > 0"},
    {"step", &C::step, D::time, "[-]", "[s]", "solver", "time-stepping step h, > 0"},
    {"theta", &C::theta, D::none, "[-]", "[-]", "solver", "time-stepping theta, in [0, 1]"},
    {"output_step", &C::output_step, D::time, "[-]", "[s]", "solver",
     "spacing of the trajectory samples, >= 0; 0: h (time-stepping) or Δt/200 (exact)"},
    {"relative_tolerance", &C::relative_tolerance, D::none, "[-]", "[-]", "solver",
     "slip integrator (Stribeck, viscous): relative tolerance of each step, in (0, 1)"},
    {"absolute_tolerance", &C::absolute_tolerance, D::none, "[-]", "[-]", "solver",
     "slip integrator: absolute tolerance of each step on the dimensionless x and x', in (0, 1)"},
    {"out", &C::out, D::none, "", "", "output", "trajectory CSV file (default: none written)"},
    {"summary", &C::summary, D::none, "", "", "output",
     "summary JSON file, - for stdout (default: <out without extension>.summary.json when out "
     "is given, else stdout)"},
};

std::string_view conversion_factor(Dimension d) {
  switch (d) {
    case D::length: return "L";
    case D::time: return "T";
    case D::velocity: return "L/T";
    case D::acceleration: return "mu g";
    case D::jerk: return "mu g / T";
    case D::rate: return "1/T";
    case D::none: break;
  }
  return "";
}

std::string format_list(const std::vector<double>& values) {
  std::string s;
  for (double v : values) {
    if (!s.empty()) s += ',';
    s += format_number(v);
  }
  return s;
}

}  // namespace

std::span<const ConfigKey> simulate_config_keys() { return kKeys; }

const KeyTable& simulate_config_key_table() {
  static const std::vector<KeySpec> specs = [] {
    constexpr ValueType kTypes[] = {ValueType::text, ValueType::number, ValueType::numbers};
    std::vector<KeySpec> s;
    for (const ConfigKey& key : kKeys)
      s.push_back({"", key.name, kTypes[key.field.index()], key.dimension, {}, {}, key.unit_si,
                   key.help});
    return s;
  }();
  static const KeyTable table{specs, "docs/config.md and `selfalign simulate --help`"};
  return table;
}

const ConfigKey* find_simulate_config_key(std::string_view name) {
  for (const ConfigKey& key : kKeys)
    if (key.name == name) return &key;
  return nullptr;
}

std::string simulate_config_key_list() {
  std::string s;
  for (const ConfigKey& key : kKeys) {
    if (!s.empty()) s += ", ";
    s += key.name;
  }
  return s;
}

std::string unknown_config_key_hint(std::string_view name) {
  return unknown_key_message(simulate_config_key_table(), "", name);
}

std::string config_flag(const ConfigKey& key) {
  std::string flag = "--" + std::string(key.name);
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

std::string_view config_type_name(const ConfigKey& key) {
  switch (key.field.index()) {
    case 0: return "string";
    case 1: return "number";
    default: return "array of numbers";
  }
}

std::string config_help(const ConfigKey& key) {
  std::string help(key.help);
  if (!key.unit.empty()) {
    help += ". Unit: " + std::string(key.unit);
    if (key.unit_si != key.unit) help += ", SI " + std::string(key.unit_si);
  }
  const SimulateConfig defaults = simulate_config_defaults();
  std::string value;
  if (auto* f = std::get_if<TextField>(&key.field)) value = (defaults.**f).value_or("");
  if (auto* f = std::get_if<NumberField>(&key.field))
    value = (defaults.**f) ? format_number(*(defaults.**f)) : "";
  if (auto* f = std::get_if<NumberListField>(&key.field))
    value = (defaults.**f) ? format_list(*(defaults.**f)) : "";
  if (!value.empty()) {
    help += ". Default: " + value;
    if (key.dimension != D::none)
      help += " (SI: " + value + " " + std::string(conversion_factor(key.dimension)) + ")";
  } else if (key.field.index() == 2) {
    help += ". Default: none";
  }
  return help;
}

}  // namespace selfalign
