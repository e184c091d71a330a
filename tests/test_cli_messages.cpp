// What `selfalign` says to its user (issue 20): NaN is refused like any other bad number and
// never means "not given" (D29); a value is checked whether the run uses its flag or not (D35);
// an error names the flag or key the user gave, not a library parameter it becomes (D32); a
// mistyped subcommand or flag gets a suggestion; a value that looks like millimetres or grams
// gets a warning; montecarlo without an uncertain input says so instead of running.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH
namespace selfalign {
namespace {

using testing::CliSandbox;
using testing::expect_clean_failure;
using testing::lines;

// A cheap montecarlo process (20 runs) and a cheap design grid.
const std::vector<std::string> kMonteCarlo = {
    "montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005", "--a2", "5", "--a3", "4",
    "--x-mu", "0.05", "--distance", "0.055", "--tolerance", "0.001", "--runs", "20", "--quiet"};
const std::vector<std::string> kDesign = {"design", "--acceleration-grid", "4", "--period-grid",
                                          "2", "--stroke-grid", "1", "--entries", "3", "--quiet"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

void expect_not_in_error(const testing::CliResult& r, const std::string& s) {
  EXPECT_EQ(r.err.find(s), std::string::npos) << r.err;
}

// D29: design --mu-static nan ran with static = kinetic; montecarlo --x-mu nan took the
// report's x_mu. Every number flag refuses NaN, naming itself and the range.
TEST(CliMessages, NanIsRefusedNeverReadAsNotGiven) {
  CliSandbox box;
  for (const char* flag : {"--mu-static", "--mu-backward", "--jerk-max"})
    expect_clean_failure(box, box.run(with(kDesign, {flag, "nan"})),
                         {std::string(flag) + " = nan", "finite", "1e50"});
  const auto mc = with(kMonteCarlo, {"--uncertain", "mu=normal:0.3,3%"});
  for (const char* flag : {"--mu-backward", "--x-mu", "--period-s", "--jerk"})
    expect_clean_failure(box, box.run(with(mc, {flag, "nan"})),
                         {std::string(flag) + " = nan", "finite"});
}

// D35: steady --width nan ran (width is unused by steady) while --width 1e60 was refused.
// Now steady offers no flag it would ignore: any value of one is refused, saying so.
TEST(CliMessages, UnusedValuesAreCheckedLikeUsedOnes) {
  CliSandbox box;
  for (const char* value : {"nan", "1e60", "-inf", "0.01"}) {
    expect_clean_failure(box, box.run({"steady", "--width", value}),
                         {"--width is not used by selfalign steady"});
    expect_clean_failure(box, box.run({"steady", "--x0", value}),
                         {"--x0 is not used by selfalign steady"});
  }
  // The same from a config file (TOML nan): the key is named.
  const std::string config = box.file("run.toml");
  std::ofstream(config) << "width = nan\n";
  expect_clean_failure(box, box.run({"steady", "--config", config}), {"width = nan", "1e50"});
  // Flags montecarlo and design take but do not use.
  expect_clean_failure(box, box.run(with(kMonteCarlo, {"--uncertain", "mu=normal:0.3,3%",
                                                       "--stroke-max", "nan"})),
                       {"--stroke-max = nan"});
  expect_clean_failure(box, box.run(with(kDesign, {"--time-quantile", "nan"})),
                       {"--time-quantile = nan"});
}

// D32: each message names what the user gave.
TEST(CliMessages, ErrorsNameTheFlagOrKeyGivenNotALibraryParameter) {
  CliSandbox box;
  // A coefficient checked as given, not as its ratio to mu under the library's name.
  const auto backward = box.run({"steady", "--mu-backward", "1e-300"});
  expect_clean_failure(box, backward, {"mu_backward = 1e-300", "[1e-50, 1e50]"});
  expect_not_in_error(backward, "mu_kinetic");
  // The field's interpolation is field_interpolation (interpolation is the samples' key).
  const std::string field = box.file("f.csv");
  std::ofstream(field) << "position,level\n0,1\n1,2\n";
  expect_clean_failure(box,
                       box.run({"simulate", "--friction", "field", "--field-file", field,
                                "--field-interpolation", "cubic"}),
                       {"field_interpolation = cubic", "steps, linear"});
  // optimize: the backward coefficient is blamed, not the static one.
  const auto optimize = box.run({"optimize", "--mu", "0.3", "--mu-backward", "0.5", "--quiet"});
  expect_clean_failure(box, optimize, {"mu-backward = 0.5", "<= mu_static"});
  // A gap between breakpoints too short for its acceleration change is the gap's.
  const auto times = box.run({"simulate", "--profile", "piecewise-linear", "--times", "0,5e-324",
                              "--accelerations", "1,-1", "--period", "1"});
  expect_clean_failure(box, times, {"times[1] = 5e-324", "too close to times[0]"});
  expect_not_in_error(times, "accels");
  // The summary's own flag when its folder is missing.
  expect_clean_failure(box,
                       box.run({"sweep", "period", "--range", "0.5:2:3", "--quiet", "--out",
                                "o.csv", "--summary", "nodir/s.json"}),
                       {"summary = nodir/s.json"});
  // Uncertain inputs whose draws give no process name the input, not the model's width or period.
  const auto mc = with(kMonteCarlo, {"--uncertain"});
  const auto offset = box.run(with(mc, {"x_mu_offset=normal:0,1e40"}));
  expect_clean_failure(box, offset, {"invalid x_mu_offset.", "draws this far give no process"});
  const auto width = box.run(with(mc, {"width=samples:1e-300,2e-300"}));
  expect_clean_failure(box, width, {"invalid width.lower = 1e-300", "no process"});
}

TEST(CliMessages, PlanarConfigErrorsNameSectionAndKey) {
  CliSandbox box;
  const std::string head =
      "units = \"dimensionless\"\n[table.x]\nprofile = \"fourier\"\nperiod = 1.0\n";
  const std::string part = "[part]\nmass = 1.0\ninertia = 0.01\nshape = \"points\"\n"
                           "xs = [0.0, 0.1]\nys = [0.0, 0.0]\n";
  const std::string run = "[run]\nstep = 0.02\nperiods = 3\n";
  const std::string zero = box.file("zero.toml"), loads = box.file("loads.toml");
  std::ofstream(zero) << head << "cos = [0.0]\nsin = [0.0]\n" << part << "loads = [0.5, 0.5]\n" << run;
  std::ofstream(loads) << head << "cos = [0.01]\nsin = [0.0]\n" << part << "loads = [0.5, nan]\n" << run;
  expect_clean_failure(box, box.run({"planar", "simulate", "--config", zero}),
                       {"table.x.cos, table.x.sin = all zero"});
  expect_clean_failure(box, box.run({"planar", "simulate", "--config", loads}),
                       {"part.loads = nan"});
}

TEST(CliMessages, TyposGetASuggestion) {
  CliSandbox box;
  expect_clean_failure(box, box.run({"desing"}),
                       {"unknown subcommand desing (did you mean design?)"});
  expect_clean_failure(box, box.run({"sweep", "acelerations"}),
                       {"did you mean accelerations?"});
  expect_clean_failure(box, box.run({"simulate", "--c_mu", "2"}),
                       {"unknown flag --c_mu (did you mean --c-mu?)"});
  // A config key the command does not read has no flag there, and the message says so.
  for (const char* flag : {"--c-mu", "--c_mu"})
    expect_clean_failure(box, box.run({"steady", flag, "2"}),
                         {"--c-mu is not used by selfalign steady"});
  expect_clean_failure(box, box.run({"sweep", "accelerations", "--x-mu", "1", "--a2-range",
                                     "1:2:2", "--a3-range", "1:2:2"}),
                       {"--x-mu is not used by selfalign sweep accelerations"});
  expect_clean_failure(box, box.run({"planar", "stedy", "--config", "x.toml"}),
                       {"did you mean steady?"});
  // A retired flag says what replaced it.
  expect_clean_failure(box, box.run({"optimize", "--static-ratio", "1.2"}),
                       {"--static-ratio", "replaced by --mu-static"});
  // Nothing close: CLI11's own message.
  expect_clean_failure(box, box.run({"steady", "--zzzzzzzz", "1"}), {"zzzzzzzz"});
}

// A warning never comes with an error, and a run without anything to say prints nothing.
TEST(CliMessages, ValuesThatLookLikeMillimetresOrGramsGetAWarning) {
  CliSandbox box;
  const auto si = box.run({"simulate", "--units", "si", "--width", "3", "--periods", "1"});
  ASSERT_EQ(si.exit_code, 0) << si.err;
  ASSERT_EQ(lines(si.err).size(), 1u) << si.err;
  EXPECT_EQ(si.err.rfind("selfalign: warning: width = 3 m looks like millimetres", 0), 0u)
      << si.err;
  const auto mc = box.run(with(kMonteCarlo, {"--uncertain", "mu=normal:0.3,3%", "--mass", "20"}));
  ASSERT_EQ(mc.exit_code, 0) << mc.err;
  EXPECT_NE(mc.err.find("selfalign: warning: --mass = 20 kg looks like grams"), std::string::npos)
      << mc.err;
  // Dimensionless widths are no metres: no warning; a failing run: its error line only.
  const auto plain = box.run({"simulate", "--width", "3", "--periods", "1"});
  ASSERT_EQ(plain.exit_code, 0);
  EXPECT_TRUE(plain.err.empty()) << plain.err;
  expect_clean_failure(box, box.run({"simulate", "--units", "si", "--width", "3",
                                     "--jerk", "-1"}),
                       {"jerk = -1"});
}

TEST(CliMessages, MonteCarloWithoutAnUncertainInputSaysSo) {
  CliSandbox box;
  expect_clean_failure(box, box.run(kMonteCarlo), {"uncertain = none", "nominal run"});
  expect_clean_failure(box, box.run(with(kMonteCarlo, {"--uncertain", "mu=known"})),
                       {"uncertain = none"});
}

}  // namespace
}  // namespace selfalign
#endif  // SELFALIGN_CLI_PATH
