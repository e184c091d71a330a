// Tests of the Sect. 7 subcommands (`stop`, `accuracy`, `accumulation`, `sweep positioning`)
// through the real binary (SELFALIGN_CLI_PATH), each in a fresh temporary directory: the keys
// scripts rely on, the library's established results seen through the front door (Sect. 7.2
// settings, Fig. 18 fixed point), determinism of the sweep for any thread count, and misuse
// (exit code 2, one line, no file left).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
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
TEST(CliStopping, NeedsTheCli) { GTEST_SKIP() << "built without the CLI (SELFALIGN_BUILD_CLI=OFF)"; }
#else

using nlohmann::json;
using testing::CliResult;
using testing::CliSandbox;
using testing::expect_clean_failure;
using testing::MisuseCase;
using testing::lines;
using testing::read_text;

// Eq. (60) and eq. (41) are the same position written two ways: (b2 + y2'')/b1 and
// x_mu + w (y2'' - 1)/(c_mu - 1); they differ by rounding of O(1) numbers only.
constexpr double kSameFormula = 1e-12;
// SI outputs are the dimensionless results times a scale: a few ulps.
constexpr double kSiAgreement = 1e-9;

json run_json(const CliSandbox& box, const std::vector<std::string>& args) {
  const CliResult r = box.run(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out);
}

void expect_keys(const json& j, const std::vector<const char*>& keys) {
  for (const char* key : keys) EXPECT_TRUE(j.contains(key)) << key;
}

// Column `column` of a CSV row, as text.
std::string csv_text(const std::string& row, int column) {
  std::size_t begin = 0;
  for (int i = 0; i < column; ++i) begin = row.find(',', begin) + 1;
  return row.substr(begin, row.find(',', begin) - begin);
}

double csv_field(const std::string& row, int column) { return std::stod(csv_text(row, column)); }

// ---------------------------------------------------------------------------------------------
// accuracy

const std::vector<const char*> kAccuracyKeys = {
    "x_mu", "x_stick_min", "overshoot_min", "overshoot_max", "dx_d", "x_d", "accumulates",
    "v_bar", "case", "f", "x_dot_0s", "entries", "accumulating_entries", "all_stopped",
    "reaches"};

// Sect. 7.2, Fig. 16 upper plot: (y2'', y3'') = (2.3, 1.3) accumulates from every entry, so
// every end position is x_stick,min and Δx_d = 0 (established in tests/test_stopping.cpp).
TEST(CliAccuracy, AccumulationGivesZeroPositioningError) {
  CliSandbox box;
  const json j = run_json(box, {"accuracy", "--json", "--a2", "2.3", "--a3", "1.3"});
  expect_keys(j, kAccuracyKeys);
  EXPECT_EQ(j["accumulates"], true);
  EXPECT_EQ(j["dx_d"], 0.0);
  EXPECT_EQ(j["reaches"], true);
  EXPECT_EQ(j["all_stopped"], true);
  EXPECT_EQ(j["entries"], 100);  // the library's default N
  EXPECT_EQ(j["accumulating_entries"], 100);
  // x_d = x_mu + (x_stick,min - x_mu) + 0: x_stick,min up to rounding.
  EXPECT_NEAR(j["x_d"].get<double>(), j["x_stick_min"].get<double>(), kSameFormula);
  EXPECT_TRUE(box.work_entries().empty());
}

// Fig. 16 lower plot: (1.8, 1.1) overshoots x_stick,min: the end positions differ, Δx_d > 0.
TEST(CliAccuracy, OvershootGivesPositiveError) {
  CliSandbox box;
  const json j = run_json(box, {"accuracy", "--json", "--a2", "1.8", "--a3", "1.1"});
  expect_keys(j, kAccuracyKeys);
  EXPECT_EQ(j["accumulates"], false);
  EXPECT_GT(j["dx_d"].get<double>(), 0.0);
  EXPECT_EQ(j["accumulating_entries"], 0);
  // eq. (39) and x_d from the reported overshoots.
  const double lo = j["overshoot_min"], hi = j["overshoot_max"];
  EXPECT_DOUBLE_EQ(j["dx_d"].get<double>(), (hi - lo) / 2);
  EXPECT_DOUBLE_EQ(j["x_d"].get<double>(), j["x_mu"].get<double>() + lo + (hi - lo) / 2);
}

