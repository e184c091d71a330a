#pragma once
/// \file simulate_config.hpp
/// The flat configuration of one `selfalign simulate` run: its keys, their defaults, and
/// loading them from JSON / TOML files and from command-line text. Physics-free.
///
/// Every key is also a CLI flag (key c_mu <-> flag --c-mu). A key left unset takes its default;
/// defaults are the paper's Sect. 7.2 setting in dimensionless units (Δt = 1, Δy = 0.084,
/// (y2'', y3'') = (2.3, 1.3), w = 0.05, c_mu = 2.5). In an SI run (units = "si") a key left
/// unset takes its dimensionless default converted to SI with the run's scales
/// (length_scale, mu, g): e.g. stroke = 0.084 L, period = 1 T with T = sqrt(L/(mu g)).
/// docs/config.md lists every key with its type, default and unit in both systems.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "selfalign/io/config_reader.hpp"  // KeyTable, ConfigValue
#include "selfalign/io/unit_system.hpp"  // Dimension, to_si, to_dimensionless
#include "selfalign/units.hpp"

namespace selfalign {

/// One run's settings. Values are in the run's unit system (`units`); unset = default.
struct SimulateConfig {
  // ---- run ----
  std::optional<std::string> units;   ///< "dimensionless" | "si"
  std::optional<std::string> method;  ///< "exact" | "time-stepping"
  // ---- table profile ----
  std::optional<std::string> profile;  ///< "three-phase" | "quadratic-sequence" | "piecewise-linear" | "fourier" | "samples"
  std::optional<double> period;  ///< Δt [-] | [s] (three-phase, fourier)
  std::optional<double> stroke;  ///< Δy [-] | [m] (three-phase)
  std::optional<double> a2;      ///< y2'' [-] | [m/s^2] (three-phase)
  std::optional<double> a3;      ///< y3'' [-] | [m/s^2] (three-phase)
  std::optional<double> jerk;    ///< jerk limit j [-] | [m/s^3] (three-phase); unset: jumps
  std::optional<std::vector<double>> times;  ///< breakpoints [-] | [s] (piecewise-linear)
  std::optional<std::vector<double>> durations;      ///< [-] | [s] (quadratic-sequence)
  std::optional<std::vector<double>> accelerations;  ///< [-] | [m/s^2] (quadratic-sequence)
  std::optional<std::vector<double>> fourier_cos;    ///< A_1..A_N [-] | [m] (fourier)
  std::optional<std::vector<double>> fourier_sin;    ///< B_1..B_N [-] | [m] (fourier)
  std::optional<std::string> samples;        ///< CSV of (t, y'') (samples)
  std::optional<std::string> interpolation;  ///< "constant" | "linear" (samples)
  // ---- friction map ----
  std::optional<std::string> friction;  ///< "two-region" | "uniform" | "field"
  std::optional<std::string> field_file;           ///< CSV of (position, level) (field)
  /// The field's samples in the config instead of field_file (field): positions [-] | [m],
  /// strictly increasing, and the level mu/mu_1 at each [-]: the rows of a field_file.
  std::optional<std::vector<double>> field_positions;
  std::optional<std::vector<double>> field_levels;
  std::optional<std::string> field_interpolation;  ///< "steps" | "linear" (field)
  std::optional<std::string> footprint;            ///< "uniform" (width w) | "point" (field)
  std::optional<double> x_mu;   ///< start of the high-friction region [-] | [m]
  std::optional<double> width;  ///< object width w [-] | [m]
  std::optional<double> c_mu;   ///< mu_2 / mu_1 [-]
  // ---- friction law ----
  std::optional<double> mu_static;    ///< static coefficient [-], >= mu; unset: mu
  std::optional<double> mu_backward;  ///< kinetic coefficient of backward slip [-]; unset: mu
  std::optional<double> stribeck_velocity;  ///< Stribeck v_s [-] | [m/s], > 0; unset: no decay
  std::optional<double> stribeck_exponent;  ///< Stribeck delta [-], in (0, 100]
  std::optional<double> viscous;  ///< viscous rate c [-] | [1/s], >= 0; unset: none
  // ---- scales (Sect. 3.2) ----
  std::optional<double> mu;            ///< mu_1 [-]
  std::optional<double> g;             ///< gravity [m/s^2]
  std::optional<double> length_scale;  ///< L [m]
  std::optional<double> mass;          ///< m [kg], reported only (cancels from eq. 6)
  // ---- initial state ----
  std::optional<double> t0;  ///< initial time [-] | [s]
  std::optional<double> x0;  ///< initial position [-] | [m]
  std::optional<double> v0;  ///< initial relative velocity x' [-] | [m/s]
  // ---- solver ----
  std::optional<double> periods;      ///< number of table periods simulated [-], > 0
  std::optional<double> step;         ///< time-stepping h [-] | [s]
  std::optional<double> theta;        ///< time-stepping theta [-], in [0, 1]
  std::optional<double> output_step;  ///< sample spacing [-] | [s]; 0: solver default
  std::optional<double> relative_tolerance;  ///< slip integrator rtol [-], in (0, 1)
  std::optional<double> absolute_tolerance;  ///< slip integrator atol [-], in (0, 1)
  // ---- output ----
  std::optional<std::string> out;      ///< trajectory CSV path; unset: no CSV
  std::optional<std::string> summary;  ///< summary JSON path, "-" = stdout

