// CLI tests for the friction law, the jerk limit and the friction field: bad inputs exit 2 with
// one line naming the parameter and its allowed range and write nothing; good ones reach the
// reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"

using selfalign::testing::CliSandbox;
using selfalign::testing::expect_clean_failure;

namespace {
std::string write(const CliSandbox& box, const std::string& name, const std::string& text) {
  const std::string path = box.file(name);  // outside the work directory, which must stay empty
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST(CliLaw, StaticBelowKineticIsRefused) {
  CliSandbox box;
  expect_clean_failure(box, box.run({"steady", "--mu-static", "0.2", "--out", "s.json"}),
                       {"mu_static = 0.2", "must be >= mu = 0.3"});
  expect_clean_failure(box, box.run({"simulate", "--mu-backward", "0.5", "--out", "t.csv"}),
                       {"mu_backward = 0.5", "<= mu_static"});
}

TEST(CliLaw, NegativeOrTooLowJerkIsRefused) {
  CliSandbox box;
  expect_clean_failure(box, box.run({"steady", "--jerk", "-1", "--out", "s.json"}),
                       {"jerk = -1", "must be > 0"});
  expect_clean_failure(box, box.run({"floquet", "--jerk", "1", "--out", "f.json"}),
                       {"jerk = 1", "need jerk >= 10.03"});
  expect_clean_failure(box, box.run({"simulate", "--jerk", "0", "--out", "t.csv"}),
                       {"jerk = 0", "must be > 0"});
}

TEST(CliLaw, BadFrictionFieldFilesAreRefusedNamingFileAndLine) {
  CliSandbox box;
  const std::string nan = write(box, "nan.csv", "position,level\n0.5,1\n0.6,nan\n");
  const std::string neg = write(box, "neg.csv", "position,level\n0.5,1\n0.6,-2\n");
  const std::string uns = write(box, "uns.csv", "position,level\n0.6,1\n0.5,2\n");
  expect_clean_failure(
      box, box.run({"simulate", "--friction", "field", "--field-file", nan, "--out", "t.csv"}),
      {"nan.csv:3 level = nan", "finite"});
  expect_clean_failure(
      box, box.run({"simulate", "--friction", "field", "--field-file", neg, "--out", "s.csv"}),
      {"neg.csv:3 level = -2", ">= 0"});
  expect_clean_failure(
      box, box.run({"simulate", "--friction", "field", "--field-file", uns, "--summary", "s.json"}),
      {"uns.csv:3 position = 0.5", "strictly increasing"});
}

// A field file equal to the paper's step (1 before x_mu = 0.5, 2.5 after) under a uniform
// footprint of width w is the two-region table: the same final state to the last digits.
TEST(CliLaw, StepFieldUnderAUniformFootprintIsTheTwoRegionTable) {
  CliSandbox box;
  const std::string step = write(box, "step.csv", "position,level\n0.0,1\n0.5,2.5\n");
  const auto a = box.run({"simulate", "--friction", "field", "--field-file", step, "--summary",
                          "-", "--periods", "30"});
  const auto b = box.run({"simulate", "--summary", "-", "--periods", "30"});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_NEAR(ja["final"]["x"].get<double>(), jb["final"]["x"].get<double>(), 1e-12);
  EXPECT_EQ(ja["friction"]["kind"], "field");
}

TEST(CliLaw, SteadyReportsTheLawThePatternAndTheJerk) {
  CliSandbox box;
  const auto r = box.run({"steady", "--json", "--mu-static", "0.4", "--jerk", "50"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["law"]["static"].get<double>(), 0.4 / 0.3, 1e-15);
  EXPECT_EQ(j["jerk"].get<double>(), 50.0);
  EXPECT_EQ(j["profile"], "jerk-limited-three-phase");
  EXPECT_TRUE(j["case_a_priori"].is_null());
  EXPECT_FALSE(j["pattern"].get<std::string>().empty());
}

// design --jerk-max: the recommended motion is jerk-limited. Checked on the profile CSV the
// controller gets (an independent reading): |Δy''/Δt| between samples never exceeds the limit,
// and reaches it on the ramps (to the sampling's resolution).
TEST(CliLaw, DesignUnderAJerkLimitRecommendsARampedProfile) {
  CliSandbox box;
  const std::string csv = box.file("profile.csv");
  // A coarse search (it is the profile's jerk that is checked, not the optimum): 0.1 s, not 2.
  const auto r = box.run({"design", "--json", "--jerk-max", "2000", "--acceleration-grid", "8",
                          "--period-grid", "3", "--stroke-grid", "1", "--entries", "10",
                          "--profile-csv", csv, "--sample-rate", "20000"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["profile"]["kind"], "jerk-limited-three-phase");
  EXPECT_EQ(j["profile"]["jerk_m_per_s3"].get<double>(), 2000.0);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  double t0 = 0, a0 = 0, peak = 0;
  bool first = true;
  while (std::getline(in, line)) {
    double t, y, yd, ydd;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &t, &y, &yd, &ydd), 4) << line;
    if (!first) peak = std::max(peak, std::abs(ydd - a0) / (t - t0));
    first = false;
    t0 = t, a0 = ydd;
  }
  EXPECT_LE(peak, 2000.0 * (1 + 1e-6));
  EXPECT_GE(peak, 2000.0 * 0.99);
}

// Stribeck and viscous laws: bad values name the key and its range; a good one runs the slip
// integrator, and every report says so and carries the integrator's statistics.
TEST(CliLaw, StribeckAndViscousBadValuesAreRefused) {
  CliSandbox box;
  expect_clean_failure(box, box.run({"simulate", "--stribeck-velocity", "0", "--out", "t.csv"}),
                       {"stribeck_velocity = 0", "must be > 0"});
  expect_clean_failure(box, box.run({"steady", "--stribeck-velocity", "0.01",
                                     "--stribeck-exponent", "-1", "--out", "s.json"}),
                       {"stribeck_exponent = -1", "(0, 100]"});
  expect_clean_failure(box, box.run({"floquet", "--viscous", "-0.5", "--out", "f.json"}),
                       {"viscous = -0.5", "[0, 1e50]"});
  expect_clean_failure(box, box.run({"simulate", "--relative-tolerance", "1", "--out", "t.csv"}),
                       {"relative_tolerance = 1", "(0, 1)"});
  expect_clean_failure(box, box.run({"stop", "--absolute-tolerance", "0", "--out", "t.csv"}),
                       {"absolute_tolerance = 0", "(0, 1)"});
  expect_clean_failure(box, box.run({"optimize", "--family", "fourier", "--order", "2.5"}),
                       {"--order", "not a whole number", "[1, 100]"});
}

TEST(CliLaw, StribeckRunsReportTheIntegrator) {
  CliSandbox box;
  const std::vector<std::string> law = {"--mu-static", "0.39", "--stribeck-velocity", "0.01",
                                        "--viscous", "0.1", "--json"};
  for (const std::string command : {"steady", "floquet"}) {
    std::vector<std::string> args{command};
    args.insert(args.end(), law.begin(), law.end());
    const auto r = box.run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "integrator") << command;
    EXPECT_GT(j["integrator"]["steps"].get<long long>(), 0) << command;
    EXPECT_EQ(j["integrator"]["relative_tolerance"], 1e-10) << command;
    EXPECT_EQ(j["law"]["stribeck_velocity"], 0.01) << command;
  }
  const auto r = box.run({"simulate", "--friction", "uniform", "--mu-static", "0.39",
                          "--stribeck-velocity", "0.01", "--summary", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "integrator");
  EXPECT_GT(j["intervals"].get<long long>(), 0);
  EXPECT_TRUE(j["law"]["viscous"].is_null());
}

// D28 (issue 20): accumulation offered the law flags and ignored them (a report byte-identical
// to the paper's law). Eq. (59) is the paper's law's: the flags are gone from its --help, and
// a law from a config file is refused naming it, with no file written.
TEST(CliLaw, AccumulationRefusesALawItCannotTake) {
  CliSandbox box;
  const selfalign::testing::CliResult help = box.run({"accumulation", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--mu-static", "--mu-backward", "--stribeck-velocity", "--viscous"})
    EXPECT_EQ(help.out.find(flag), std::string::npos) << flag;
  EXPECT_EQ(box.run({"accumulation", "--viscous", "0.1", "--out", "m.csv"}).exit_code, 2);
  const std::string config = write(box, "law.toml", "stribeck_velocity = 0.01\n");
  expect_clean_failure(box, box.run({"accumulation", "--config", config, "--out", "m.csv"}),
                       {"invalid law", "paper's law only"});
}

// F07: the coefficients are absolute in every run, mu the kinetic one, whatever the unit
// system; reports give both the coefficients and their ratios (expected ratios: the quotients
// of the coefficients given, docs/config.md "Friction law").
TEST(CliLaw, CoefficientsAreAbsoluteWithMuTheKineticOneInEveryRun) {
  CliSandbox box;
  const std::vector<std::string> sequence = {"steady", "--profile", "quadratic-sequence",
                                             "--durations", "0.5,0.3,0.2", "--accelerations",
                                             "1,-5,5", "--json"};
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = sequence;
    args.insert(args.end(), more.begin(), more.end());
    return box.run(args);
  };
  const auto given = with({"--mu", "0.59", "--mu-static", "0.72"});
  ASSERT_EQ(given.exit_code, 0) << given.err;
  EXPECT_TRUE(given.err.empty()) << given.err;
  const auto law = nlohmann::json::parse(given.out)["law"];
  EXPECT_EQ(law["mu"].get<double>(), 0.59);
  EXPECT_DOUBLE_EQ(law["mu_static"].get<double>(), 0.72);  // mu x the ratio: to rounding
  EXPECT_EQ(law["mu_backward"].get<double>(), 0.59);
  EXPECT_DOUBLE_EQ(law["static"].get<double>(), 0.72 / 0.59);
  // The same coefficients in an SI run: the same ratio.
  const auto si = with({"--units", "si", "--mu", "0.59", "--mu-static", "0.72"});
  ASSERT_EQ(si.exit_code, 0) << si.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(si.out)["law"]["static"].get<double>(), 0.72 / 0.59);
  // Without --mu the default kinetic coefficient 0.3 is used, and a warning says so.
  const auto alone = with({"--mu-static", "0.72"});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(alone.out)["law"]["static"].get<double>(), 0.72 / 0.3);
  EXPECT_EQ(alone.err.rfind("selfalign: warning: mu_static = 0.72 is an absolute coefficient", 0),
            0u)
      << alone.err;
  EXPECT_NE(alone.err.find("mu = 0.3 (ratio 2.4)"), std::string::npos) << alone.err;
  // optimize takes the same three flags (its --static-ratio is gone).
  const auto opt = box.run({"optimize", "--family", "three-phase", "--starts", "1",
                            "--max-evaluations", "40", "--mu", "0.5", "--mu-static", "0.6",
                            "--mu-backward", "0.4", "--quiet", "--json"});
  ASSERT_EQ(opt.exit_code, 0) << opt.err;
  const auto olaw = nlohmann::json::parse(opt.out)["law"];
  EXPECT_DOUBLE_EQ(olaw["static"].get<double>(), 0.6 / 0.5);
  EXPECT_DOUBLE_EQ(olaw["kinetic_backward"].get<double>(), 0.4 / 0.5);
  EXPECT_DOUBLE_EQ(olaw["mu_static"].get<double>(), 0.6);
}