TEST(CliAccuracy, ProfileAndFrictionFlagsAndPerEntryCsv) {
  CliSandbox box;
  const CliResult r = box.run({"accuracy", "--period", "1", "--stroke", "0.084", "--a2", "2.3",
                               "--a3", "1.3", "--width", "0.05", "--c-mu", "2.5", "--entries",
                               "7", "--out", "e.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"e.csv", "e.summary.json"}));
  const json s = json::parse(read_text(box.work_file("e.summary.json")));
  EXPECT_EQ(s["entries"], 7);
  EXPECT_EQ(s["csv_file"], "e.csv");
  const std::vector<std::string> rows = lines(read_text(box.work_file("e.csv")));
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[0], "x0s,end_position,overshoot,stop,periods_p99,periods_p999");
  EXPECT_EQ(csv_field(rows[7], 0), 0.0);  // entries x_0s in [-v̄Δt, 0]
  EXPECT_NEAR(csv_field(rows[1], 0), -s["v_bar"].get<double>(), kSameFormula);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(csv_text(rows[i], 3), "accumulation") << rows[i];
    EXPECT_EQ(csv_field(rows[i], 1), s["x_stick_min"].get<double>()) << rows[i];
    EXPECT_GE(std::stoi(csv_text(rows[i], 5)), std::stoi(csv_text(rows[i], 4))) << rows[i];
  }
  // --json prints the report instead of writing it beside the CSV.
  const json printed = run_json(box, {"accuracy", "--entries", "7", "--json", "--out", "f.csv"});
  EXPECT_EQ(printed["csv_file"], "f.csv");
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"e.csv", "e.summary.json", "f.csv"}));
}

// ---------------------------------------------------------------------------------------------
// accumulation

// Fig. 18 setting: the fixed point of eq. (59) is x_stick,min (eq. 60 = eq. 41).
TEST(CliAccumulation, FixedPointIsStickPositionMinForFigure18) {
  CliSandbox box;
  const json j = run_json(box, {"accumulation", "--json", "--a2", "2.2", "--a3", "0.9",
                                "--period", "1.05"});
  expect_keys(j, {"fixed_point", "x_stick_min", "fixed_point_minus_x_stick_min",
                  "slope_at_fixed_point", "basin_lower_bound", "accumulates_for_every_entry",
                  "map_at_x_mu", "iterates"});
  EXPECT_LT(std::abs(j["fixed_point"].get<double>() - j["x_stick_min"].get<double>()),
            kSameFormula);
  EXPECT_LT(std::abs(j["fixed_point_minus_x_stick_min"].get<double>()), kSameFormula);
  // Sect. 7.3: accumulation from every entry iff x_{n+1}(x_mu) < x_stick,min.
  EXPECT_EQ(j["accumulates_for_every_entry"].get<bool>(),
            j["map_at_x_mu"].get<double>() < j["x_stick_min"].get<double>());
  const json& it = j["iterates"];
  EXPECT_EQ(it["x1"], 0.5);  // default x1 = x_mu
  EXPECT_EQ(it["positions"][0], 0.5);
  EXPECT_EQ(it["positions"][1], j["map_at_x_mu"]);
  ASSERT_EQ(it["fractions"].size(), 2u);
  EXPECT_EQ(it["fractions"][0]["p"], 0.99);
}