  friend bool operator==(const SimulateConfig&, const SimulateConfig&) = default;
};


using TextField = std::optional<std::string> SimulateConfig::*;
using NumberField = std::optional<double> SimulateConfig::*;
using NumberListField = std::optional<std::vector<double>> SimulateConfig::*;

/// Description of one key: drives file loading, CLI flags, help texts and unit conversion.
struct ConfigKey {
  std::string_view name;   ///< key in files, e.g. "c_mu" (flag: --c-mu)
  std::variant<TextField, NumberField, NumberListField> field;
  Dimension dimension;     ///< SI conversion of the value
  std::string_view unit;     ///< unit in dimensionless runs, e.g. "[-]"
  std::string_view unit_si;  ///< unit in SI runs, e.g. "[m]"
  std::string_view group;    ///< "run", "profile", "friction", "law", "scales", "initial", "solver", "output"
  std::string_view help;     ///< meaning, and which profile / friction map uses it
};

/// Every key, in documentation order.
std::span<const ConfigKey> simulate_config_keys();
/// The same keys as the config reader's key table (one section, ""): what reads a config file
/// and parses a flag's text (config_reader.hpp).
const KeyTable& simulate_config_key_table();
/// The key named `name`, or nullptr.
const ConfigKey* find_simulate_config_key(std::string_view name);
/// Comma-separated list of all key names (for error messages).
std::string simulate_config_key_list();
/// The message for an unknown key: the closest key when it looks like a typo, and where every
/// key is listed (one short line, unlike the full list).
std::string unknown_config_key_hint(std::string_view name);
/// The key's CLI flag: "--" + name with '_' replaced by '-'.
std::string config_flag(const ConfigKey& key);
/// One-line help: meaning, unit in both systems, default (and its SI conversion).
std::string config_help(const ConfigKey& key);
/// Type name for messages: "string", "number" or "array of numbers".
std::string_view config_type_name(const ConfigKey& key);

/// The dimensionless defaults (Sect. 7.2). out, summary and samples stay unset; arrays empty.
SimulateConfig simulate_config_defaults();

/// Reads a .json or .toml file (read_document, io/document.hpp: one table of keys, at most 2
/// levels deep) and registers it as the run's --config input. Throws InvalidParameter:
/// ("config key", key, "unknown key ...") for an unknown key, (key, value, "must be a <type>
/// ...") for a wrong type, ("config file", path, <what, with line and column>) for an
/// unreadable, malformed or too deeply nested file. Values are not range-checked here.
SimulateConfig load_simulate_config(const std::string& path);

/// The same from a document already read (a JSON object of keys, e.g. the WebAssembly core's
/// argument): the keys, types and messages of a config file; `source` names it in messages
/// ("(in <source>)"). Throws InvalidParameter("config", source, ...) unless `doc` is an object.
SimulateConfig simulate_config_from_json(const nlohmann::json& doc, const std::string& source);

/// Sets one key from command-line text (numbers as C-locale text, "nan" parsed and refused by
/// resolve_simulate_config, whatever the key; arrays comma-separated: "0.3,0.2,0.5"). Throws InvalidParameter for an unknown key
/// or text that is not of the key's type.
void set_simulate_config_value(SimulateConfig& config, std::string_view key,
                               const std::string& text);
/// Sets `key`'s field to `value` (of the key's type: the config reader's value of that key).
void set_simulate_config_value(SimulateConfig& config, const ConfigKey& key, ConfigValue value);

/// `base` with every key set in `overrides` replaced (file values, then flags).
SimulateConfig merge(const SimulateConfig& base, const SimulateConfig& overrides);


/// Converts every dimensional key (Dimension != none; numbers and arrays) from dimensionless
/// to SI with `scales`. Other keys are copied. The samples file is not touched.
SimulateConfig to_si(const SimulateConfig& config, const Scales& scales);
/// The inverse of to_si: SI values to the dimensionless variables of eq. (4).
SimulateConfig to_dimensionless(const SimulateConfig& config, const Scales& scales);

/// Every key set: unset keys take their defaults in the run's unit system (SI defaults are the
/// dimensionless ones converted with the run's scales). Validates units, mu, g, length_scale,
/// and that every number given (used by the run or not) is finite and within ±1e50: NaN and
/// ±inf are refused naming their key.
/// out, summary and samples stay unset when not given.
SimulateConfig resolve_simulate_config(const SimulateConfig& config);

/// Where a run writes its results; "-" is standard output.
struct OutputPaths {
  std::optional<std::string> trajectory;  ///< CSV path or "-"; none: no CSV
  std::optional<std::string> summary;     ///< JSON path or "-"; none: no summary

  bool summary_to_stdout() const noexcept { return summary && *summary == "-"; }
};
/// Registers the files a config names as inputs of the run (`samples`, `field_file`;
/// register_input_file, run_files.hpp), so that no output replaces them. Called when a config
/// is complete (file and flags merged), before any work, and by resolve_output_paths.
void register_config_files(const SimulateConfig& config);

/// out as given; summary as given, else "<out without extension>.summary.json" when out is a
/// file, none when out is "-" (the CSV takes standard output), else "-". Registers the config's
/// inputs (register_config_files) and both outputs (require_output_path, run_files.hpp), which
/// throws InvalidParameter when a path is empty, a directory, an input of the run (--config,
/// the samples or field file, ...) or the file of another output (out and summary naming one
/// file, however spelled); throws too when both would go to standard output. Call it before
/// the run's work.
OutputPaths resolve_output_paths(const SimulateConfig& config);

}  // namespace selfalign
