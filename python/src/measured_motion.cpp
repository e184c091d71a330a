// read_measured_motion: a measured run (io/measured_motion.hpp, issue 25) as NumPy columns.

#include "selfalign/io/measured_motion.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"

namespace selfalign::python {

namespace {

// A column as a float64 array, or None where the file has none.
py::object column(std::vector<double>&& v) {
  if (v.empty()) return py::none();
  return to_array(std::move(v));
}

}  // namespace

void bind_measured_motion(py::module_& m) {
  m.def(
      "read_measured_motion",
      [](const py::object& path) {
        if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
          throw py::type_error("path: expected a str or os.PathLike, got " +
                               py::str(py::type::of(path).attr("__name__")).cast<std::string>());
        const std::string p = py::str(py::module_::import("os").attr("fspath")(path));
        MeasuredMotion r;
        {
          py::gil_scoped_release release;
          r = read_measured_motion(p);
        }
        py::dict d;
        d["source"] = r.source, d["title"] = r.title;
        d["t"] = to_array(std::move(r.t)), d["x"] = to_array(std::move(r.x));
        d["y"] = column(std::move(r.y)), d["angle"] = column(std::move(r.angle));
        d["table_position"] = column(std::move(r.table_position));
        d["table_acceleration"] = column(std::move(r.table_acceleration));
        std::vector<std::int64_t> line(r.line.begin(), r.line.end());
        d["line"] = to_array(std::move(line));
        d["skipped"] = r.skipped;
        d["ignored_columns"] = r.ignored_columns;
        return d;
      },
      py::arg("path"), R"doc(
Reads a measured run of a part (docs/identification.md, "Data in"): a CSV or a video-tracking
export with a header naming its columns (t/time, x/position, y, angle/theta, table_x/
table_position, table_a/table_acceleration; units as suffixes "x [mm]", "x (mm)", "x/mm" or
"x_mm", or in a side file `<path>.units` of lines "column = unit"; SI without one), fields
separated by commas, semicolons, tabs or spaces, title lines above the header, '#'
comments. Returns a dict, all in SI:
  float64  t [s] (strictly increasing, not necessarily uniform), x [m]; y [m], angle [rad],
           table_position [m], table_acceleration [m/s^2] (None where the file has no such
           column)
  int64    line (each sample's line in the file, 1-based)
  int      skipped (rows skipped for a missing value: empty, nan, NA, - or a short row)
  str      source, title; list[str] ignored_columns
Raises InvalidParameter with one line naming the file and line: no time column, time that does
not increase, a field that is text, an unknown unit, a column named twice, no x, no complete
row; in the side file a bad line, a column the data lacks or a unit that disagrees with the
header's.)doc");
}

}  // namespace selfalign::python