// Issue 9 / F02: where Sect. 7.3's derivation does not hold, the condition is not applicable
// (null, with the reason), not "true": peak acceleration above c_mu (no x_stick,min, eq. 41)
// and y3'' > y2'' (the map's fixed point is not x_stick,min, eq. 60). The F02 reproducer's
// settings; `accuracy` agrees that no entry accumulates there.
TEST(CliAccumulation, EveryEntryConditionIsNullWhereItsDerivationDoesNotHold) {
  CliSandbox box;
  const std::vector<std::string> beyond_c_mu = {
      "--period", "0.60597757985852", "--stroke", "0.012412335492963484", "--a2",
      "8.508483283348117", "--a3", "1.2561507198610682", "--width", "0.06676181403696926",
      "--c-mu", "4.739200637052614"};
  const std::vector<std::vector<std::string>> outside = {beyond_c_mu,
                                                         {"--a2", "1.3", "--a3", "2.3"}};
  for (const auto& setting : outside) {
    std::vector<std::string> args = {"accumulation", "--json", "--x-mu", "0.008150211493444207"};
    args.insert(args.end(), setting.begin(), setting.end());
    const json j = run_json(box, args);
    EXPECT_TRUE(j["accumulates_for_every_entry"].is_null()) << j.dump();
    EXPECT_EQ(j["accumulation_condition_applies"], false);
    EXPECT_FALSE(j["accumulation_condition_reason"].get<std::string>().empty());
    std::vector<std::string> accuracy = {"accuracy", "--json", "--entries", "10"};
    accuracy.insert(accuracy.end(), setting.begin(), setting.end());
    const json a = run_json(box, accuracy);
    EXPECT_EQ(a["accumulates"], false);
    EXPECT_EQ(a["accumulating_entries"], 0);
  }
  // Inside the domain: the paper's condition (Sect. 7.2 upper plot) and no reason.
  const json in = run_json(box, {"accumulation", "--json", "--a2", "2.3", "--a3", "1.3"});
  EXPECT_EQ(in["accumulation_condition_applies"], true);
  EXPECT_EQ(in["accumulates_for_every_entry"], true);
  EXPECT_TRUE(in["accumulation_condition_reason"].is_null());
}

