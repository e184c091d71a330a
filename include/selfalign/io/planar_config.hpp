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
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/profiles/table_profile.hpp"
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
};

/// Every section and key of a planar config: type, dimension, unit, meaning (docs/planar.md).
const KeyTable& planar_config_keys();

/// Reads and validates a .toml or .json planar configuration. `set` holds "section.key=value"
/// assignments (the CLI's --set) applied over the file's values before they are checked, each
/// value parsed by its key's type (parse_config_value: numbers "4e-5", arrays "0.01,0" or
/// "[0.01, 0]", rows as JSON); InvalidParameter("--set", ...) for an unknown key.
PlanarSetup load_planar_config(const std::string& path, const std::vector<std::string>& set = {});

}  // namespace selfalign
