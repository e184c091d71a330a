// Tests of the analysis subcommands (`steady`, `floquet`, `converge`, `sweep`) through the real
// binary (SELFALIGN_CLI_PATH), each in a fresh temporary directory: the keys scripts rely on,
// values checked against closed forms of the paper, SI output, determinism of sweeps for any
// thread count, and misuse (exit code 2, one line, no file left).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
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
TEST(CliAnalysis, NeedsTheCli) {
  GTEST_SKIP() << "built without the CLI (SELFALIGN_BUILD_CLI=OFF)";
}
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

// The exact solver and the closed forms of Sect. 5.1 evaluate the same parabolas; they differ
// by rounding only (a few ulps of O(1) numbers).
constexpr double kClosedForm = 1e-12;
// SI inputs are converted to [-] and back: a few ulps per conversion.
// Saltation matrices are exact; central differences with h = 1e-7 of the piecewise-smooth
// period map have O(h^2) truncation and O(eps/h) ~ 1e-9 rounding errors.
constexpr double kFiniteDifference = 1e-6;


json run_json(const CliSandbox& box, const std::vector<std::string>& args) {
  const CliResult r = box.run(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out);
}

// ---------------------------------------------------------------------------------------------
// steady

const char* const kSteadyKeys[] = {
    "case", "case_a_priori", "case_name", "v_bar", "f", "x_dot_0s", "phase", "converged",
    "periods", "method", "units", "profile", "t1", "t2", "t3", "y_ini", "y_dot_ini"};

TEST(CliSteady, CaseOneMatchesTheClosedFormOfSection51) {
  CliSandbox box;
  const json s = run_json(box, {"steady", "--json", "--a2", "3", "--a3", "0.9"});
  for (const char* key : kSteadyKeys) EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["case"], 1);
  EXPECT_EQ(s["case_a_priori"], 1);
  EXPECT_EQ(s["case_name"], "stick-slip with x' >= 0");
  EXPECT_EQ(s["profile"], "three-phase");
  EXPECT_EQ(s["units"], "dimensionless");
  EXPECT_EQ(s["method"], "exact");
  EXPECT_EQ(s["converged"], true);
  EXPECT_EQ(s["period"], 1.0);
  EXPECT_EQ(s["stroke"], 0.084);
  EXPECT_EQ(s["t3"], 1.0);
  EXPECT_EQ(s["x_dot_0s"], 0.0);  // Sect. 5.1: x'_0s = 0 is the steady state of case 1

  // Eqs. (12)-(24): rest on [t0, t1], slip with x'' = y2'' - 1 on [t1, t2], then x'' = -1 - y3''
  // until x' = 0 (eq. 21), stick until t3.
  const double a2 = 3, a3 = 0.9, t1 = s["t1"], t2 = s["t2"];
  const double v2 = (a2 - 1) * (t2 - t1), x2 = (a2 - 1) * (t2 - t1) * (t2 - t1) / 2;  // (16), (17)
  const double tau = v2 / (1 + a3);                                                   // (21)
  const double x_end = x2 + v2 * tau - (1 + a3) * tau * tau / 2;                     // (20)
  const double v_bar = s["v_bar"];
  EXPECT_NEAR(v_bar, x_end / 1.0, kClosedForm);                            // eq. (10), Δt = 1
  EXPECT_NEAR(s["f"].get<double>(), 1 / (1e4 * v_bar * v_bar), kClosedForm);  // eq. (11)
}

