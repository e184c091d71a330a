// SimulateConfig: defaults, values from text, merging, SI resolution, output paths.
// The key table itself is in config_keys.cpp.

#include "selfalign/io/simulate_config.hpp"

#include <cmath>
#include <filesystem>

#include "selfalign/error.hpp"
#include "selfalign/io/run_files.hpp"
#include "selfalign/io/unit_system.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

const std::string kStdout = "-";  // summary destination meaning standard output
using D = Dimension;

double convert(Dimension d, double v, const Scales& s, bool si) {
  return si ? to_si(d, v, s) : to_dimensionless(d, v, s);
}

SimulateConfig convert_config(const SimulateConfig& config, const Scales& scales, bool si) {
  SimulateConfig r = config;
  for (const ConfigKey& key : simulate_config_keys()) {
    if (key.dimension == D::none) continue;
    if (auto* f = std::get_if<NumberField>(&key.field); f && (r.**f))
      *(r.**f) = convert(key.dimension, *(r.**f), scales, si);
    if (auto* f = std::get_if<NumberListField>(&key.field); f && (r.**f))
      for (double& v : *(r.**f)) v = convert(key.dimension, v, scales, si);
  }
  return r;
}

}  // namespace

SimulateConfig simulate_config_defaults() {
  SimulateConfig d;
  d.units = "dimensionless";
  d.method = "exact";
  d.profile = "three-phase";
  d.period = 1.0;     // Δt, Sect. 7.2
  d.stroke = 0.084;   // Δy, Sect. 7.2
  d.a2 = 2.3;         // (y2'', y3'') = (2.3, 1.3), Sect. 7.2 / Fig. 16
  d.a3 = 1.3;
  d.durations = std::vector<double>{};
  d.accelerations = std::vector<double>{};
  d.fourier_cos = std::vector<double>{};
  d.fourier_sin = std::vector<double>{};
  d.interpolation = "constant";
  d.friction = "two-region";
  d.field_interpolation = "steps";
  d.footprint = "uniform";
  d.x_mu = 0.5;
  d.width = 0.05;     // w, Sect. 7.2
  d.c_mu = 2.5;       // mu_2 = 2.5 mu_1, Sect. 7.2
  d.mu = 0.3;
  d.g = 9.81;
  d.length_scale = 1e-3;
  d.mass = 1.0;
  d.t0 = 0.0;
  d.x0 = 0.0;
  d.v0 = 0.0;
  d.periods = 20.0;
  d.step = 1e-4;
  d.theta = 0.5;
  d.output_step = 0.0;
  d.stribeck_exponent = 1.0;
  d.relative_tolerance = 1e-10;
  d.absolute_tolerance = 1e-12;
  return d;
}

void set_simulate_config_value(SimulateConfig& config, std::string_view name,
                               const std::string& text) {
  const ConfigKey* key = find_simulate_config_key(name);
  if (!key)
    throw InvalidParameter("config key", std::string(name), unknown_config_key_hint(name));
  set_simulate_config_value(
      config, *key, parse_config_value(*simulate_config_key_table().find("", name), text));
}

SimulateConfig merge(const SimulateConfig& base, const SimulateConfig& overrides) {
  SimulateConfig r = base;
  for (const ConfigKey& key : simulate_config_keys())
    std::visit(
        [&](auto field) {
          if (overrides.*field) r.*field = overrides.*field;
        },
        key.field);
  return r;
}

SimulateConfig to_si(const SimulateConfig& config, const Scales& scales) {
  return convert_config(config, scales, true);
}

SimulateConfig to_dimensionless(const SimulateConfig& config, const Scales& scales) {
  return convert_config(config, scales, false);
}

