#include "selfalign/io/npy.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstring>
#include <cstdlib>
#include <new>
#include <set>

#if __has_include(<sys/mman.h>)
#include <sys/mman.h>  // madvise
#endif

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace {

static_assert(std::endian::native == std::endian::little,
              "npy files hold the machine's little-endian bytes as '<f8' and '<i8'");

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::size_t length_of(const NpyColumn& c) {
  return std::visit([](const auto& v) { return v.size(); }, c.values);
}

std::string type_of(const NpyField& f) {
  switch (f.kind) {
    case NpyKind::float64: return "<f8";
    case NpyKind::int64: return "<i8";
    case NpyKind::bytes: return "|S" + std::to_string(f.width);
  }
  return "";
}

// Uninitialised bytes: the rows are first touched by the threads that fill them. A large
// table asks for transparent huge pages (Linux): 10^6 rows of 70 bytes are otherwise 17 000
// page faults, about as long as computing the rows (bench/bench_sweep.cpp).
std::unique_ptr<char[], void (*)(char*)> allocate_file(std::size_t size) {
#ifdef MADV_HUGEPAGE
  constexpr std::size_t kHugePage = 2u << 20;
  if (size >= 2 * kHugePage) {
    const std::size_t rounded = (size + kHugePage - 1) / kHugePage * kHugePage;
    if (void* p = std::aligned_alloc(kHugePage, rounded)) {
      madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal changes nothing
      return {static_cast<char*>(p), [](char* q) { std::free(q); }};
    }
  }
#endif
  void* p = std::malloc(std::max<std::size_t>(size, 1));
  if (!p) throw std::bad_alloc();
  return {static_cast<char*>(p), [](char* q) { std::free(q); }};
}

}  // namespace

NpyRecords::NpyRecords(std::vector<NpyField> fields, std::size_t rows)
    : fields_(std::move(fields)), rows_(rows) {
  if (fields_.empty()) throw InvalidParameter("columns", "none", "needs at least one column");
  std::set<std::string> names;
  std::string descr = "[";
  for (NpyField& f : fields_) {
    if (!identifier(f.name) || !names.insert(f.name).second)
      throw InvalidParameter("columns", f.name, "names must be distinct identifiers");
    if (f.kind != NpyKind::bytes) f.width = 8;
    if (f.width == 0) throw InvalidParameter("columns", f.name, "a word field needs a width >= 1");
    offsets_.push_back(row_bytes_);
    row_bytes_ += f.width;
    descr += (descr.size() > 1 ? ", " : "") + std::string("('") + f.name + "', '" + type_of(f) +
             "')";
  }
  descr += "]";
  std::string header = "{'descr': " + descr + ", 'fortran_order': False, 'shape': (" +
                       std::to_string(rows) + ",), }";
  // magic (6) + version (2) + header length (2) + header, ending in '\n', to a multiple of 64
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  if (header.size() > 65535)
    throw InvalidParameter("columns", std::to_string(fields_.size()), "too many for a v1.0 header");
  data_ = 10 + header.size();
  size_ = data_ + rows * row_bytes_;
  bytes_ = allocate_file(size_);
  std::memcpy(bytes_.get(), "\x93NUMPY\x01\x00", 8);
  bytes_[8] = static_cast<char>(header.size() & 0xff);
  bytes_[9] = static_cast<char>(header.size() >> 8);
  std::memcpy(bytes_.get() + 10, header.data(), header.size());
}

char* NpyRecords::at(std::size_t r, std::size_t k) const noexcept {
  return bytes_.get() + data_ + r * row_bytes_ + offsets_[k];
}

void NpyRecords::set(std::size_t r, std::size_t k, double value) noexcept {
  std::memcpy(at(r, k), &value, 8);
}
void NpyRecords::set(std::size_t r, std::size_t k, std::int64_t value) noexcept {
  std::memcpy(at(r, k), &value, 8);
}
void NpyRecords::set(std::size_t r, std::size_t k, std::string_view word) {
  const NpyField& f = fields_[k];
  if (word.size() > f.width)
    throw InvalidParameter("columns", f.name,
                           "word longer than the field's " + std::to_string(f.width) + " bytes");
  for (char ch : word)
    if (ch < 0x20 || ch > 0x7e)
      throw InvalidParameter("columns", f.name, "words must be printable ASCII");
  char* p = at(r, k);
  std::memcpy(p, word.data(), word.size());
  std::memset(p + word.size(), 0, f.width - word.size());
}

double NpyRecords::number(std::size_t r, std::size_t k) const noexcept {
  double v;
  std::memcpy(&v, at(r, k), 8);
  return v;
}
std::int64_t NpyRecords::integer(std::size_t r, std::size_t k) const noexcept {
  std::int64_t v;
  std::memcpy(&v, at(r, k), 8);
  return v;
}
std::string_view NpyRecords::word(std::size_t r, std::size_t k) const noexcept {
  const char* p = at(r, k);
  return {p, strnlen(p, fields_[k].width)};
}

std::vector<NpyField> npy_fields(const std::vector<NpyColumn>& columns) {
  std::vector<NpyField> fields;
  for (const NpyColumn& c : columns)
    fields.push_back(std::visit(
        Overloaded{[&](const std::vector<double>&) { return NpyField{c.name, NpyKind::float64}; },
                   [&](const std::vector<std::int64_t>&) {
                     return NpyField{c.name, NpyKind::int64};
                   },
                   [&](const std::vector<std::string>& words) {
                     std::size_t w = 1;
                     for (const std::string& s : words) w = std::max(w, s.size());
                     return NpyField{c.name, NpyKind::bytes, w};
                   }},
        c.values));
  return fields;
}

NpyRecords npy_records(const std::vector<NpyColumn>& columns) {
  if (columns.empty()) throw InvalidParameter("columns", "none", "needs at least one column");
  const std::size_t rows = length_of(columns[0]);
  for (const NpyColumn& c : columns)
    if (length_of(c) != rows)
      throw InvalidParameter("columns", c.name,
                             "has " + std::to_string(length_of(c)) + " values, the first column " +
                                 std::to_string(rows));
  NpyRecords t(npy_fields(columns), rows);
  for (std::size_t k = 0; k < columns.size(); ++k)
    std::visit([&](const auto& values) {
      for (std::size_t r = 0; r < rows; ++r) t.set(r, k, values[r]);
    }, columns[k].values);
  return t;
}

std::string npy_file(const std::vector<NpyColumn>& columns) {
  return std::string(npy_records(columns).file());
}

}  // namespace selfalign
