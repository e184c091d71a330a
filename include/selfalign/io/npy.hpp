#pragma once
/// \file npy.hpp
/// A table of named columns as a NumPy .npy file (format version 1.0): a one-dimensional
/// structured array with one field per column, readable without selfalign by
/// `numpy.load(path)` (then `a["v_bar"]`, `a.dtype.names`). Field types: float64 ('<f8') for
/// numbers, int64 ('<i8') for counts and flags, fixed-width bytes ('|S<n>') for words such as a
/// cell's status. Little-endian, C order, no padding between fields; the header is padded with
/// spaces to a multiple of 64 bytes (as NumPy writes it).
/// The format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
///
/// Two ways to build one: npy_file() from whole columns, or NpyRecords, a file laid out up front
/// and filled row by row in place (a sweep's workers write each cell's record as it is
/// computed, so a study of 10^6 cells is never held twice).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace selfalign {

struct NpyColumn {
  std::string name;  ///< the field name: [A-Za-z_][A-Za-z0-9_]*
  std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::string>> values;
};

/// The type of one field of a record.
enum class NpyKind { float64, int64, bytes };

/// One field of a record: its name ([A-Za-z_][A-Za-z0-9_]*), type, and for bytes the width
/// (>= 1; float64 and int64 are 8 bytes).
struct NpyField {
  std::string name;
  NpyKind kind = NpyKind::float64;
  std::size_t width = 8;
};

/// A .npy file of `rows` fixed-width records, laid out up front: the header is written once and
/// row r's field k sits at a fixed offset, so distinct rows may be set from several threads at
/// once. Every field of every row must be set before file() is read (the bytes start
/// uninitialised: a 10^6-row table is first touched by the threads that fill it).
class NpyRecords {
 public:
  /// Throws InvalidParameter naming "columns" when there are no fields, a name is not an
  /// identifier or repeats, or a bytes width is 0.
  NpyRecords(std::vector<NpyField> fields, std::size_t rows);

  std::size_t rows() const noexcept { return rows_; }
  const std::vector<NpyField>& fields() const noexcept { return fields_; }

  /// Sets field k (float64) of row r.
  void set(std::size_t r, std::size_t k, double value) noexcept;
  /// Sets field k (int64) of row r.
  void set(std::size_t r, std::size_t k, std::int64_t value) noexcept;
  /// Sets field k (bytes) of row r, NUL-padded to the width. Throws InvalidParameter naming
  /// "columns" for a word longer than the width or holding a character outside printable ASCII.
  void set(std::size_t r, std::size_t k, std::string_view word);

  double number(std::size_t r, std::size_t k) const noexcept;
  std::int64_t integer(std::size_t r, std::size_t k) const noexcept;
  /// The word without its NUL padding.
  std::string_view word(std::size_t r, std::size_t k) const noexcept;

  /// The bytes of the .npy file.
  std::string_view file() const noexcept { return {bytes_.get(), size_}; }

 private:
  char* at(std::size_t r, std::size_t k) const noexcept;

  std::vector<NpyField> fields_;
  std::vector<std::size_t> offsets_;
  std::size_t rows_ = 0, row_bytes_ = 0, data_ = 0, size_ = 0;
  std::unique_ptr<char[], void (*)(char*)> bytes_{nullptr, nullptr};
};

/// The bytes of the .npy file of whole columns (bytes fields as wide as their longest word).
/// Throws InvalidParameter naming "columns" when there are none or their lengths differ, a name
/// is not an identifier or repeats, or a word holds a NUL or a character outside printable
/// ASCII.
std::string npy_file(const std::vector<NpyColumn>& columns);

/// The fields npy_file gives these columns.
std::vector<NpyField> npy_fields(const std::vector<NpyColumn>& columns);
/// NpyRecords holding these columns (npy_file's table, for readers of NpyRecords).
NpyRecords npy_records(const std::vector<NpyColumn>& columns);

}  // namespace selfalign
