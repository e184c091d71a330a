#pragma once
/// \file measured_motion.hpp
/// Measured motion of a part (issue 25, item 1; docs/identification.md): a table of time
/// stamps and the part's position (x; y and angle for planar parts), optionally the table's
/// measured position or acceleration, read from a CSV or a video-tracking export and converted
/// to SI.
///
/// The format (docs/identification.md, "Data in"):
///  - one header line naming the columns; lines above it that are not numbers are a title
///    (tracking tools write one, e.g. "mass A" above "t x y"); blank lines and lines starting
///    with '#' are skipped anywhere;
///  - fields separated by commas, semicolons, tabs or runs of spaces (the header's separator);
///  - columns by name, case-insensitive: time (t, time), x (x, position), y, angle (angle,
///    theta), table position (table_x, table, table_position), table acceleration (table_a,
///    table_acceleration); other columns are ignored and listed;
///  - each column's unit as a suffix: "x [mm]", "x (mm)", "x/mm" or "x_mm"; without one, SI
///    (s, m, rad, m/s^2). Units: time s, ms, us, min; length m, cm, mm, um; angle rad, deg;
///    acceleration m/s^2, mm/s^2, g (9.80665 m/s^2); or in a side file beside the data,
///    `<data>.units`, of lines `column = unit` ('#' comments), for files whose header cannot
///    carry them (a unit in both places must agree);
///  - time stamps need not be uniform but must strictly increase;
///  - a row with a missing value (an empty field, nan, NA, '-', or fewer fields than the header)
///    is skipped and counted.

#include <istream>
#include <map>
#include <string>
#include <vector>

namespace selfalign {

/// One measured run in SI units. Columns the file does not have are empty vectors.
struct MeasuredMotion {
  std::string source;                       ///< the file (or the stream's name)
  std::string title;                        ///< the title lines above the header, joined by "; "
  std::vector<double> t;                    ///< time stamps [s], strictly increasing
  std::vector<double> x;                    ///< the part's position along x [m]
  std::vector<double> y;                    ///< along y [m] (planar), or empty
  std::vector<double> angle;                ///< the part's angle [rad] (planar), or empty
  std::vector<double> table_position;       ///< the table's measured position [m], or empty
  std::vector<double> table_acceleration;   ///< the table's measured acceleration [m/s^2], or empty
  std::vector<long long> line;              ///< each sample's line in the file (1-based)
  long long skipped = 0;                    ///< data rows skipped for a missing value
  std::vector<std::string> ignored_columns; ///< header columns that name no known quantity
};

/// Reads a measured run from `path` (at most 512 MB), with the units of `path + ".units"` where
/// that file exists. Throws InvalidParameter with one line naming the file and line: no header
/// with a time column, a column named twice, an unknown unit, a field that is neither a number
/// nor a missing value, time that does not strictly increase, no x column, or no complete row;
/// in the side file a line that is not `column = unit`, a column the data does not have, or a
/// unit that disagrees with the header's.
MeasuredMotion read_measured_motion(const std::string& path);

/// The column units of a side file (`column = unit` per line, '#' comments, blank lines;
/// quotes around the unit allowed): column name (lower case) -> unit; `source` names the file.
std::map<std::string, std::string> parse_measured_units(std::istream& in, const std::string& source);

/// The run from a stream; `source` names it in errors and in the result; `units` (from
/// parse_measured_units, named `units_source` in errors) gives units for columns by name.
MeasuredMotion parse_measured_motion(std::istream& in, const std::string& source,
                                     const std::map<std::string, std::string>& units = {},
                                     const std::string& units_source = "");

}  // namespace selfalign