TEST(CliAccumulation, MapCsvOnTheGrid) {
  CliSandbox box;
  const CliResult r = box.run({"accumulation", "--n", "11", "--out", "m.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"m.csv", "m.summary.json"}));
  const std::vector<std::string> rows = lines(read_text(box.work_file("m.csv")));
  ASSERT_EQ(rows.size(), 12u);
  EXPECT_EQ(rows[0], "x_n,x_next,diagonal");
  EXPECT_EQ(csv_field(rows[1], 0), 0.5);   // default --from: x_mu
  EXPECT_EQ(csv_field(rows[11], 0), 0.55);  // default --to: x_mu + w
  const json s = json::parse(read_text(box.work_file("m.summary.json")));
  EXPECT_EQ(csv_field(rows[1], 1), s["map_at_x_mu"].get<double>());
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(csv_text(rows[i], 0), csv_text(rows[i], 2)) << rows[i];
}

// ---------------------------------------------------------------------------------------------
// stop

TEST(CliStop, DefaultRunAccumulatesAtStickPositionMin) {
  CliSandbox box;
  const json j = run_json(box, {"stop", "--json"});
  expect_keys(j, {"stop", "end_position", "process_time", "entry_time", "x_mu", "x_stick_min",
                  "stick_positions", "fractions"});
  EXPECT_EQ(j["stop"], "accumulation");
  EXPECT_EQ(j["end_position"], j["x_stick_min"]);
  EXPECT_TRUE(j["process_time"].is_null());  // reached only as t -> inf
  EXPECT_EQ(j["x_mu"], 0.5);
  EXPECT_GT(j["entry_time"].get<double>(), 0.0);
  EXPECT_FALSE(j["stick_positions"].empty());
  ASSERT_EQ(j["fractions"].size(), 2u);
  for (const json& p : j["fractions"]) {
    expect_keys(p, {"p", "time", "periods_from_entry"});
    EXPECT_GT(p["time"].get<double>(), j["entry_time"].get<double>());
    EXPECT_GE(p["periods_from_entry"].get<int>(), 1);
  }
}

TEST(CliStop, PermanentStickAndTrajectoryCsv) {
  CliSandbox box;
  // (1.8, 1.1) overshoots x_stick,min and sticks there for good (eq. 40).
  const CliResult r = box.run({"stop", "--a2", "1.8", "--a3", "1.1", "--out", "s.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"s.csv", "s.summary.json"}));
  const json j = json::parse(read_text(box.work_file("s.summary.json")));
  EXPECT_EQ(j["stop"], "permanent-stick");
  EXPECT_GE(j["end_position"].get<double>(), j["x_stick_min"].get<double>());
  EXPECT_EQ(j["csv_file"], "s.csv");
  const std::vector<std::string> rows = lines(read_text(box.work_file("s.csv")));
  ASSERT_GT(rows.size(), 2u);
  EXPECT_EQ(rows[0], "t,x,x_dot,stick");
  EXPECT_EQ(csv_field(rows[1], 0), 0.0);
  // The trajectory ends at the stop: at the end position, at the process time.
  EXPECT_NEAR(csv_field(rows.back(), 0), j["process_time"].get<double>(), kSameFormula);
  EXPECT_NEAR(csv_field(rows.back(), 1), j["end_position"].get<double>(), kSameFormula);
  EXPECT_EQ(csv_field(rows.back(), 2), 0.0);
}

TEST(CliStop, SiOutputIsTheDimensionlessResultConverted) {
  const double mu = 0.3, g = 9.81, L = 1e-3;
  const Scales sc(L, mu, g);
  CliSandbox box;
  const json d = run_json(box, {"stop", "--json"});
  const json si = run_json(box, {"stop", "--json", "--units", "si"});  // same physical run
  EXPECT_EQ(si["units"], "si");
  EXPECT_NEAR(si["end_position"].get<double>() / L, d["end_position"].get<double>(),
              kSiAgreement);
  EXPECT_NEAR(si["entry_time"].get<double>() / sc.time(), d["entry_time"].get<double>(),
              kSiAgreement * d["entry_time"].get<double>());
  EXPECT_EQ(si["fractions"][0]["periods_from_entry"], d["fractions"][0]["periods_from_entry"]);
}

// ---------------------------------------------------------------------------------------------
// sweep positioning

TEST(CliSweepPositioning, CsvIsIdenticalForAnyThreadCount) {
  CliSandbox box;
  const std::vector<std::string> grid = {"sweep", "positioning", "--a2-range", "1.8:2.4:3",
                                         "--a3-range", "0.8:1.4:3", "--entries", "5"};
  for (const char* threads : {"1", "2"}) {
    std::vector<std::string> args = grid;
    args.insert(args.end(), {"--threads", threads, "--out", std::string("t") + threads + ".csv"});
    const CliResult r = box.run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const std::string csv = read_text(box.work_file("t1.csv"));
  EXPECT_EQ(read_text(box.work_file("t2.csv")), csv);
  const std::vector<std::string> rows = lines(csv);
  ASSERT_EQ(rows.size(), 10u);
  EXPECT_EQ(rows[0], "a2,a3,case,f,accumulates,dx_d,accumulating_entries,max_periods_p99,"
                     "max_periods_p999,status");
  EXPECT_EQ(csv_field(rows[1], 0), 1.8);  // row-major, a2 outer
  EXPECT_EQ(csv_field(rows[3], 1), 1.4);
  const json s = json::parse(read_text(box.work_file("t1.summary.json")));
  EXPECT_EQ(s["sweep"], "positioning");
  EXPECT_EQ(s["cells"], 9);
  EXPECT_EQ(s["entries"], 5);
  EXPECT_EQ(s["max_periods"], 300);
  EXPECT_EQ(s["failures"]["count"], 0);  // every cell computed (F01: a failure has a status)
}

// ---------------------------------------------------------------------------------------------
// Misuse: exit code 2, one line on stderr, nothing on stdout, no file left behind.

class CliStoppingMisuse : public ::testing::TestWithParam<MisuseCase> {};

TEST_P(CliStoppingMisuse, ExitsTwoWithOneLineAndWritesNothing) {
  CliSandbox box;
  expect_clean_failure(box, box.run(GetParam().args), GetParam().expected);
}

const MisuseCase kMisuseCases[] = {
    {"accuracy_entries_zero", {"accuracy", "--entries", "0", "--out", "a.csv"},
     {"entries = 0", "[1, 1e5]"}},
    {"accuracy_width_negative", {"accuracy", "--width", "-1", "--out", "a.csv"},
     {"width = -1", "> 0"}},
    {"accuracy_c_mu_one", {"accuracy", "--c-mu", "1", "--out", "a.csv"}, {"c_mu = 1", "> 1"}},
    {"accuracy_case_zero", {"accuracy", "--a2", "0.5", "--a3", "0.5", "--out", "a.csv"},
     {"a2, a3", "case 0"}},
    {"accuracy_needs_piecewise_constant",
     {"accuracy", "--profile", "fourier", "--fourier-cos", "0.02", "--out", "a.csv"},
     {"profile = fourier", "piecewise-constant"}},
    {"accumulation_needs_three_phase",
     {"accumulation", "--profile", "quadratic-sequence", "--durations", "0.3,0.4,0.3",
      "--accelerations", "0,-3,4", "--out", "m.csv"},
     {"profile = quadratic-sequence", "three-phase"}},
    {"accumulation_grid_empty", {"accumulation", "--n", "0", "--out", "m.csv"}, {"n = 0"}},
    {"accumulation_width_negative", {"accumulation", "--width", "-1", "--out", "m.csv"},
     {"width = -1"}},
    {"stop_fraction_above_one", {"stop", "--fractions", "0.9,1.5", "--out", "s.csv"},
     {"fraction p = 1.5"}},
    {"stop_max_periods_zero", {"stop", "--max-periods", "0", "--out", "s.csv"},
     {"max_periods = 0"}},
    {"stop_c_mu_one", {"stop", "--c-mu", "1", "--out", "s.csv"}, {"c_mu = 1"}},
    {"stop_json_and_summary_file", {"stop", "--json", "--summary", "s.json"},
     {"summary = s.json", "--json"}},
    {"stop_si_width_restated", {"stop", "--units", "si", "--width", "-0.001", "--out", "s.csv"},
     {"width = -0.001 [m]"}},
    {"sweep_positioning_entries_zero",
     {"sweep", "positioning", "--a2-range", "1:2:2", "--a3-range", "1:2:2", "--entries", "0",
      "--out", "p.csv"},
     {"entries = 0"}},
    {"sweep_positioning_width_negative",
     {"sweep", "positioning", "--a2-range", "1:2:2", "--a3-range", "1:2:2", "--width", "-1",
      "--out", "p.csv"},
     {"width = -1"}},
    {"sweep_positioning_c_mu_one",
     {"sweep", "positioning", "--a2-range", "1:2:2", "--a3-range", "1:2:2", "--c-mu", "1",
      "--out", "p.csv"},
     {"c_mu = 1"}},
};

INSTANTIATE_TEST_SUITE_P(Stopping, CliStoppingMisuse, ::testing::ValuesIn(kMisuseCases),
                         [](const auto& test) { return test.param.name; });

// stop takes any friction field (issue 21): it ran on the default two-region table with the
// --field-file it offered silently ignored. A field of steps, level 1 then 3 from x = 0.3,
// averaged over the footprint w = 0.05 (eq. 7), is the two-region table (x_mu 0.3, c_mu 3):
// its x_stick,min is eq. (41)'s x_mu + w (y2'' - 1)/(c_mu - 1) = 0.3325 for the default
// y2'' = 2.3, and the run ends where `stop --x-mu 0.3 --c-mu 3` ends (at or beyond it).
TEST(CliStop, TakesAFieldAndEndsWhereTheEquivalentTwoRegionTableDoes) {
  CliSandbox box;
  const std::string field = box.file("field.csv");
  std::ofstream(field) << "0,1\n0.3,3\n";
  const CliResult on_field = box.run({"stop", "--field-file", field, "--json"});
  ASSERT_EQ(on_field.exit_code, 0) << on_field.err;
  const json f = json::parse(on_field.out);
  EXPECT_EQ(f["friction"]["kind"].get<std::string>(), "field");
  EXPECT_NEAR(f["x_mu"].get<double>(), 0.3, kSameFormula);  // the rise of the level
  EXPECT_TRUE(f["c_mu"].is_null());
  const double eq41 = 0.3 + 0.05 * (2.3 - 1) / (3 - 1);
  EXPECT_NEAR(f["x_stick_min"].get<double>(), eq41, kSameFormula);
  EXPECT_GE(f["end_position"].get<double>(), eq41);  // it stops at or beyond x_stick,min
  const CliResult two = box.run({"stop", "--x-mu", "0.3", "--c-mu", "3", "--json"});
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_NEAR(f["end_position"].get<double>(),
              json::parse(two.out)["end_position"].get<double>(), 1e-9);
  // accuracy takes the field where it stands (x_mu: its rise, 0.3) and, the table's motion
  // being the same everywhere, gives the two-region table's spread (placed at x_mu = dx) with
  // the ends moved by 0.3 - dx. The default y2'' = 2.3, y3'' = 1.3 accumulate (dx_d = 0).
  const CliResult acc_field =
      box.run({"accuracy", "--field-file", field, "--entries", "5", "--json"});
  ASSERT_EQ(acc_field.exit_code, 0) << acc_field.err;
  const CliResult acc_two = box.run({"accuracy", "--c-mu", "3", "--entries", "5", "--json"});
  ASSERT_EQ(acc_two.exit_code, 0) << acc_two.err;
  const json af = json::parse(acc_field.out), at = json::parse(acc_two.out);
  EXPECT_NEAR(af["x_mu"].get<double>(), 0.3, kSameFormula);
  EXPECT_NEAR(af["dx_d"].get<double>(), at["dx_d"].get<double>(), 1e-9);
  EXPECT_NEAR(af["x_d"].get<double>() - 0.3,
              at["x_d"].get<double>() - at["x_mu"].get<double>(), 1e-9);
  EXPECT_EQ(af["accumulates"], at["accumulates"]);
  // accumulation's closed form is the two-region table's (eq. 59): this field is that table (one
  // step from 1 to c_mu = 3 under the footprint w = 0.05), so its report is the two-region
  // flags' (second method) but for the field's own description; a field of two steps takes the
  // exact solver's map (below); a field key beside another friction map is refused.
  const CliResult acc_f = box.run({"accumulation", "--field-file", field, "--json"});
  const CliResult acc_t = box.run({"accumulation", "--x-mu", "0.3", "--c-mu", "3", "--json"});
  ASSERT_EQ(acc_f.exit_code, 0) << acc_f.err;
  ASSERT_EQ(acc_t.exit_code, 0) << acc_t.err;
  json from_field = json::parse(acc_f.out), from_flags = json::parse(acc_t.out);
  EXPECT_EQ(from_field["friction"]["kind"], "field");
  from_field.erase("friction");
  EXPECT_EQ(from_field, from_flags);
  EXPECT_EQ(from_flags["map"], "eq. 59");
  // A level of two ramps with a kink (no closed form): the exact solver's stick-position map.
  // Second method: the stopping run on the same field accumulates at the same x_stick,min, and
  // the map's iterates rise to it with shrinking steps.
  const std::string kink = box.file("kink.csv");
  std::ofstream(kink) << "position,level\n0.1,1\n0.125,1.9\n0.15,2.5\n";
  const CliResult acc_k = box.run({"accumulation", "--field-file", kink, "--json"});
  ASSERT_EQ(acc_k.exit_code, 0) << acc_k.err;
  const CliResult stop_k = box.run({"stop", "--field-file", kink, "--json"});
  ASSERT_EQ(stop_k.exit_code, 0) << stop_k.err;
  const json k = json::parse(acc_k.out), sk = json::parse(stop_k.out);
  EXPECT_EQ(k["map"], "exact solver");
  EXPECT_EQ(sk["stop"], "accumulation");
  EXPECT_EQ(k["fixed_point"], sk["x_stick_min"]);
  EXPECT_EQ(k["x_stick_min"], sk["x_stick_min"]);
  EXPECT_NEAR(k["fixed_point"].get<double>(), sk["end_position"].get<double>(), 1e-12);
  EXPECT_TRUE(k["accumulates_for_every_entry"].is_null());
  EXPECT_TRUE(k["slope_at_fixed_point"].is_null());
  EXPECT_FALSE(k["accumulation_condition_reason"].get<std::string>().empty());
  const json& positions = k["iterates"]["positions"];
  ASSERT_GT(positions.size(), 10u);
  for (std::size_t i = 2; i < positions.size(); ++i) {
    EXPECT_GT(positions[i].get<double>(), positions[i - 1].get<double>()) << i;
    EXPECT_LE(positions[i].get<double>() - positions[i - 1].get<double>(),
              positions[i - 1].get<double>() - positions[i - 2].get<double>()) << i;
  }
  EXPECT_LT(positions.back().get<double>(), k["fixed_point"].get<double>());
  EXPECT_GT(k["contraction_at_fixed_point"].get<double>(), 0.0);
  EXPECT_LT(k["contraction_at_fixed_point"].get<double>(), 1.0);
  expect_clean_failure(
      box, box.run({"simulate", "--friction", "two-region", "--field-file", field, "--periods", "1"}),
      {"field_file"});
  // simulate with a field file alone runs on the field.
  const CliResult sim = box.run({"simulate", "--field-file", field, "--periods", "1"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_EQ(json::parse(sim.out)["friction"]["kind"].get<std::string>(), "field");
  // sweep positioning takes the field too: every cell as on the two-region table, to rounding.
  const std::vector<std::string> grid = {"sweep", "positioning", "--a2-range", "1.5:2.5:3",
                                         "--a3-range", "0.8:1.3:3", "--entries", "5"};
  auto with_args = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = grid;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  ASSERT_EQ(box.run(with_args({"--field-file", field, "--out", "pf.csv"})).exit_code, 0);
  ASSERT_EQ(box.run(with_args({"--c-mu", "3", "--out", "p2.csv"})).exit_code, 0);
  const std::vector<std::string> rows_field = lines(read_text(box.work_file("pf.csv")));
  const std::vector<std::string> on_two = lines(read_text(box.work_file("p2.csv")));
  ASSERT_EQ(rows_field.size(), 10u);
  ASSERT_EQ(on_two.size(), 10u);
  int compared = 0;
  for (std::size_t i = 1; i < rows_field.size(); ++i) {
    const std::string a = csv_text(rows_field[i], 5), b = csv_text(on_two[i], 5);  // dx_d
    if (a == "nan" || b == "nan") {
      EXPECT_EQ(a, b) << i;
      continue;
    }
    EXPECT_NEAR(std::stod(a), std::stod(b), 1e-9) << i;
    ++compared;
  }
  EXPECT_GE(compared, 5);
  EXPECT_TRUE(json::parse(read_text(box.work_file("pf.summary.json")))["c_mu"].is_null());
}

// accuracy and sweep positioning under a Stribeck law ran the slip integrator (steady state,
// dx, stopping runs) at its default tolerances whatever --relative-tolerance said (offered, then
// ignored; found beside converge's). A loose tolerance must change the results, by no more
// than it allows (x_mu = dx within 1e-6 at rtol = atol = 1e-4 over one steady period).
TEST(CliStop, PositioningUsesTheSlipIntegratorTolerances) {
  CliSandbox box;
  const std::vector<std::string> law = {"--mu-static", "0.36", "--stribeck-velocity", "0.1",
                                        "--entries", "3"};
  const std::vector<std::string> loose = {"--relative-tolerance", "1e-4",
                                          "--absolute-tolerance", "1e-4"};
  auto run = [&](std::vector<std::string> args, const std::vector<std::string>& extra) {
    args.insert(args.end(), law.begin(), law.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = box.run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
  };
  const json tight = json::parse(run({"accuracy", "--json"}, {}));
  const json coarse = json::parse(run({"accuracy", "--json"}, loose));
  EXPECT_NE(tight["x_mu"].get<double>(), coarse["x_mu"].get<double>()) << "tolerance ignored";
  EXPECT_NEAR(tight["x_mu"].get<double>(), coarse["x_mu"].get<double>(), 1e-6);
  const std::vector<std::string> grid = {"sweep", "positioning", "--a2-range", "2:2.5:2",
                                         "--a3-range", "1:1.3:2"};
  EXPECT_NE(run(grid, {}), run(grid, loose)) << "tolerance ignored";
}

#endif  // SELFALIGN_CLI_PATH

}  // namespace
}  // namespace selfalign
