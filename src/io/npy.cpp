#include "selfalign/io/npy.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <set>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace {

static_assert(std::endian::native == std::endian::little,
              "npy_file writes the machine's little-endian bytes as '<f8' and '<i8'");

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::size_t length_of(const NpyColumn& c) {
  return std::visit([](const auto& v) { return v.size(); }, c.values);
}

// A column's field width in bytes and its NumPy type string.
std::pair<std::size_t, std::string> field_of(const NpyColumn& c) {
  return std::visit(
      Overloaded{[](const std::vector<double>&) { return std::pair<std::size_t, std::string>{8, "<f8"}; },
                 [](const std::vector<std::int64_t>&) {
                   return std::pair<std::size_t, std::string>{8, "<i8"};
                 },
                 [](const std::vector<std::string>& words) {
                   std::size_t w = 1;
                   for (const std::string& s : words) w = std::max(w, s.size());
                   return std::pair<std::size_t, std::string>{w, "|S" + std::to_string(w)};
                 }},
      c.values);
}

}  // namespace

std::string npy_file(const std::vector<NpyColumn>& columns) {
  if (columns.empty()) throw InvalidParameter("columns", "none", "needs at least one column");
  const std::size_t rows = length_of(columns[0]);
  std::set<std::string> names;
  std::vector<std::size_t> widths;
  std::string descr = "[";
  for (const NpyColumn& c : columns) {
    if (!identifier(c.name) || !names.insert(c.name).second)
      throw InvalidParameter("columns", c.name, "names must be distinct identifiers");
    if (length_of(c) != rows)
      throw InvalidParameter("columns", c.name,
                             "has " + std::to_string(length_of(c)) + " values, the first column " +
                                 std::to_string(rows));
    if (const auto* words = std::get_if<std::vector<std::string>>(&c.values))
      for (const std::string& s : *words)
        for (char ch : s)
          if (ch < 0x20 || ch > 0x7e)
            throw InvalidParameter("columns", c.name, "words must be printable ASCII");
    const auto [width, type] = field_of(c);
    widths.push_back(width);
    descr += (descr.size() > 1 ? ", " : "") + std::string("('") + c.name + "', '" + type + "')";
  }
  descr += "]";
  std::string header = "{'descr': " + descr + ", 'fortran_order': False, 'shape': (" +
                       std::to_string(rows) + ",), }";
  // magic (6) + version (2) + header length (2) + header, ending in '\n', to a multiple of 64
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  if (header.size() > 65535)
    throw InvalidParameter("columns", std::to_string(columns.size()), "too many for a v1.0 header");
  std::size_t row_bytes = 0;
  for (std::size_t w : widths) row_bytes += w;
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  out += header;
  const std::size_t data = out.size();
  out.resize(data + rows * row_bytes, '\0');
  std::size_t offset = 0;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    char* at = out.data() + data + offset;
    std::visit(Overloaded{[&](const std::vector<std::string>& words) {
                            for (std::size_t r = 0; r < rows; ++r)
                              std::memcpy(at + r * row_bytes, words[r].data(), words[r].size());
                          },
                          [&](const auto& numbers) {
                            for (std::size_t r = 0; r < rows; ++r)
                              std::memcpy(at + r * row_bytes, &numbers[r], 8);
                          }},
               columns[k].values);
    offset += widths[k];
  }
  return out;
}

}  // namespace selfalign
