// `selfalign feeder` and `selfalign regimes` (apps/selfalign/cmd_feeder.cpp, cmd_regimes.cpp): the SI report against hand values (the
// horizontal shaker's onset K = mu_s, the lift-off at Gamma = 1, the machine number), the run's
// first event on either side of the forward onset, and bad input: one line naming the flag,
// exit code 2, no file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH
namespace selfalign {
namespace {
namespace cli_feeder_test {  // own names: the tests are built as a unity build

using nlohmann::json;
using testing::CliSandbox;
using testing::expect_clean_failure;

std::string text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

TEST(CliFeeder, ReportsTheOnsetsAndTheRunInSiUnits) {
  const CliSandbox box;
  const double f = 50, g = 9.81, mu = 0.5, w = 2 * std::numbers::pi * f;
  // psi = 0 on a level track: both slips at K = mu_s, i.e. a0 = mu_s g / w^2; no lift-off.
  const double onset = mu * g / (w * w);
  for (const double factor : {0.97, 1.03}) {
    const auto r = box.run({"feeder", "--amplitude", text(factor * onset), "--frequency", "50",
                            "--mu-static", "0.5", "--mu-kinetic", "0.4", "--periods", "3",
                            "--steps-per-period", "4000", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_NEAR(j["machine_number"].get<double>(), factor * mu, 1e-12);
    EXPECT_NEAR(j["onsets"]["forward_slip"]["amplitude_m"].get<double>(), onset, 1e-15);
    EXPECT_NEAR(j["onsets"]["backward_slip"]["machine_number"].get<double>(), mu, 1e-15);
    EXPECT_TRUE(j["onsets"]["lift_off"]["machine_number"].is_null());
    EXPECT_EQ(j["first_event"], factor < 1 ? "none" : "forward slip");
    EXPECT_EQ(j["first_event_time_s"].is_null(), factor < 1);
    EXPECT_FALSE(j["lifted_off"].get<bool>());
  }
  // psi = 0.5, theta = 0.1: the lift-off at Gamma = 1, K = cos(theta) / sin(psi); above it the
  // part hops and still conveys. The classical lift-off phase: N = g cos(theta) (1 - Gamma
  // sin(w t)) turns negative at sin(w t) = 1 / Gamma: exact (the default) to 1e-9 rad, and by
  // time-stepping to the step (2 pi / 2000 rad) at the end of that step.
  const double K = 1.5 * std::cos(0.1) / std::sin(0.5);
  for (const std::string method : {"exact", "time-stepping"}) {
    SCOPED_TRACE(method);
    const auto r = box.run({"feeder", "--amplitude", text(K * g / (w * w)), "--frequency", "50",
                            "--vibration-angle", "0.5", "--incline", "0.1", "--mu-static", "0.6",
                            "--mu-kinetic", "0.5", "--periods", "10", "--method", method,
                            "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_NEAR(j["throw_number"].get<double>(), 1.5, 1e-12);
    EXPECT_NEAR(j["onsets"]["lift_off"]["machine_number"].get<double>(), K / 1.5, 1e-12);
    EXPECT_TRUE(j["lifted_off"].get<bool>());
    EXPECT_GT(j["census"]["flight"].get<double>(), 0);
    EXPECT_GT(j["velocity_m_per_s"].get<double>(), 0);
    EXPECT_NEAR(j["lift_off_phase_rad"].get<double>(), std::asin(1 / 1.5),
                method == "exact" ? 1e-9 : 2 * std::numbers::pi / 2000 * 1.5);
    EXPECT_EQ(j["steps_per_period"].is_null(), method == "exact");
  }
}

TEST(CliFeeder, StopsPastAFrictionStepOrSaysItDidNot) {
  // 50 Hz, psi = 0.35, theta = 0.02, K = 1.5 (a0 = 1.5 g / w^2): sliding forward at mu 0.5/0.4;
  // from 10 mm on the friction is 7 times higher, where the onsets hold a part at this K
  // (rough_regime stick): it stops past the step. The exact end position is the contact core's
  // limit (tests/test_feeder_smooth_exact.cpp, FeederStop); here the report's fields.
  const CliSandbox box;
  const double w = 2 * std::numbers::pi * 50, g = 9.81;
  const std::vector<std::string> base = {
      "feeder", "--amplitude", text(1.5 * g / (w * w)), "--frequency", "50",
      "--vibration-angle", "0.35", "--incline", "0.02", "--mu-static", "0.5", "--mu-kinetic",
      "0.4", "--step-position", "0.01", "--c-mu", "7", "--json"};
  const auto r = box.run(base);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out)["stop"];
  EXPECT_TRUE(j["stopped"].get<bool>());
  EXPECT_EQ(j["rough_regime"], "stick");
  EXPECT_GT(j["past_step_m"].get<double>(), 0);
  EXPECT_NEAR(j["end_position_m"].get<double>() - 0.01, j["past_step_m"].get<double>(), 1e-15);
  EXPECT_GT(j["stop_time_s"].get<double>(), 0);
  // Gamma = 1.3 lifts the part off every period: it never stops (null, not 0).
  const double K = 1.3 * std::cos(0.02) / std::sin(0.35);
  std::vector<std::string> hop = base;
  hop[2] = text(K * g / (w * w));
  hop.insert(hop.end(), {"--max-periods", "30"});
  const auto h = box.run(hop);
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const json k = json::parse(h.out)["stop"];
  EXPECT_FALSE(k["stopped"].get<bool>());
  EXPECT_TRUE(k["end_position_m"].is_null());
  EXPECT_TRUE(k["stop_time_s"].is_null());
  EXPECT_EQ(k["periods"], 30);
  // bad input: one line naming the flag, exit 2, no file
  const CliSandbox bad;
  std::vector<std::string> args = base;
  args[args.size() - 2] = "0";  // --c-mu 0
  args.insert(args.end(), {"--out", "r.json"});
  expect_clean_failure(bad, bad.run(args), {"c-mu", "(0, 1e6]"});
}

TEST(CliFeederDesign, TheDesignedDriveConveysAtTheTargetSpeed) {
  // 50 Hz, theta = 0.02, mu 0.5 / 0.4: 0.03 m/s with at most 3 rad of flight a period. The
  // designed drive, run by `selfalign feeder` (the exact run, the default), conveys at the
  // target (the design's bisection closes K to 1e-10 relative) and flies within the bound.
  const CliSandbox box;
  const auto r = box.run({"feeder-design", "--target-speed", "0.03", "--frequency", "50",
                          "--incline", "0.02", "--mu-static", "0.5", "--mu-kinetic", "0.4",
                          "--max-flight-angle", "3", "--json", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j["feasible"].get<bool>());
  const json& b = j["best"];
  EXPECT_EQ(j["candidates"].size(), 10u);
  const auto run = box.run({"feeder", "--amplitude", text(b["amplitude_m"].get<double>()),
                            "--frequency", "50", "--vibration-angle",
                            text(b["vibration_angle_rad"].get<double>()), "--incline", "0.02",
                            "--mu-static", "0.5", "--mu-kinetic", "0.4", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json k = json::parse(run.out);
  EXPECT_NEAR(k["velocity_m_per_s"].get<double>(), 0.03, 1e-6);
  EXPECT_LE(k["flight_angle_rad"].get<double>(), 3.0);
  EXPECT_NEAR(k["machine_number"].get<double>(), b["machine_number"].get<double>(), 1e-12);
  // unreachable: a result (feasible false, nulls), not an error
  const auto none = box.run({"feeder-design", "--target-speed", "5", "--frequency", "50",
                             "--mu-static", "0.5", "--mu-kinetic", "0.4", "--angles", "3",
                             "--json", "--quiet"});
  ASSERT_EQ(none.exit_code, 0) << none.err;
  const json n = json::parse(none.out);
  EXPECT_FALSE(n["feasible"].get<bool>());
  EXPECT_TRUE(n["best"]["amplitude_m"].is_null());
  EXPECT_FALSE(n["best"]["reason"].is_null());
  // bad input: one line naming the flag, exit 2, no file
  const CliSandbox bad;
  expect_clean_failure(bad, bad.run({"feeder-design", "--target-speed", "0", "--frequency", "50",
                                     "--mu-static", "0.5", "--mu-kinetic", "0.4", "--out",
                                     "d.json"}),
                       {"target-speed"});
}

TEST(CliFeeder, AConfigFileGivesTheFlagsAndFlagsOverrideIt) {
  // [drive], [friction], [run] and [stop] keys (SI) give the same report as the flags; a flag
  // overrides its key; an unknown key is one line naming it with the spelling hint; a missing
  // required value names the flag and the key. The file lies outside the work folder.
  const CliSandbox box;
  const std::string path = box.file("feeder.toml");
  {
    std::ofstream out(path);
    out << "[drive]\namplitude = 0.149e-3\nfrequency = 50\nvibration_angle = 0.35\n"
           "incline = 0.02\n[friction]\nmu_static = 0.5\nmu_kinetic = 0.4\n"
           "[run]\nmethod = \"exact\"\nperiods = 20\n[stop]\nstep_position = 0.01\nc_mu = 7\n";
  }
  const auto from_file = box.run({"feeder", "--config", path, "--json"});
  const auto from_flags = box.run({"feeder", "--amplitude", "0.149e-3", "--frequency", "50",
                                   "--vibration-angle", "0.35", "--incline", "0.02",
                                   "--mu-static", "0.5", "--mu-kinetic", "0.4", "--periods",
                                   "20", "--step-position", "0.01", "--c-mu", "7", "--json"});
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  ASSERT_EQ(from_flags.exit_code, 0) << from_flags.err;
  EXPECT_EQ(json::parse(from_file.out), json::parse(from_flags.out));
  const auto overridden = box.run({"feeder", "--config", path, "--c-mu", "3", "--json"});
  ASSERT_EQ(overridden.exit_code, 0) << overridden.err;
  EXPECT_EQ(json::parse(overridden.out)["stop"]["c_mu"].get<double>(), 3.0);
  {
    std::ofstream out(path);
    out << "[drive]\namplitude = 1e-4\nfrequency = 50\n[friction]\nmu_static = 0.5\n"
           "mu_kinetic = 0.4\n[stop]\nc_mux = 7\n";
  }
  expect_clean_failure(box, box.run({"feeder", "--config", path, "--out", "r.json"}),
                       {"stop.c_mux", "did you mean c_mu"});
  expect_clean_failure(box, box.run({"feeder", "--frequency", "50", "--mu-static", "0.5",
                                     "--mu-kinetic", "0.4", "--out", "r.json"}),
                       {"amplitude", "drive.amplitude"});
}

TEST(CliFeeder, ATwoFrequencyDriveHasTheOnsetsOfItsShape) {
  // r = 0.25, phi2 = pi/2: the acceleration shape sin(phi) + cos(2 phi) peaks at 9/8 (where
  // sin(phi) = 1/4) and dips to -2 (phi = 3 pi / 2), by hand. psi = 0.4, theta = 0.03: the
  // lift-off at K = cos(theta) / (sin(psi) 9/8), the throw number K sin(psi) 9/8 / cos(theta),
  // the backward slip at (mu cos(theta) - sin(theta)) / ((cos(psi) - mu sin(psi)) 2).
  const CliSandbox box;
  const double f = 50, g = 9.81, w = 2 * std::numbers::pi * f, K = 2.0;
  const auto r = box.run({"feeder", "--amplitude", text(K * g / (w * w)), "--frequency", "50",
                          "--vibration-angle", "0.4", "--incline", "0.03", "--mu-static", "0.5",
                          "--mu-kinetic", "0.4", "--harmonic-ratio", "0.25", "--harmonic-phase",
                          text(std::numbers::pi / 2), "--periods", "4", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const double s = std::sin(0.4), c = std::cos(0.4), ct = std::cos(0.03), st = std::sin(0.03);
  EXPECT_NEAR(j["onsets"]["lift_off"]["machine_number"].get<double>(), ct / (s * 1.125), 1e-12);
  EXPECT_NEAR(j["throw_number"].get<double>(), K * s * 1.125 / ct, 1e-12);
  EXPECT_NEAR(j["onsets"]["backward_slip"]["machine_number"].get<double>(),
              (0.5 * ct - st) / ((c - 0.5 * s) * 2.0), 1e-12);
  EXPECT_NEAR(j["onsets"]["forward_slip"]["machine_number"].get<double>(),
              (st + 0.5 * ct) / ((c + 0.5 * s) * 1.125), 1e-12);
  EXPECT_EQ(j["drive"]["harmonic_ratio"].get<double>(), 0.25);
  const CliSandbox bad;
  expect_clean_failure(bad, bad.run({"feeder", "--amplitude", "1e-4", "--frequency", "50",
                                     "--mu-static", "0.5", "--mu-kinetic", "0.4",
                                     "--harmonic-ratio", "-1", "--out", "r.json"}),
                       {"harmonic-ratio", "[0, 100]"});
}

TEST(CliFeeder, BadInputIsOneLineNamingTheFlag) {
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{"--amplitude", "0"}, {"amplitude"}},
      {{"--frequency", "-50"}, {"frequency"}},
      {{"--vibration-angle", "1.6"}, {"vibration-angle", "pi/2"}},
      {{"--incline", "-2"}, {"incline", "pi/2"}},
      {{"--mu-kinetic", "0.9"}, {"mu-kinetic", "mu-static"}},
      {{"--steps-per-period", "1"}, {"steps-per-period"}},
      {{"--restitution", "1.5"}, {"restitution", "[0, 1]"}},
      {{"--method", "integrator"}, {"method", "exact or time-stepping"}},
      // Gamma = a0 w^2 sin(0.5) / g = 4.8 > 1 with lift-off forbidden
      {{"--amplitude", "1e-3", "--vibration-angle", "0.5", "--no-flight"},
       {"amplitude", "no-flight", "negative"}},
  };
  for (const auto& [change, expected] : cases) {
    const CliSandbox box;
    std::vector<std::string> args = {"feeder", "--amplitude", "1e-4", "--frequency", "50",
                                     "--mu-static", "0.5", "--mu-kinetic", "0.4"};
    std::vector<std::string> extra;
    for (std::size_t i = 0; i < change.size(); ++i) {
      bool replaced = false;
      for (std::size_t k = 1; i + 1 < change.size() && k + 1 < args.size(); ++k)
        if (args[k] == change[i]) args[k + 1] = change[i + 1], replaced = true;
      if (replaced) {
        ++i;
      } else {
        extra.push_back(change[i]);
        if (i + 1 < change.size() && change[i + 1].rfind("--", 0) != 0)
          extra.push_back(change[++i]);
      }
    }
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--out", "report.json"});
    SCOPED_TRACE(change[0]);
    expect_clean_failure(box, box.run(args), expected);
  }
}

TEST(CliRegimes, WritesTheChartsCellsWithTheClosedFormRegimes) {
  // psi = 0 on a level track: both slips at K = mu_s (0.5), no lift-off, so on the geometric
  // K axis 0.1 .. 10 the cells below 0.5 are stick and the others both; psi = 0.5 adds the
  // lift-off at K = 1 / sin(0.5).
  for (const std::string method : {"exact", "time-stepping"}) {
  SCOPED_TRACE(method);
  const CliSandbox box;
  const auto r = box.run({"regimes", "--angle-min", "0", "--angle-max", "0.5", "--angles", "2",
                          "--machine-numbers", "9", "--mu-static", "0.5", "--mu-kinetic",
                          "0.4", "--periods", "3", "--csv", "chart.csv", "--json", "--quiet",
                          "--method", method});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["cells"], 18);
  const std::vector<std::string> rows = testing::lines(testing::read_text(box.work_file("chart.csv")));
  ASSERT_EQ(rows.size(), 19u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> col;
    std::stringstream ss(rows[i]);
    for (std::string c; std::getline(ss, c, ',');) col.push_back(c);
    ASSERT_EQ(col.size(), 10u) << rows[i];
    const double psi = std::stod(col[0]), K = std::stod(col[1]);
    std::string expected = K > 0.5 ? "both" : "stick";
    if (psi > 0) {
      const double c = std::cos(psi), s = std::sin(psi);
      const double kf = 0.5 / (c + 0.5 * s), kb = 0.5 / std::abs(0.5 * s - c), kl = 1 / s;
      expected = K >= kl ? "hopping" : K > kf && K > kb ? "both" : K > kf ? "forward"
                 : K > kb ? "backward" : "stick";
    }
    EXPECT_EQ(col[3], expected) << rows[i];
    EXPECT_EQ(col[9], "ok");
  }
  EXPECT_NE(j["method"].get<std::string>().find(method == "exact" ? "exact" : "Moreau"), std::string::npos);
  }
  // Bad input: one line naming the flag, exit 2, no file.
  const CliSandbox bad;
  expect_clean_failure(bad, bad.run({"regimes", "--mu-static", "0.5", "--mu-kinetic", "0.4",
                                     "--angles", "0", "--csv", "c.csv"}),
                       {"angles", "[1, 2000]"});
  expect_clean_failure(bad, bad.run({"regimes", "--mu-static", "0.5", "--mu-kinetic", "0.4",
                                     "--restitution", "-1", "--csv", "c.csv"}),
                       {"restitution", "[0, 1]"});
}

}  // namespace cli_feeder_test
}  // namespace
}  // namespace selfalign
#endif