TEST(CliSteady, NonPhysicalRequestIsCaseZeroNotAnError) {
  CliSandbox box;
  const CliResult r = box.run({"steady", "--json", "--a2", "0.5", "--a3", "0.5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json s = json::parse(r.out);
  for (const char* key : kSteadyKeys) EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["case"], 0);
  EXPECT_EQ(s["case_a_priori"], 0);
  EXPECT_EQ(s["case_name"], "non-physical profile");
  for (const char* key : {"v_bar", "f", "x_dot_0s", "t1", "t2", "t3", "y_ini", "y_dot_ini"})
    EXPECT_TRUE(s[key].is_null()) << key;
  EXPECT_EQ(s["a2"], 0.5);
}

TEST(CliSteady, PureStickHasZeroVelocityAndNoObjective) {
  CliSandbox box;
  const json s = run_json(box, {"steady", "--json", "--period", "2", "--a2", "0.9", "--a3", "0.9"});
  EXPECT_EQ(s["case"], 5);
  EXPECT_EQ(s["case_a_priori"], 5);
  EXPECT_EQ(s["v_bar"], 0.0);
  EXPECT_TRUE(s["f"].is_null());  // f = 1/(c v̄^2) is infinite
}

TEST(CliSteady, TableByDefaultJsonFileWithOut) {
  CliSandbox box;
  const CliResult table = box.run({"steady", "--a2", "3", "--a3", "0.9"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("stick-slip with x' >= 0"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("v_bar"), std::string::npos) << table.out;

  const CliResult printed = box.run({"steady", "--json", "--a2", "3", "--a3", "0.9"});
  const CliResult written = box.run({"steady", "--a2", "3", "--a3", "0.9", "--out", "s.json"});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_TRUE(written.out.empty()) << written.out;
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"s.json"});
  EXPECT_EQ(read_text(box.work_file("s.json")), printed.out);
}

TEST(CliSteady, OtherProfilesHaveNoAPrioriCaseOrSwitchTimes) {
  CliSandbox box;
  const json s = run_json(box, {"steady", "--json", "--profile", "quadratic-sequence",
                                "--durations", "0.3,0.4,0.3", "--accelerations", "0,-3,4"});
  EXPECT_EQ(s["profile"], "quadratic-sequence");
  for (const char* key : {"case_a_priori", "t1", "t2", "t3", "y_ini", "y_dot_ini", "a2", "a3"})
    EXPECT_TRUE(s[key].is_null()) << key;
  EXPECT_GE(s["case"].get<int>(), 1);
  EXPECT_LE(s["case"].get<int>(), 5);
  EXPECT_EQ(s["period"], 1.0);
}

TEST(CliSteady, SiOutputIsTheDimensionlessResultConverted) {
  const double mu = 0.2, g = 9.8, L = 2e-3;
  const Scales sc(L, mu, g);
  CliSandbox box;
  const json d = run_json(box, {"steady", "--json", "--a2", "3", "--a3", "0.9"});
  const json si = run_json(
      box, {"steady", "--json", "--units", "si", "--mu", num(mu), "--g", num(g), "--length-scale",
            num(L), "--period", num(sc.time()), "--stroke", num(0.084 * L), "--a2",
            num(3 * sc.acceleration()), "--a3", num(0.9 * sc.acceleration())});
  EXPECT_EQ(si["units"], "si");
  EXPECT_EQ(si["case"], 1);
  const double v_bar = d["v_bar"];
  EXPECT_NEAR(si["v_bar"].get<double>() / sc.velocity(), v_bar, kSiAgreement * v_bar);
  EXPECT_NEAR(si["f"].get<double>(), d["f"].get<double>(), kSiAgreement * d["f"].get<double>());
  EXPECT_NEAR(si["t1"].get<double>() / sc.time(), d["t1"].get<double>(), kSiAgreement);
  EXPECT_NEAR(si["y_ini"].get<double>() / L, d["y_ini"].get<double>(), kSiAgreement);
}

// ---------------------------------------------------------------------------------------------
// floquet

void expect_monodromy(const json& m, bool available) {
  ASSERT_TRUE(m.contains("available"));
  EXPECT_EQ(m["available"], available);
  if (!available) {
    EXPECT_TRUE(m["matrix"].is_null());
    EXPECT_TRUE(m["multipliers"].is_null());
    return;
  }
  ASSERT_EQ(m["matrix"].size(), 2u);
  for (const json& row : m["matrix"]) EXPECT_EQ(row.size(), 2u);
  ASSERT_EQ(m["multipliers"].size(), 2u);
  for (const json& z : m["multipliers"]) {
    EXPECT_TRUE(z["re"].is_number()) << z;
    EXPECT_TRUE(z["im"].is_number()) << z;
  }
}

TEST(CliFloquet, SlipSlipMultiplierIsEquation33ByEveryMethod) {
  CliSandbox box;
  const json j = run_json(box, {"floquet", "--json", "--a2", "1.2", "--a3", "2.5"});
  for (const char* key : {"case", "x_dot_0s", "spread", "slip_slip_lambda2_formula"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["case"], 4);
  const double lambda2 = (0.2 * 1.5) / (2.2 * 3.5);  // eq. (33)
  EXPECT_NEAR(j["slip_slip_lambda2_formula"].get<double>(), lambda2, kClosedForm);
  for (const char* method : {"analytic", "saltation", "finite_difference"}) {
    expect_monodromy(j[method], true);
    const json& z = j[method]["multipliers"];
    const double tolerance = std::string(method) == "finite_difference" ? kFiniteDifference
                                                                       : kClosedForm;
    EXPECT_NEAR(z[0]["re"].get<double>(), 1.0, tolerance) << method;  // freedom in position
    EXPECT_NEAR(z[1]["re"].get<double>(), lambda2, tolerance) << method;
  }
  EXPECT_LT(j["spread"].get<double>(), kFiniteDifference);
}

TEST(CliFloquet, OtherPiecewisePolynomialProfilesHaveNoAnalyticMatrix) {
  CliSandbox box;
  const json j = run_json(box, {"floquet", "--json", "--profile", "quadratic-sequence",
                                "--durations", "0.3,0.4,0.3", "--accelerations", "0,-3,4"});
  expect_monodromy(j["analytic"], false);
  expect_monodromy(j["saltation"], true);
  expect_monodromy(j["finite_difference"], true);
  EXPECT_TRUE(j["slip_slip_lambda2_formula"].is_null());
}

TEST(CliFloquet, SiMatrixHasTimeUnitsOffTheDiagonal) {
  const double mu = 0.2, g = 9.8, L = 2e-3;
  const Scales sc(L, mu, g);
  CliSandbox box;
  const json d = run_json(box, {"floquet", "--json", "--a2", "1.2", "--a3", "2.5"});
  const json si = run_json(
      box, {"floquet", "--json", "--units", "si", "--mu", num(mu), "--g", num(g),
            "--length-scale", num(L), "--period", num(sc.time()), "--stroke", num(0.084 * L),
            "--a2", num(1.2 * sc.acceleration()), "--a3", num(2.5 * sc.acceleration())});
  const double m12 = d["saltation"]["matrix"][0][1];  // Δx(t3) per Δx'(t0): a time
  EXPECT_NEAR(si["saltation"]["matrix"][0][1].get<double>() / sc.time(), m12, kSiAgreement);
  EXPECT_NEAR(si["saltation"]["multipliers"][1]["re"].get<double>(),
              d["saltation"]["multipliers"][1]["re"].get<double>(), kSiAgreement);
  EXPECT_NEAR(si["x_dot_0s"].get<double>() / sc.velocity(), d["x_dot_0s"].get<double>(),
              kSiAgreement);
}

TEST(CliFloquet, TableByDefault) {
  CliSandbox box;
  const CliResult r = box.run({"floquet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* word : {"case", "analytic", "saltation", "finite_difference", "spread"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// ---------------------------------------------------------------------------------------------
// converge

TEST(CliConverge, CaseOneResponsesCoincideInFiniteTime) {
  CliSandbox box;
  const CliResult r = box.run({"converge", "--a2", "3", "--a3", "0.9", "--v1", "0.5", "--v2",
                               "-0.5", "--periods", "3", "--out", "c.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"c.csv", "c.summary.json"}));

  const std::vector<std::string> rows = lines(read_text(box.work_file("c.csv")));
  ASSERT_GT(rows.size(), 2u);
  EXPECT_EQ(rows[0], "t,v1,v2,V");
  EXPECT_EQ(csv_field(rows[1], 0), 0.0);
  EXPECT_EQ(csv_field(rows[1], 1), 0.5);
  EXPECT_EQ(csv_field(rows[1], 2), -0.5);
  EXPECT_EQ(csv_field(rows.back(), 0), 3.0);
  for (std::size_t i = 1; i < rows.size(); ++i) {  // eq. (35), and V never grows (eq. 36)
    const double dv = csv_field(rows[i], 1) - csv_field(rows[i], 2);
    EXPECT_NEAR(csv_field(rows[i], 3), dv * dv / 2, kClosedForm) << rows[i];
    if (i > 1) EXPECT_LE(csv_field(rows[i], 3), csv_field(rows[i - 1], 3) + kClosedForm);
  }

  const json s = json::parse(read_text(box.work_file("c.summary.json")));
  for (const char* key : {"intervals", "t_coincide", "V0", "V_end", "csv_file"})
    EXPECT_TRUE(s.contains(key)) << key;
  ASSERT_TRUE(s["t_coincide"].is_number());
  EXPECT_GT(s["t_coincide"].get<double>(), 0.0);
  EXPECT_LT(s["t_coincide"].get<double>(), 3.0);
  EXPECT_EQ(s["V0"], 0.5);
  EXPECT_EQ(s["V_end"], 0.0);
  EXPECT_EQ(s["csv_file"], "c.csv");
  // The intervals cover [t0, t0 + 3 Δt] without gaps and alternate '=' / '≠'.
  const json& iv = s["intervals"];
  ASSERT_FALSE(iv.empty());
  EXPECT_EQ(iv.front()["t_begin"], 0.0);
  EXPECT_EQ(iv.back()["t_end"], 3.0);
  EXPECT_EQ(iv.front()["same"], false);  // opposite slips at the start
  for (std::size_t i = 1; i < iv.size(); ++i) {
    EXPECT_EQ(iv[i]["t_begin"], iv[i - 1]["t_end"]);
    EXPECT_NE(iv[i]["same"], iv[i - 1]["same"]);
  }
}

TEST(CliConverge, SummaryToStdoutWithoutOut) {
  CliSandbox box;
  const json s = run_json(box, {"converge", "--a2", "3", "--a3", "0.9", "--periods", "2"});
  EXPECT_TRUE(box.work_entries().empty());
  EXPECT_TRUE(s["csv_file"].is_null());
  EXPECT_EQ(s["v1"], 0.5);  // library defaults
  EXPECT_EQ(s["v2"], -0.5);
}

// converge under a Stribeck law ran the slip integrator at its default tolerances whatever
// --relative-tolerance / --absolute-tolerance said (offered, then ignored). The loose run must
// differ from the tight one, and by no more than its tolerance allows (largest |dv| <= 1e-2 at
// rtol = atol = 1e-4 over 3 periods: the error grows at most linearly with the events, ~10).
TEST(CliConverge, SlipIntegratorTolerancesAreUsed) {
  CliSandbox box;
  const std::vector<std::string> law = {"converge", "--mu-static", "0.36",
                                        "--stribeck-velocity", "0.1", "--periods", "3"};
  // v1 by sample time (the uniform samples; rows at the runs' own event times differ).
  auto velocities = [&](const std::vector<std::string>& extra, const std::string& out) {
    std::vector<std::string> args = law;
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--out", out});
    const CliResult r = box.run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::map<std::string, double> v;
    const std::vector<std::string> rows = lines(read_text(box.work_file(out)));
    for (std::size_t i = 1; i < rows.size(); ++i)
      v[csv_text(rows[i], 0)] = std::stod(csv_text(rows[i], 1));
    return v;
  };
  const auto tight = velocities({}, "tight.csv");
  const auto loose =
      velocities({"--relative-tolerance", "1e-4", "--absolute-tolerance", "1e-4"}, "loose.csv");
  double largest = 0;
  std::size_t common = 0;
  for (const auto& [t, v] : tight)
    if (const auto it = loose.find(t); it != loose.end()) {
      ++common;
      largest = std::max(largest, std::abs(v - it->second));
    }
  EXPECT_GE(common, 600u);  // 200 samples per period over 3 periods
  EXPECT_GT(largest, 0.0) << "the tolerances changed nothing: ignored";
  EXPECT_LE(largest, 1e-2);
}

// ---------------------------------------------------------------------------------------------
// sweep

TEST(CliSweep, AccelerationCsvIsIdenticalForAnyThreadCount) {
  CliSandbox box;
  const std::vector<std::string> grid = {"sweep", "accelerations", "--a2-range", "0.1:3:20",
                                         "--a3-range", "0.1:3:20"};
  // 3 and 1e9 exceed a 2-core machine's cores: capped, silently (D02 crashed, D15 warned).
  for (const char* threads : {"1", "2", "0", "3", "1000000000"}) {
    std::vector<std::string> args = grid;
    args.insert(args.end(), {"--threads", threads, "--out", std::string("t") + threads + ".csv"});
    const CliResult r = box.run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << "no progress bar when stderr is not a terminal: " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const std::string csv = read_text(box.work_file("t1.csv"));
  EXPECT_EQ(read_text(box.work_file("t2.csv")), csv);
  EXPECT_EQ(read_text(box.work_file("t0.csv")), csv);
  json s1 = json::parse(read_text(box.work_file("t1.summary.json")));
  json s2 = json::parse(read_text(box.work_file("t2.summary.json")));
  EXPECT_EQ(s1["csv_file"], "t1.csv");
  s1.erase("csv_file");
  s2.erase("csv_file");
  EXPECT_EQ(s1, s2);

  const std::vector<std::string> rows = lines(csv);
  ASSERT_EQ(rows.size(), 401u);
  EXPECT_EQ(rows[0], "a2,a3,case_a_priori,case,v_bar,f,x_dot_0s,converged,status");
  EXPECT_EQ(csv_field(rows[1], 0), 0.1);  // row-major, a2 outer
  EXPECT_EQ(csv_field(rows[2], 0), 0.1);
  EXPECT_NEAR(csv_field(rows[2], 1), 0.1 + 2.9 / 19, kClosedForm);  // evenly spaced
  EXPECT_EQ(csv_field(rows[21], 0), csv_field(rows[21 + 19], 0));
  EXPECT_EQ(csv_field(rows.back(), 0), 3.0);
  EXPECT_EQ(csv_field(rows.back(), 1), 3.0);
  int counted = 0;
  for (const auto& [c, n] : s1["cases"].items()) counted += n.get<int>();
  EXPECT_EQ(counted, 400);
  EXPECT_EQ(s1["cells"], 400);
}

// Issue 22 item 3: the cells are the closed-form steady state ("method": "closed form");
// --search computes them by the fixed-point search instead: the same cases, v̄ and x'_0s within
// the closed form's agreement with the search (1e-10, tests/test_three_phase_steady_state.cpp).
TEST(CliSweep, ClosedFormCellsAgreeWithTheSearch) {
  CliSandbox box;
  const std::vector<std::string> grid = {"sweep", "accelerations", "--a2-range", "0.1:3:15",
                                         "--a3-range", "0.1:3:15", "--mu-static", "0.36",
                                         "--mu-backward", "0.21"};  // law (1.2, 1, 0.7)
  std::vector<std::string> closed = grid, search = grid;
  closed.insert(closed.end(), {"--out", "c.csv"});
  search.insert(search.end(), {"--out", "s.csv", "--search"});
  ASSERT_EQ(box.run(closed).exit_code, 0);
  ASSERT_EQ(box.run(search).exit_code, 0);
  EXPECT_EQ(json::parse(read_text(box.work_file("c.summary.json")))["method"], "closed form");
  EXPECT_EQ(json::parse(read_text(box.work_file("s.summary.json")))["method"], "exact");
  const std::vector<std::string> c = lines(read_text(box.work_file("c.csv")));
  const std::vector<std::string> s = lines(read_text(box.work_file("s.csv")));
  ASSERT_EQ(c.size(), 226u);
  ASSERT_EQ(s.size(), c.size());
  int slipping = 0;
  for (std::size_t k = 1; k < c.size(); ++k) {
    for (int col : {0, 1, 2, 3, 7}) EXPECT_EQ(csv_text(c[k], col), csv_text(s[k], col)) << c[k];
    for (int col : {4, 6}) {
      const double a = csv_field(c[k], col), b = csv_field(s[k], col);
      if (std::isnan(b)) {
        EXPECT_TRUE(std::isnan(a)) << c[k];
        continue;
      }
      EXPECT_NEAR(a, b, 1e-10 * (1 + std::abs(b))) << c[k];
      slipping += col == 4 && b != 0;
    }
  }
  EXPECT_GE(slipping, 100);  // most physical cells slip (the test is not vacuous)
}

TEST(CliSweep, NonFiniteValuesAreNanAndInfInCsv) {
  CliSandbox box;
  // Δt = 2: (0.1, ·) is non-physical (1/a2 + 1/a3 > Δt²/(8 Δy) ≈ 5.95); (0.5, 0.5) and
  // (0.9, 0.9) stick throughout (|y''| <= 1): v̄ = 0, f = inf.
  const CliResult r = box.run({"sweep", "accelerations", "--period", "2", "--a2-range",
                               "0.1:0.9:3", "--a3-range", "0.1:0.9:3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> rows = lines(r.out);
  ASSERT_EQ(rows.size(), 10u) << r.out;
  EXPECT_EQ(rows[1], "0.1,0.1,0,0,nan,nan,nan,0,ok");
  EXPECT_EQ(rows[5], "0.5,0.5,5,5,0,inf,0,1,ok");
  EXPECT_EQ(rows[9], "0.9,0.9,5,5,0,inf,0,1,ok");
}

TEST(CliSweep, PeriodAndStrokeStudies) {
  CliSandbox box;
  CliResult r = box.run({"sweep", "period", "--range", "0.5:2:4", "--a2", "3", "--a3", "0.9"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> rows = lines(r.out);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], "period,stroke,physical,case,v_bar,f,status");
  EXPECT_EQ(rows[1], "0.5,0.084,0,0,nan,nan,ok");  // 1/3 + 1/0.9 > 0.25/(8 · 0.084): case 0
  EXPECT_EQ(csv_field(rows[4], 0), 2.0);
  EXPECT_EQ(csv_text(rows[4], 2), "1");

  r = box.run({"sweep", "stroke", "--family", "scaled-shape", "--range", "0.01:0.2:5", "--log",
               "--out", "s.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"s.csv", "s.summary.json"}));
  rows = lines(read_text(box.work_file("s.csv")));
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(csv_field(rows[1], 1), 0.01);
  EXPECT_EQ(csv_field(rows[5], 1), 0.2);
  EXPECT_NEAR(csv_field(rows[3], 1), std::sqrt(0.01 * 0.2), kClosedForm);  // log-spaced
  const json s = json::parse(read_text(box.work_file("s.summary.json")));
  EXPECT_EQ(s["family"], "scaled-shape");
  EXPECT_EQ(s["sweep"], "stroke");
  EXPECT_EQ(s["grid"]["spacing"], "log");
  EXPECT_EQ(s["cells"], 5);
}

// ---------------------------------------------------------------------------------------------
// parameters

TEST(CliParameters, ListsTheViewAfterSetAsTheSiModelDefinesIt) {
  CliSandbox box;
  // SI run: mu = 0.2, the table's a2 = 3 m/s^2; --set applies the factors to the SI keys:
  // a2 x a/p^2 (a = 1.2, p = 2: 3 x 0.3 = 0.9 m/s^2), the period x 2.
  const json j = run_json(box, {"parameters", "--units", "si", "--mu", "0.2", "--a2", "3",
                                "--a3", "2", "--period", "0.05", "--stroke", "0.0002", "--set",
                                "amplitude_scale=1.2", "--set", "time_scale=2", "--set",
                                "mu_static=0.25", "--json"});
  std::map<std::string, json> by_name;
  for (const json& p : j["parameters"]) by_name[p["name"]] = p;
  EXPECT_NEAR(by_name["a2"]["value"].get<double>(), 0.9, 1e-15);
  EXPECT_EQ(by_name["a2"]["unit"], "[m/s^2]");
  EXPECT_NEAR(by_name["period"]["value"].get<double>(), 0.1, 1e-16);
  EXPECT_NEAR(by_name["stroke"]["value"].get<double>(), 0.00024, 1e-18);
  EXPECT_EQ(by_name["mu_static"]["value"], 0.25);
  EXPECT_TRUE(by_name["stribeck_velocity"]["value"].is_null());  // absent, not 0
  EXPECT_EQ(by_name.count("g"), 1u);
  EXPECT_EQ(by_name["amplitude_scale"]["value"], 1.0);
}

// ---------------------------------------------------------------------------------------------
// Misuse: exit code 2, one line on stderr, nothing on stdout, no file left behind.

class CliAnalysisMisuse : public ::testing::TestWithParam<MisuseCase> {};

TEST_P(CliAnalysisMisuse, ExitsTwoWithOneLineAndWritesNothing) {
  CliSandbox box;
  expect_clean_failure(box, box.run(GetParam().args), GetParam().expected);
}

const MisuseCase kAnalysisMisuseCases[] = {
    {"sweep_range_malformed",
     {"sweep", "accelerations", "--a2-range", "1:2", "--a3-range", "0.1:3:20", "--out", "a.csv"},
     {"a2-range = 1:2", "LO:HI:N"}},
    {"sweep_range_not_a_number",
     {"sweep", "accelerations", "--a2-range", "0.1:3:20", "--a3-range", "x:3:20", "--out", "a.csv"},
     {"a3-range = x:3:20"}},
    {"sweep_range_zero_points",
     {"sweep", "stroke", "--range", "0.01:0.1:0", "--out", "a.csv"}, {"range", "N in [1, 1e7]"}},
    {"sweep_threads_negative",
     {"sweep", "accelerations", "--a2-range", "0.1:3:20", "--a3-range", "0.1:3:20", "--threads",
      "-1", "--out", "a.csv"},
     {"threads = -1", ">= 0"}},
    {"sweep_periods_include_zero",
     {"sweep", "period", "--range", "0:1:5", "--out", "a.csv"}, {"range = 0:1:5", "> 0"}},
    {"sweep_log_needs_positive",
     {"sweep", "stroke", "--range", "-0.1:0.1:5", "--log", "--out", "a.csv"}, {"range", "> 0"}},
    {"sweep_unknown_family",
     {"sweep", "period", "--range", "0.5:2:4", "--family", "square", "--out", "a.csv"},
     {"family = square", "three-phase, scaled-shape"}},
    {"sweep_missing_range", {"sweep", "accelerations", "--a3-range", "0.1:3:20"}, {"--a2-range"}},
    {"sweep_missing_kind", {"sweep"}, {}},
    {"sweep_summary_and_csv_on_stdout",
     {"sweep", "period", "--range", "0.5:2:4", "--summary", "-"}, {"summary", "--out"}},
    {"steady_bad_period", {"steady", "--period", "0", "--out", "s.json"}, {"period = 0", "> 0"}},
    {"steady_bad_units", {"steady", "--units", "imperial", "--json"}, {"units = imperial"}},
    {"floquet_case_zero", {"floquet", "--a2", "0.5", "--a3", "0.5", "--out", "f.json"},
     {"a2, a3", "case 0"}},
    {"floquet_fd_step_zero", {"floquet", "--fd-step", "0", "--out", "f.json"}, {"fd-step = 0"}},
    {"floquet_needs_piecewise_constant",
     {"floquet", "--profile", "fourier", "--fourier-cos", "0.02", "--out", "f.json"},
     {"profile = fourier", "piecewise-constant"}},
    {"converge_samples_zero",
     {"converge", "--samples-per-period", "0", "--out", "c.csv"}, {"samples_per_period = 0"}},
    {"converge_periods_zero", {"converge", "--periods", "0", "--out", "c.csv"}, {"periods = 0"}},
    {"converge_v1_nan", {"converge", "--v1", "nan", "--out", "c.csv"}, {"v1"}},
    {"parameters_setting", {"parameters", "--set", "step=1e-3", "--out", "p.json"},
     {"step", "setting", "not a model parameter"}},
    {"parameters_not_in_model",
     {"parameters", "--friction", "uniform", "--set", "c_mu=3", "--out", "p.json"},
     {"c_mu", "friction = uniform"}},
    {"parameters_not_a_number", {"parameters", "--set", "c_mu=3x", "--out", "p.json"},
     {"c_mu = 3x", "number"}},
    {"parameters_out_of_range", {"parameters", "--set", "c_mu=0.5", "--out", "p.json"},
     {"c_mu = 0.5", "> 1"}},
    {"parameters_malformed", {"parameters", "--set", "c_mu", "--out", "p.json"},
     {"NAME=VALUE"}},
    {"parameters_offers_no_solver_flag", {"parameters", "--step", "1e-3", "--out", "p.json"},
     {"--step is not used by selfalign parameters"}},
};

INSTANTIATE_TEST_SUITE_P(Analysis, CliAnalysisMisuse, ::testing::ValuesIn(kAnalysisMisuseCases),
                         [](const auto& test) { return test.param.name; });

#endif  // SELFALIGN_CLI_PATH

}  // namespace
}  // namespace selfalign
