// Measured motion files (io/measured_motion.hpp, issue 25 item 1): hand-written tables whose
// SI values are worked out by hand in the comments (1 ms = 1e-3 s, 1 mm = 1e-3 m, 90 deg =
// pi/2 rad, 1 g = 9.80665 m/s^2).

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/io/measured_motion.hpp"

namespace selfalign {
namespace measured_motion_test {

MeasuredMotion parse(const std::string& text) {
  std::istringstream in(text);
  return parse_measured_motion(in, "run.csv");
}

// The one-line message of the InvalidParameter that parsing `text` throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "";
}

TEST(MeasuredMotion, BracketedUnitsAreConvertedToSI) {
  const MeasuredMotion m = parse(
      "t [ms],x [mm],y [mm],angle [deg],table_a [g]\n"
      "0,1.5,-2,90,0.5\n"
      "2.5,1.75,-2,-45,1\n");
  ASSERT_EQ(m.t.size(), 2u);
  EXPECT_DOUBLE_EQ(m.t[1], 2.5e-3);
  EXPECT_DOUBLE_EQ(m.x[0], 1.5e-3);
  EXPECT_DOUBLE_EQ(m.x[1], 1.75e-3);
  EXPECT_DOUBLE_EQ(m.y[0], -2e-3);
  EXPECT_DOUBLE_EQ(m.angle[0], std::acos(-1.0) / 2);
  EXPECT_DOUBLE_EQ(m.angle[1], -std::acos(-1.0) / 4);
  EXPECT_DOUBLE_EQ(m.table_acceleration[0], 0.5 * 9.80665);
  EXPECT_TRUE(m.table_position.empty());
  EXPECT_EQ(m.line, (std::vector<long long>{2, 3}));
  EXPECT_EQ(m.skipped, 0);
}

TEST(MeasuredMotion, ATrackerExportWithATitleAndAMissingValue) {
  // a video-tracking export: a title line, tab-separated "t x y", one row without y
  const MeasuredMotion m = parse(
      "mass A\n"
      "t\tx\ty\n"
      "0.000\t0.0100\t0.0020\n"
      "0.033\t0.0110\t\n"
      "0.067\t0.0125\t0.0021\n");
  EXPECT_EQ(m.title, "mass A");
  EXPECT_EQ(m.t, (std::vector<double>{0.0, 0.067}));
  EXPECT_EQ(m.x, (std::vector<double>{0.0100, 0.0125}));
  EXPECT_EQ(m.y, (std::vector<double>{0.0020, 0.0021}));
  EXPECT_EQ(m.skipped, 1);
  EXPECT_EQ(m.line, (std::vector<long long>{3, 5}));
}

TEST(MeasuredMotion, SpacesCommentsSuffixesAndIgnoredColumns) {
  // non-uniform time stamps, "x_mm" and "t/s" suffixes, a frame column nobody asked for,
  // missing markers nan / NA / - and a short row: four rows skipped
  const MeasuredMotion m = parse(
      "# exported 2026-12-03\n"
      "\n"
      "frame   t/s    x_mm   table_x_mm\n"
      "1       0.0    0.0    0.0\n"
      "2       0.001  0.25   nan\n"
      "3       0.003  0.5    NA\n"
      "# a comment between rows\n"
      "4       0.004  -      0.1\n"
      "5       0.010\n"
      "6       0.011  0.75   0.2\n");
  EXPECT_EQ(m.t, (std::vector<double>{0.0, 0.011}));
  EXPECT_DOUBLE_EQ(m.x[1], 0.75e-3);
  EXPECT_DOUBLE_EQ(m.table_position[1], 0.2e-3);
  EXPECT_EQ(m.skipped, 4);
  EXPECT_EQ(m.ignored_columns, (std::vector<std::string>{"frame"}));
  EXPECT_TRUE(m.y.empty());
  EXPECT_TRUE(m.angle.empty());
}

TEST(MeasuredMotion, BadInputNamesTheFileAndLine) {
  // no time column anywhere
  EXPECT_NE(error_of("a,x\n1,2\n").find("time column"), std::string::npos);
  EXPECT_NE(error_of("").find("time column"), std::string::npos);
  // time that does not increase, named by its line and the previous sample's
  const std::string back = error_of("t,x\n0,0\n0.2,1\n0.1,2\n");
  EXPECT_NE(back.find("run.csv:4 time"), std::string::npos) << back;
  EXPECT_NE(back.find("at line 3"), std::string::npos) << back;
  EXPECT_NE(error_of("t,x\n0,0\n0,1\n").find("run.csv:3 time"), std::string::npos);
  // a field that is text
  EXPECT_NE(error_of("t,x\n0,0\n1,abc\n").find("run.csv:3 column 2"), std::string::npos);
  // an unknown unit, with the allowed ones
  const std::string unit = error_of("t [h],x\n0,0\n");
  EXPECT_NE(unit.find("must be one of: s, ms, us, min"), std::string::npos) << unit;
  // a quantity twice, no x, no complete row, data before the header, too many fields
  EXPECT_NE(error_of("t,x,position\n0,0,0\n").find("column 3"), std::string::npos);
  EXPECT_NE(error_of("t,y\n0,0\n").find("no x column"), std::string::npos);
  EXPECT_NE(error_of("t,x\n0,\n").find("at least one complete row"), std::string::npos);
  EXPECT_NE(error_of("0,1\nt,x\n").find("run.csv:1"), std::string::npos);
  EXPECT_NE(error_of("t,x\n0,1,2\n").find("has 3 fields"), std::string::npos);
  // every message is one line
  for (const std::string& e : {back, unit}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(MeasuredMotion, AMissingFileIsNamed) {
  try {
    read_measured_motion("/nonexistent/run.csv");
    FAIL();
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/run.csv"), std::string::npos);
  }
}


// The side file's units: parsed, applied by column name, and checked against the header.
MeasuredMotion parse_with(const std::string& text, const std::string& units_text) {
  std::istringstream u(units_text);
  const auto units = parse_measured_units(u, "run.csv.units");
  std::istringstream in(text);
  return parse_measured_motion(in, "run.csv", units, "run.csv.units");
}

std::string side_error(const std::string& text, const std::string& units_text) {
  try {
    parse_with(text, units_text);
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "";
}

TEST(MeasuredMotion, ASideFileGivesTheUnitsTheHeaderCannotCarry) {
  const MeasuredMotion m = parse_with("t x angle\n0 2 180\n40 3 90\n",
                                      "# tracker export units\nt = ms\nx = \"mm\"\nangle = deg\n");
  EXPECT_DOUBLE_EQ(m.t[1], 0.04);
  EXPECT_DOUBLE_EQ(m.x[0], 2e-3);
  EXPECT_DOUBLE_EQ(m.angle[0], std::acos(-1.0));
  // the same unit in both places is fine; a different one is an error naming both
  EXPECT_DOUBLE_EQ(parse_with("t,x [mm]\n0,5\n", "x = mm\n").x[0], 5e-3);
  const std::string clash = side_error("t,x [mm]\n0,5\n", "x = cm\n");
  EXPECT_NE(clash.find("run.csv.units x = cm: disagrees with the header's unit 'mm'"),
            std::string::npos) << clash;
  EXPECT_NE(side_error("t,x\n0,5\n", "y = mm\n").find("does not have"), std::string::npos);
  EXPECT_NE(side_error("t,x\n0,5\n", "x mm\n").find("run.csv.units:1"), std::string::npos);
  EXPECT_NE(side_error("t,x\n0,5\n", "x = mm\nx = cm\n").find("run.csv.units:2"),
            std::string::npos);
  EXPECT_NE(side_error("t,x\n0,5\n", "x = parsec\n").find("must be one of: m, cm, mm, um"),
            std::string::npos);
}

}  // namespace measured_motion_test
}  // namespace selfalign
