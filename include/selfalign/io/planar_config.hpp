#pragma once
/// \file planar_config.hpp
/// The configuration of a planar run (`selfalign planar ...`, issue 13) from a TOML or JSON
/// file, in SI units (units = "si", the default) or dimensionless (units = "dimensionless"),
/// converted to the dimensionless model with the scales L, mu, g (units.hpp). docs/planar.md
/// lists every table and key; examples/planar.toml is a complete example. The file is read by
/// read_document (document.hpp: registered as the --config input, at most 4 levels deep, errors
/// with line and column), then checked against the planar key table (planar_config_keys) by
/// the one config reader of the 1-D and planar configs (config_reader.hpp), which converts
/// each value by its key's dimension. Unknown keys and values out of range are refused with
/// InvalidParameter naming the key with its section ("part.radius").

#include <memory>
#include <string>
#include <vector>

#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/units.hpp"

namespace selfalign {

/// A loaded planar configuration: the problem (dimensionless), the profiles it points to, and
/// the settings of each command. Move-only (the problem points into `profiles`).
struct PlanarSetup {
  Scales scales{1.0, 1.0, 9.81};
  bool si = true;
  double mass = 1;  ///< [kg] (reported; the model is per unit mass)
  std::vector<std::unique_ptr<TableProfile>> profiles;
  PlanarProblem problem;
  // [run]
  PlanarPose pose;
  PlanarTwist twist;
  int periods = 10, every = 1;
  Method method = Method::time_stepping;  ///< simulate: time-stepping or exact (planar_run.hpp)
  int transient = 0;          ///< steady: periods before the fixed-point search
  int steady_periods = 2000;  ///< steady: periods of the search at most
  double tolerance = 0;       ///< steady: PlanarSteadyStateOptions::tolerance (0: default)
  int window = 10;            ///< no longer used (the window average before issue 21)
  bool window_given = false;
  // [field_map]
  std::vector<double> grid_x{0.0}, grid_y{0.0}, grid_angles{0.0};
  int field_periods = 1;
  // [stop]
  std::vector<PlanarPose> entries;
  int max_periods = 2000;
  std::string path;  ///< the file read
  /// Keys the config (and --set) gives that building this setup did not read, as
  /// "section.key": they have no effect (e.g. c_mu for an axis field, cos for a three-phase
  /// motion). The CLI warns about each.
  std::vector<std::string> unused_keys;
};

/// Every section and key of a planar config: type, dimension, unit, meaning (docs/planar.md).
const KeyTable& planar_config_keys();

/// Reads and validates a .toml or .json planar configuration. `set` holds "section.key=value"
/// assignments (the CLI's --set) applied over the file's values before they are checked, each
/// value parsed by its key's type (parse_config_value: numbers "4e-5", arrays "0.01,0" or
/// "[0.01, 0]", rows as JSON), or "section.key[i]=value" setting element i of an array the
/// config gives; InvalidParameter("--set", ...) for an unknown key or an element out of range.
/// `reads` (optional) receives every number and array the setup was built from, as the config
/// gives them (file units; defaults where unset): the source of planar_model_parameters.
PlanarSetup load_planar_config(const std::string& path, const std::vector<std::string>& set = {},
                               std::vector<ConfigSection::Read>* reads = nullptr);

/// The named parameter view of a planar config (issue 21 item 1; parameter_view.hpp is the 1-D
/// one): every number the model built from this config depends on, in the order it was read,
/// with its value as the config gives it (SI in an SI config: its file's units; the default
/// where the config does not set it), unit, group (the section) and meaning (the key's help).
/// A parameter is a number key whose role is KeyRole::parameter (settings: the unit L, the
/// reported mass, discretisation, solver and analysis keys), or element i of such an array
/// ("field.levels[2]", "run.pose[0]"), only the keys the config's kinds read (an axis field has
/// no c_mu). Changing one is `set` (the same names: "field.c_mu=3", "field.levels[2]=1.5"),
/// checked as the file's values are. Throws what load_planar_config throws.
std::vector<ModelParameter> planar_model_parameters(const std::string& path,
                                                    const std::vector<std::string>& set = {});
/// The same view from the reads of a load_planar_config already done (`si`: the setup's unit
/// system), for a caller that needs the setup too (the config is read once).
std::vector<ModelParameter> planar_model_parameters(const std::vector<ConfigSection::Read>& reads,
                                                    bool si);

}  // namespace selfalign