namespace {
// Every number of a config is a finite number within ±1e50 (error.hpp, kMaxMagnitude), whether
// the run uses its key or not: beyond, a value is a typo or a probe and would overflow the
// motion it describes; NaN and ±inf are refused alike (never read as "not given").
void require_moderate_numbers(const SimulateConfig& c) {
  auto check = [](std::string_view name, double v) {
    if (!(std::abs(v) <= kMaxMagnitude)) require_moderate(std::string(name), v);  // NaN too
  };
  for (const ConfigKey& key : simulate_config_keys()) {
    if (const auto* f = std::get_if<NumberField>(&key.field); f && (c.**f)) check(key.name, *(c.**f));
    if (const auto* f = std::get_if<NumberListField>(&key.field); f && (c.**f))
      for (double v : *(c.**f)) check(key.name, v);
  }
}
// Whether `c` sets every key that has a default: then resolving it changes nothing.
bool sets_every_default(const SimulateConfig& c, const SimulateConfig& defaults) {
  for (const ConfigKey& key : simulate_config_keys()) {
    const bool unset_default = std::visit(
        [&](auto field) { return (defaults.*field).has_value() && !(c.*field).has_value(); },
        key.field);
    if (unset_default) return false;
  }
  return true;
}

}  // namespace

SimulateConfig resolve_simulate_config(const SimulateConfig& in) {
  require_moderate_numbers(in);
  // field_file belongs to friction = field: alone it implies it; with another friction map
  // named it would be ignored, so it is refused (issue 21: `stop --field-file` ran on the
  // default two-region table without a word).
  SimulateConfig config = in;
  const bool inline_field = config.field_positions || config.field_levels;
  if ((config.field_file || inline_field) && !config.friction) config.friction = "field";
  if (config.friction && *config.friction != "field" && config.field_file)
    throw InvalidParameter("field_file", *config.field_file,
                           "belongs to friction = field, but friction = " + *config.friction +
                               ": give friction = field or drop field_file");
  if (config.friction && *config.friction != "field" && inline_field)
    throw InvalidParameter(config.field_positions ? "field_positions" : "field_levels", "given",
                           "belongs to friction = field, but friction = " + *config.friction +
                               ": give friction = field or drop the field's samples");
  if (config.field_file && inline_field)
    throw InvalidParameter("field_positions", "given with field_file",
                           "give the field's samples in field_file or in field_positions and "
                           "field_levels, not both");
  static const SimulateConfig defaults = simulate_config_defaults();
  if (sets_every_default(config, defaults)) {  // resolved already (a parameter view's config)
    if (parse_unit_system(*config.units) == UnitSystem::si)
      (void)Scales(*config.length_scale, *config.mu, *config.g);  // validates them, as below
    return config;
  }
  const SimulateConfig given = merge(defaults, config);  // dimensionless defaults under config
  if (parse_unit_system(*given.units) == UnitSystem::dimensionless) return given;
  // SI: unset keys take their dimensionless default converted with the run's scales.
  const Scales scales(*given.length_scale, *given.mu, *given.g);
  return merge(to_si(defaults, scales), config);
}

void register_config_files(const SimulateConfig& config) {
  if (config.samples && !config.samples->empty()) register_input_file(*config.samples, "--samples");
  if (config.field_file && !config.field_file->empty())
    register_input_file(*config.field_file, "--field-file");
}

OutputPaths resolve_output_paths(const SimulateConfig& config) {
  register_config_files(config);
  OutputPaths paths;
  if (config.out) {
    require_output_path("out", *config.out);
    paths.trajectory = *config.out;
  }
  if (config.summary) {
    if (config.summary->empty())
      throw InvalidParameter("summary", "\"\"", "must be a file path or - (stdout)");
    paths.summary = *config.summary;
  } else if (!config.out) {
    paths.summary = kStdout;
  } else if (*config.out != kStdout) {
    paths.summary = std::filesystem::path(*config.out).replace_extension(".summary.json").string();
  }  // out = "-": the CSV takes standard output; no summary unless one is named
  if (!paths.summary) return paths;
  if (paths.trajectory && *paths.trajectory == kStdout && paths.summary_to_stdout())
    throw InvalidParameter("summary", kStdout,
                           "cannot share standard output with out = -; give --summary FILE");
  require_output_path("summary", *paths.summary);  // also: not the file of out
  return paths;
}

}  // namespace selfalign
