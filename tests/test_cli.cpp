// Tests of the `selfalign simulate` command through the real binary (SELFALIGN_CLI_PATH), each
// in a fresh temporary directory: exit codes, the one-line error report, no output left behind
// on error, and the outputs of good runs (CSV, JSON summary, config files, SI units, methods).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"
#include "selfalign/error.hpp"
#include "selfalign/units.hpp"
#include "temp_dir.hpp"

namespace selfalign {
namespace {

#ifndef SELFALIGN_CLI_PATH
TEST(CliSimulate, NeedsTheCli) { GTEST_SKIP() << "built without the CLI (SELFALIGN_BUILD_CLI=OFF)"; }
#else

using nlohmann::json;
using testing::CliResult;
using testing::CliSandbox;
using testing::csv_field;
using testing::csv_text;
using testing::kSiAgreement;
using testing::num;
using testing::expect_clean_failure;
using testing::MisuseCase;
using testing::lines;
using testing::read_text;
using testing::write_text;

// The exact solver computes the same arcs from SI inputs converted to [-] as from [-] inputs;
// only the conversions' rounding differs (a few ulps), far below this.
// Moreau time-stepping is first order; with h = 1e-3 over 2 periods it stays within 1e-4 of the
// exact solution here (observed 4e-5), so 1e-3 is a safe bound that still catches a wrong model.
constexpr double kTimeSteppingAgreement = 1e-3;


// ---------------------------------------------------------------------------------------------
// Misuse: exit code 2, one line on stderr naming the parameter and its range, no file written.

// simulate's misuse cases may also carry a config file, written to the sandbox root.
struct ConfigMisuseCase {
  std::string name;
  std::vector<std::string> args;
  std::string config_name, config_text;     // written to the sandbox root when non-empty
  std::vector<std::string> expected;        // substrings of the error line
};

void PrintTo(const ConfigMisuseCase& c, std::ostream* os) { *os << c.name; }

class CliMisuse : public ::testing::TestWithParam<ConfigMisuseCase> {};

TEST_P(CliMisuse, ExitsTwoWithOneLineAndWritesNothing) {
  const ConfigMisuseCase& c = GetParam();
  CliSandbox box;
  std::vector<std::string> args = {"simulate"};
  if (!c.config_name.empty()) {
    write_text(box.file(c.config_name), c.config_text);
    args.insert(args.end(), {"--config", box.file(c.config_name)});
  }
  args.insert(args.end(), c.args.begin(), c.args.end());
  args.insert(args.end(), {"--out", "run.csv"});
  expect_clean_failure(box, box.run(args), c.expected);
}

const ConfigMisuseCase kMisuseCases[] = {
    {"width_zero", {"--width", "0"}, "", "", {"width = 0", "must be > 0"}},
    {"width_negative", {"--width", "-0.01"}, "", "", {"width = -0.01", "must be > 0"}},
    {"width_negative_si", {"--units", "si", "--width", "-0.002"}, "", "",
     {"width = -0.002 [m]", "must be > 0"}},
    {"c_mu_one", {"--c-mu", "1"}, "", "", {"c_mu = 1", "must be > 1"}},
    {"c_mu_below_one", {"--c-mu", "0.5"}, "", "", {"c_mu = 0.5", "must be > 1"}},
    {"period_zero", {"--period", "0"}, "", "", {"period = 0", "must be > 0"}},
    {"period_negative", {"--period", "-1"}, "", "", {"period = -1", "must be > 0"}},
    // NaN is refused like 1e60, before any key's own range (issue 20, D35).
    {"width_nan", {"--width", "nan"}, "", "", {"--width = nan", "finite", "1e50"}},
    {"c_mu_nan", {"--c-mu", "nan"}, "", "", {"--c-mu = nan", "finite", "1e50"}},
    {"periods_zero", {"--periods", "0"}, "", "", {"periods = 0", "must be > 0"}},
    {"units_unknown", {"--units", "imperial"}, "", "", {"units = imperial", "dimensionless, si"}},
    {"profile_unknown", {"--profile", "square"}, "", "", {"profile = square", "three-phase"}},
    {"friction_unknown", {"--friction", "sticky"}, "", "", {"friction = sticky", "two-region"}},
    {"width_not_a_number", {"--width", "wide"}, "", "", {"width = wide", "must be a number"}},
    {"case0_profile", {"--a2", "0.5", "--a3", "0.5"}, "", "",
     {"a2, a3", "case 0", "1/a2 + 1/a3 <= period^2/(8 stroke)"}},
    {"unknown_key_json", {}, "c.json", R"({"width": 0.05, "widht": 0.05})",
     {"config key = widht", "unknown key", "did you mean width?", "docs/config.md"}},
    {"unknown_key_toml", {}, "c.toml", "width = 0.05\nwidht = 0.05\n",
     {"config key = widht", "unknown key", "did you mean width?"}},
    // Issue 9: D10 (a number beyond a double), D16 (a huge value is not echoed whole), D12 and
    // D09 (an unresolvable friction transition), D13 (a number beyond ±1e50), D07 (samples
    // whose acceleration does not integrate to zero name the file).
    {"json_number_overflow", {}, "c.json", R"({"width": 1e999})",
     {"config file", "c.json", "number overflow"}},
    {"huge_value_cut", {}, "c.json", "{\"units\": \"" + std::string(100000, 'x') + "\"}",
     {"units = xxx", "(100000 characters)"}},
    {"c_mu_unresolvable", {"--c-mu", "3e16"}, "", "", {"c_mu, width", "1e12"}},
    {"width_denormal", {"--width", "1e-320"}, "", "", {"width = 1e-320", "resolvable"}},
    {"velocity_beyond_1e50", {"--v0", "1e308"}, "", "", {"--v0 = 1e308", "1e50"}},  // as given
    {"negative_duration_named", {"--profile", "quadratic-sequence", "--durations", "-0.3,0.4,0.9",
                                 "--accelerations", "0,-3,4"}, "", "", {"durations[0] = -0.3"}},
    {"deep_json", {}, "deep.json",
     "{\"width\": " + std::string(60000, '[') + "1" + std::string(60000, ']') + "}",
     {"config file", "deep.json", "nests too deeply"}},
    {"malformed_json", {}, "bad.json", "{\"width\": 0.05,\n\"c_mu\": }\n",
     {"config file", "bad.json", "not valid JSON at line 2, column 9"}},
    {"malformed_toml", {}, "bad.toml", "width = 0.05\nc_mu = = 2\n",
     {"config file", "bad.toml", "line 2"}},
    {"wrong_type_json", {}, "c.json", R"({"width": "wide"})", {"width", "must be a number"}},
    {"wrong_type_toml", {}, "c.toml", "durations = 0.5\n", {"durations", "array of numbers"}},
    {"value_from_config_file", {}, "c.toml", "c_mu = 0.9\n", {"c_mu = 0.9", "must be > 1"}},
    {"missing_config_file", {"--config", "nowhere.json"}, "", "", {"config file", "nowhere.json"}},
    {"unknown_flag", {"--widht", "0.05"}, "", "", {"--widht"}},
};

INSTANTIATE_TEST_SUITE_P(Simulate, CliMisuse, ::testing::ValuesIn(kMisuseCases),
                         [](const auto& test) { return test.param.name; });

TEST(CliSimulate, FailedRunKeepsAnExistingOutputUntouched) {
  CliSandbox box;
  write_text(box.work_file("run.csv"), "old");
  const CliResult r = box.run({"simulate", "--width", "0", "--out", "run.csv"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_text(box.work_file("run.csv")), "old");
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"run.csv"});
}

// ---------------------------------------------------------------------------------------------
// Good runs.

TEST(CliSimulate, HelpAndVersionExitZero) {
  CliSandbox box;
  CliResult r = box.run({"simulate", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* flag : {"--width", "--c-mu", "--period", "--stroke", "--a2", "--a3", "--x-mu",
                           "--method", "--step", "--periods", "--units", "--out", "--summary",
                           "--config", "--output-step", "--length-scale"})
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
  r = box.run({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("selfalign ", 0), 0u) << r.out;
  r = box.run({});  // no subcommand: misuse
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
}

TEST(CliSimulate, DefaultRunWritesCsvAndSummaryBesideIt) {
  CliSandbox box;
  const CliResult r = box.run({"simulate", "--out", "run.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"run.csv", "run.summary.json"}));

  const std::vector<std::string> rows = lines(read_text(box.work_file("run.csv")));
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0], "t,x,x_dot,y,y_dot,y_ddot,stick");
  // Exact solver, default output step Δt/200 over 20 periods: 4000 intervals -> 4001 samples
  // (t = 0 .. 20), possibly one more when rounding puts the last grid point before the end.
  EXPECT_GE(rows.size() - 1, 4001u);
  EXPECT_LE(rows.size() - 1, 4002u);
  EXPECT_EQ(csv_field(rows[1], 0), 0.0);
  EXPECT_EQ(csv_field(rows.back(), 0), 20.0);

  const json s = json::parse(read_text(box.work_file("run.summary.json")));
  for (const char* key : {"units", "method", "profile", "friction", "initial", "final", "periods",
                          "arcs", "mean_velocity_last_period", "stick_fraction", "scales",
                          "trajectory_file"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["units"], "dimensionless");
  EXPECT_EQ(s["method"], "exact");
  EXPECT_EQ(s["profile"]["kind"], "three-phase");
  EXPECT_EQ(s["profile"]["a2"], 2.3);
  EXPECT_EQ(s["friction"]["width"], 0.05);
  EXPECT_EQ(s["periods"], 20.0);
  EXPECT_EQ(s["trajectory_file"], "run.csv");
  EXPECT_EQ(s["final"]["x"].get<double>(), csv_field(rows.back(), 1));  // same number, both files
  EXPECT_GT(s["arcs"].get<int>(), 0);
}

TEST(CliSimulate, SummaryGoesToStdoutWithoutOutOrWithDash) {
  CliSandbox box;
  CliResult r = box.run({"simulate", "--periods", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(box.work_entries().empty());
  EXPECT_TRUE(json::parse(r.out)["trajectory_file"].is_null());

  r = box.run({"simulate", "--periods", "2", "--out", "run.csv", "--summary", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"run.csv"});
  EXPECT_EQ(json::parse(r.out)["trajectory_file"], "run.csv");

  r = box.run({"simulate", "--periods", "2", "--summary", "s.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"run.csv", "s.json"}));
}

const char kJsonConfig[] = R"({
  "profile": "three-phase", "period": 1.05, "stroke": 0.084, "a2": 2.2, "a3": 0.9,
  "width": 0.04, "x_mu": 0.4, "c_mu": 2.5, "x0": 0.1, "periods": 6
})";
const char kTomlConfig[] = R"(profile = "three-phase"
period = 1.05
stroke = 0.084
a2 = 2.2
a3 = 0.9
width = 0.04
x_mu = 0.4
c_mu = 2.5
x0 = 0.1
periods = 6
)";

TEST(CliSimulate, JsonAndTomlConfigsGiveIdenticalResults) {
  CliSandbox box;
  write_text(box.file("c.json"), kJsonConfig);
  write_text(box.file("c.toml"), kTomlConfig);
  ASSERT_EQ(box.run({"simulate", "--config", box.file("c.json"), "--out", "a.csv"}).exit_code, 0);
  ASSERT_EQ(box.run({"simulate", "--config", box.file("c.toml"), "--out", "b.csv"}).exit_code, 0);
  EXPECT_EQ(read_text(box.work_file("a.csv")), read_text(box.work_file("b.csv")));
  json a = json::parse(read_text(box.work_file("a.summary.json")));
  json b = json::parse(read_text(box.work_file("b.summary.json")));
  EXPECT_EQ(a["friction"]["width"], 0.04);
  EXPECT_EQ(a["profile"]["period"], 1.05);
  a.erase("trajectory_file");
  b.erase("trajectory_file");
  EXPECT_EQ(a, b);
}

TEST(CliSimulate, FlagOverridesConfigValue) {
  CliSandbox box;
  write_text(box.file("c.toml"), kTomlConfig);
  const CliResult r = box.run({"simulate", "--config", box.file("c.toml"), "--width", "0.06"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = json::parse(r.out);
  EXPECT_EQ(s["friction"]["width"], 0.06);  // flag
  EXPECT_EQ(s["friction"]["x_mu"], 0.4);    // file
  EXPECT_EQ(s["profile"]["a2"], 2.2);       // file
  EXPECT_EQ(s["periods"], 6.0);             // file
}

TEST(CliSimulate, SiRunEqualsDimensionlessRunAfterConversion) {
  const double mu = 0.2, g = 9.8, L = 2e-3;
  const Scales scales(L, mu, g);
  const double T = std::sqrt(L / (mu * g)), V = L / T, A = mu * g;  // by hand (Sect. 3.2)
  ASSERT_DOUBLE_EQ(T, scales.time());
  CliSandbox box;
  const CliResult d = box.run({"simulate", "--period", "1.05", "--a2", "2.2", "--a3", "0.9",
                               "--x0", "0.3", "--v0", "0.1", "--width", "0.04", "--x-mu", "0.45",
                               "--periods", "8"});
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const CliResult si = box.run(
      {"simulate", "--units", "si", "--mu", num(mu), "--g", num(g), "--length-scale", num(L),
       "--period", num(1.05 * T), "--stroke", num(0.084 * L), "--a2", num(2.2 * A), "--a3",
       num(0.9 * A), "--x0", num(0.3 * L), "--v0", num(0.1 * V), "--width", num(0.04 * L),
       "--x-mu", num(0.45 * L), "--periods", "8"});
  ASSERT_EQ(si.exit_code, 0) << si.err;
  const json jd = json::parse(d.out), js = json::parse(si.out);
  EXPECT_EQ(js["units"], "si");
  EXPECT_DOUBLE_EQ(js["scales"]["time_s"].get<double>(), T);
  const double xd = jd["final"]["x"], xs = js["final"]["x"];
  EXPECT_NEAR(xs / L, xd, kSiAgreement * std::abs(xd));
  EXPECT_NEAR(js["final"]["t"].get<double>() / T, jd["final"]["t"].get<double>(),
              kSiAgreement * 8.4);
  EXPECT_NEAR(js["final"]["x_dot"].get<double>() / V, jd["final"]["x_dot"].get<double>(),
              kSiAgreement);
  EXPECT_NEAR(js["profile"]["t1"].get<double>() / T, jd["profile"]["t1"].get<double>(),
              kSiAgreement);
  EXPECT_EQ(js["arcs"], jd["arcs"]);
}

TEST(CliSimulate, SiDefaultsAreTheDimensionlessDefaultsConverted) {
  const double L = 2e-3;
  CliSandbox box;
  const CliResult d = box.run({"simulate", "--periods", "5"});
  const CliResult si = box.run({"simulate", "--periods", "5", "--units", "si", "--mu", "0.2",
                                "--g", "9.8", "--length-scale", num(L)});
  ASSERT_EQ(d.exit_code, 0) << d.err;
  ASSERT_EQ(si.exit_code, 0) << si.err;
  const double xd = json::parse(d.out)["final"]["x"], xs = json::parse(si.out)["final"]["x"];
  EXPECT_NEAR(xs / L, xd, kSiAgreement * std::abs(xd));
}

TEST(CliSimulate, TimeSteppingMethodAgreesWithExact) {
  CliSandbox box;
  const CliResult ts = box.run({"simulate", "--method", "time-stepping", "--periods", "2",
                                "--step", "1e-3", "--output-step", "0.01", "--out", "ts.csv"});
  ASSERT_EQ(ts.exit_code, 0) << ts.err;
  const CliResult ex = box.run({"simulate", "--periods", "2", "--summary", "-"});
  ASSERT_EQ(ex.exit_code, 0) << ex.err;
  const json s = json::parse(read_text(box.work_file("ts.summary.json")));
  EXPECT_EQ(s["method"], "time-stepping");
  EXPECT_EQ(s["steps"], 2000);  // 2 periods / h
  EXPECT_FALSE(s.contains("arcs"));
  EXPECT_NEAR(s["final"]["x"].get<double>(), json::parse(ex.out)["final"]["x"].get<double>(),
              kTimeSteppingAgreement);
  // Output every 0.01: 200 intervals -> 201 samples (t = 0 .. 2).
  const std::vector<std::string> rows = lines(read_text(box.work_file("ts.csv")));
  EXPECT_GE(rows.size() - 1, 201u);
  EXPECT_LE(rows.size() - 1, 202u);
}

#endif  // SELFALIGN_CLI_PATH

}  // namespace
}  // namespace selfalign
