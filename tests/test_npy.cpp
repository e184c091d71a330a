// Tests for io/npy.hpp against the .npy format by hand (NumPy's format 1.0: the magic
// "\x93NUMPY", version 1.0, a little-endian uint16 header length, the header dict padded with
// spaces and ended by '\n' so that the data start at a multiple of 64, then the rows packed).
// python/tests/test_npy_output.py reads the CLI's files with numpy.load, the second reader.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

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

}  // namespace
}  // namespace selfalign
