#pragma once
/// \file npy.hpp
/// A table of named columns as a NumPy .npy file (format version 1.0): a one-dimensional
/// structured array with one field per column, readable without selfalign by
/// `numpy.load(path)` (then `a["v_bar"]`, `a.dtype.names`). Field types: float64 ('<f8') for
/// numbers, int64 ('<i8') for counts and flags, fixed-width bytes ('|S<n>', n the longest
/// value) for words such as a cell's status. Little-endian, C order, no padding between fields;
/// the header is padded with spaces to a multiple of 64 bytes (as NumPy writes it).
/// The format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace selfalign {

struct NpyColumn {
  std::string name;  ///< the field name: [A-Za-z_][A-Za-z0-9_]*
  std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::string>> values;
};

/// The bytes of the .npy file. Throws InvalidParameter naming "columns" when there are none or
/// their lengths differ, a name is not an identifier or repeats, or a word holds a NUL or a
/// character outside printable ASCII.
std::string npy_file(const std::vector<NpyColumn>& columns);

}  // namespace selfalign
