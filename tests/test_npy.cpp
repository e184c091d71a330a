// Tests for io/npy.hpp against the .npy format by hand (NumPy's format 1.0: the magic
// "\x93NUMPY", version 1.0, a little-endian uint16 header length, the header dict padded with
// spaces and ended by '\n' so that the data start at a multiple of 64, then the rows packed).
// python/tests/test_npy_output.py reads the CLI's files with numpy.load, the second reader.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/io/npy.hpp"

namespace selfalign {
namespace {

TEST(Npy, TheFileIsTheFormatByHand) {
  const std::string file = npy_file({{"x", std::vector<double>{1.5, -2.0}},
                                     {"n", std::vector<std::int64_t>{3, -4}},
                                     {"status", std::vector<std::string>{"ok", "failed"}}});
  const std::string dict =
      "{'descr': [('x', '<f8'), ('n', '<i8'), ('status', '|S6')], 'fortran_order': False, "
      "'shape': (2,), }";
  ASSERT_EQ(file.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header = static_cast<unsigned char>(file[8]) +
                             256 * static_cast<unsigned char>(file[9]);
  EXPECT_EQ((10 + header) % 64, 0u);
  const std::string text = file.substr(10, header);
  EXPECT_EQ(text.substr(0, dict.size()), dict);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find_first_not_of(' ', dict.size()), header - 1);  // spaces, then '\n'
  ASSERT_EQ(file.size(), 10 + header + 2 * (8 + 8 + 6));
  const char* row = file.data() + 10 + header;
  double x;
  std::int64_t n;
  std::memcpy(&x, row + 22, 8);
  std::memcpy(&n, row + 22 + 8, 8);
  EXPECT_EQ(x, -2.0);
  EXPECT_EQ(n, -4);
  EXPECT_EQ(std::string(row + 16, 6), std::string("ok\0\0\0\0", 6));
  EXPECT_EQ(std::string(row + 22 + 16, 6), "failed");
}

TEST(Npy, BadTablesAreRefusedByName) {
  EXPECT_THROW(npy_file({}), InvalidParameter);
  EXPECT_THROW(npy_file({{"a", std::vector<double>{1}}, {"b", std::vector<double>{1, 2}}}),
               InvalidParameter);
  EXPECT_THROW(npy_file({{"a", std::vector<double>{1}}, {"a", std::vector<double>{2}}}),
               InvalidParameter);
  EXPECT_THROW(npy_file({{"1a", std::vector<double>{1}}}), InvalidParameter);
  EXPECT_THROW(npy_file({{"w", std::vector<std::string>{std::string("a\0b", 3)}}}),
               InvalidParameter);
  // an empty table (no rows) is a valid file
  EXPECT_NO_THROW(npy_file({{"a", std::vector<double>{}}}));
}

// NpyRecords, filled row by row from several threads (as a sweep's workers fill it), is the
// same file as npy_file of the same columns; its readers give back what was set.
TEST(Npy, RecordsFilledInPlaceAreTheColumnsFile) {
  constexpr std::size_t rows = 5000;
  std::vector<double> x(rows);
  std::vector<std::int64_t> n(rows);
  std::vector<std::string> status(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    x[r] = 0.1 * static_cast<double>(r) - 7.0;
    n[r] = static_cast<std::int64_t>(r % 7) - 3;
    status[r] = r % 11 == 0 ? "failed" : "ok";
  }
  NpyRecords t({{"x", NpyKind::float64}, {"n", NpyKind::int64}, {"status", NpyKind::bytes, 6}},
               rows);
  std::vector<std::thread> workers;
  for (std::size_t w = 0; w < 4; ++w)
    workers.emplace_back([&, w] {
      for (std::size_t r = w; r < rows; r += 4) {
        t.set(r, 0, x[r]);
        t.set(r, 1, n[r]);
        t.set(r, 2, std::string_view(status[r]));
      }
    });
  for (std::thread& w : workers) w.join();
  EXPECT_EQ(std::string(t.file()),
            npy_file({{"x", x}, {"n", n}, {"status", status}}));  // widest word: "failed"
  EXPECT_EQ(t.number(17, 0), x[17]);
  EXPECT_EQ(t.integer(17, 1), n[17]);
  EXPECT_EQ(t.word(22, 2), "failed");
  EXPECT_EQ(t.word(23, 2), "ok");
  EXPECT_THROW(t.set(0, 2, std::string_view("toolong")), InvalidParameter);
  EXPECT_THROW(t.set(0, 2, std::string_view("a\tb")), InvalidParameter);
  EXPECT_THROW(NpyRecords({{"w", NpyKind::bytes, 0}}, 1), InvalidParameter);
  EXPECT_THROW(NpyRecords({}, 1), InvalidParameter);
}

}  // namespace
}  // namespace selfalign
