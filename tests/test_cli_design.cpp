// `selfalign design` through the real binary: the report's keys, the controller CSV, and an
// infeasible request as a one-line error that leaves no file.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"

namespace selfalign {
namespace {

using nlohmann::json;
using testing::CliSandbox;
using testing::expect_clean_failure;
using testing::lines;
using testing::read_text;

const std::vector<std::string> kSmall = {"design", "--acceleration-grid", "10", "--period-grid",
                                         "2", "--stroke-grid", "1", "--entries", "10"};

TEST(CliDesign, ReportsTheProfileAndWritesTheControllerCsv) {
  CliSandbox box;
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), {"--json", "--profile-csv", "profile.csv", "--sample-rate", "2000"});
  const auto r = box.run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key : {"feasible", "profile", "case", "v_bar_m_per_s", "x_mu_m",
                          "end_position_m", "error_band_m", "process_time_s", "stop"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["feasible"].get<bool>());
  EXPECT_NEAR(j["end_position_m"].get<double>(), 0.1, j["error_band_m"].get<double>() + 1e-12);
  EXPECT_LE(j["profile"]["velocity_peak_m_per_s"].get<double>(), 0.2 * (1 + 1e-12));
  const auto rows = lines(read_text(box.work_file("profile.csv")));
  ASSERT_GT(rows.size(), 3u);
  EXPECT_EQ(rows[0], "t_s,y_m,y_dot_m_per_s,y_ddot_m_per_s2,y_dddot_m_per_s3");
}

TEST(CliDesign, InfeasibleRequestIsOneLineNamingTheLimit) {
  CliSandbox box;
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), {"--acceleration-max", "2", "--profile-csv", "p.csv"});
  expect_clean_failure(box, box.run(args), {"infeasible", "acceleration_max"});
}

TEST(CliDesign, MisuseIsOneLineNamingTheParameter) {
  CliSandbox box;
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), {"--width", "-1", "--out", "d.json"});
  expect_clean_failure(box, box.run(args), {"width", "must be > 0"});
}

TEST(CliDesign, NominalDesignOfTheIssueCarriesAFragilityWarning) {
  // The issue's task: y2'' = c_mu mu g exactly, so mu or c_mu a little low never stops.
  CliSandbox box;
  const auto r = box.run({"design", "--mass", "0.02", "--width", "0.003", "--mu", "0.2",
                          "--c-mu", "2.5", "--distance", "0.04", "--stroke-max", "0.002",
                          "--acceleration-max", "50", "--frequency-max", "30", "--tolerance",
                          "1e-4", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j["fragility"]["fragile"].get<bool>());
  EXPECT_LT(j["fragility"]["stop_margin"].get<double>(), 0.05);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("never stops"), std::string::npos);
  EXPECT_TRUE(j["fragility"]["end_shift_mu_m"].is_null());  // mu 5% low: no end position
  // No --mu-static: the design assumed mu_static = mu, and a plain warning says so.
  EXPECT_TRUE(j["fragility"]["assumes_equal_static"].get<bool>());
  EXPECT_EQ(j["fragility"]["end_m_with_mu_static_low_high"].size(), 2u);
  bool plain = false;
  for (const json& w : j["warnings"])
    plain = plain || w.get<std::string>().find("assumes mu_static = mu") != std::string::npos;
  EXPECT_TRUE(plain);
  // The profile sits on the grid's top acceleration and the full stroke, and says so.
  EXPECT_FALSE(j["limits"].empty());
}

TEST(CliDesign, RobustDesignReportsVerificationAndActuatorCsv) {
  CliSandbox box;
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), {"--tolerance", "0.003", "--uncertain", "mu=normal:0.3,3%", "--robust",
                           "--screening-runs", "50", "--verification-runs", "400", "--json",
                           "--profile-csv", "p.csv", "--sample-rate", "1000", "--moving-mass",
                           "2"});
  const auto r = box.run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j.contains("robust"));
  EXPECT_EQ(j["robust"]["verification"]["runs"].get<int>(), 400);
  const double p = j["robust"]["verification"]["p_within"].get<double>();
  // Met: the selection's lower 95% bound and the independent verification reach the target.
  const json& selection = j["robust"]["selection"];
  EXPECT_EQ(j["robust"]["meets_target"].get<bool>(),
            selection["p_within_95ci"][0].get<double>() >= 0.99 && p >= 0.99);
  EXPECT_EQ(selection["runs"].get<int>(), 400);
  EXPECT_NE(selection["seed"], j["robust"]["verification"]["seed"]);
  EXPECT_EQ(j["robust"]["rungs"], json::array({25, 50}));
  EXPECT_TRUE(j["robust"]["limits"].is_array());
  EXPECT_TRUE(j["robust"]["achievable_tolerance_m"].is_number() ||
              j["robust"]["achievable_tolerance_m"].is_null());
  EXPECT_GE(p, 0);
  // Actuator-ready: n = round(period x rate) rows, no repeated endpoint, the rate adjusted so
  // the period is n samples: t_i = i period / n, and force = mass x y''.
  const auto rows = lines(read_text(box.work_file("p.csv")));
  const long long n = j["profile_csv"]["samples_per_period"].get<long long>();
  ASSERT_EQ(static_cast<long long>(rows.size()), n + 1);
  EXPECT_EQ(rows[0], "t_s,y_m,y_dot_m_per_s,y_ddot_m_per_s2,y_dddot_m_per_s3,force_n");
  const double period = j["profile"]["period_s"].get<double>();
  EXPECT_EQ(n, std::llround(period * 1000));
  EXPECT_NEAR(j["profile_csv"]["sample_rate_hz"].get<double>(), n / period, 1e-9);
  const auto fields = [](const std::string& row) {
    std::vector<double> v;
    std::stringstream ss(row);
    std::string item;
    while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
    return v;
  };
  const std::vector<double> last = fields(rows.back());
  EXPECT_NEAR(last[0], period * (n - 1) / n, 1e-15);
  for (std::size_t i = 1; i < rows.size(); i += 7) {
    const std::vector<double> v = fields(rows[i]);
    EXPECT_DOUBLE_EQ(v[5], 2 * v[3]);
  }
}

TEST(CliDesign, TheLargestGridIsRefusedUpFrontWithinAMemoryLimit) {
  // D36: the flags' largest grid (200^2 x 100 x 20 x 1000 = 8e10 steady entries) ended in
  // std::bad_alloc under 4 GiB; it is refused at once, naming the grid, without allocating it.
  CliSandbox box;
  const std::string flags = " design --acceleration-grid 200 --period-grid 100 --stroke-grid 20"
                            " --entries 1000 --threads 1 --out d.json";
#ifdef SELFALIGN_SANITIZED_TESTS
  const std::string limit;  // AddressSanitizer reserves far more address space than 4 GiB
#else
  const std::string limit = "ulimit -v 4194304 && ";
#endif
  for (const std::string extra : {"", " --robust --tolerance 0.001 --uncertain mu=normal:0.3,5%"}) {
    const std::string command = "cd " + testing::quote(box.work().string()) + " && " + limit +
                                testing::quote(SELFALIGN_CLI_PATH) + flags + extra + " >" +
                                testing::quote(box.file("stdout.txt")) + " 2>" +
                                testing::quote(box.file("stderr.txt"));
    const int status = std::system(command.c_str());
    testing::CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(box.file("stdout.txt"));
    r.err = read_text(box.file("stderr.txt"));
    expect_clean_failure(box, r, {"invalid grid", "acceleration_grid^2 x period_grid x stroke_grid"});
  }
}

TEST(CliDesign, BadUncertaintyIsOneLineNamingTheParameter) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--uncertain", "mu=normal:0.3,-0.01"}, "mu.sd"},
      {{"--uncertain", "mu=normal:0.3,0.01,0.35,0.4"}, "mu.lower"},
      {{"--uncertain", "width=samples:"}, "width.samples"},
      {{"--uncertain", "mu=normal:0.3,0.01", "--robust", "--probability-target", "1"},
       "probability_target"},
      {{"--uncertain", "mu=normal:0.3,0.01", "--robust", "--probability-target", "0"},
       "probability_target"},
      {{"--uncertain", "friction=normal:0.3,0.01"}, "uncertain"},
  };
  for (const auto& [extra, name] : cases) {
    CliSandbox box;
    std::vector<std::string> args = kSmall;
    args.insert(args.end(), {"--tolerance", "0.001", "--out", "d.json", "--profile-csv", "p.csv"});
    args.insert(args.end(), extra.begin(), extra.end());
    expect_clean_failure(box, box.run(args), {name});
  }
}

TEST(CliMonteCarlo, EvaluatesADesignReportDeterministically) {
  CliSandbox box;
  std::vector<std::string> args = kSmall;
  args.insert(args.end(), {"--tolerance", "0.001", "--width", "0.008", "--out", "d.json"});
  ASSERT_EQ(box.run(args).exit_code, 0);
  const auto mc = [&](const std::string& threads) {
    return box.run({"montecarlo", "--design", "d.json", "--uncertain",
                    "mu=normal:0.3,3%", "--uncertain", "c_mu=uniform:2.4,2.6", "--runs", "300",
                    "--threads", threads, "--json", "--worst-case", "--interior-points", "8"});
  };
  const auto one = mc("1"), two = mc("2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);  // identical for any thread count
  const json j = json::parse(one.out);
  EXPECT_EQ(j["monte_carlo"]["runs"].get<int>(), 300);
  EXPECT_NE(j["worst_case"]["method"].get<std::string>().find("corners"), std::string::npos);
  EXPECT_EQ(j["uncertainty"]["mu"]["distribution"].get<std::string>(),
            "normal(mean=0.3, sd=0.009)");
  // The design's request is read back: its width and tolerance, not the flags' defaults.
  EXPECT_EQ(j["uncertainty"]["width"]["nominal"].get<double>(), 0.008);
  EXPECT_EQ(j["monte_carlo"]["tolerance_m"].get<double>(), 0.001);
  const auto wider = box.run({"montecarlo", "--design", "d.json", "--width", "0.009",
                              "--uncertain", "mu=normal:0.3,3%", "--runs", "10", "--json"});
  ASSERT_EQ(wider.exit_code, 0) << wider.err;
  EXPECT_EQ(json::parse(wider.out)["uncertainty"]["width"]["nominal"].get<double>(), 0.009);
  CliSandbox bad;
  expect_clean_failure(bad, bad.run({"montecarlo", "--period-s", "0.05", "--stroke-m", "0.0005",
                                     "--a2", "5", "--a3", "4", "--x-mu", "0.05", "--uncertain",
                                     "mu=normal:0.3,-1%", "--out", "m.json"}),
                       {"mu.sd"});
}

}  // namespace
}  // namespace selfalign

namespace selfalign {
namespace {

TEST(CliOptimize, ThreePhaseReportAndMisuse) {
  testing::CliSandbox box;
  const auto r = box.run({"optimize", "--family", "three-phase", "--json", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["results"].size(), 1u);
  EXPECT_TRUE(j["results"][0]["feasible"].get<bool>());
  EXPECT_LE(j["results"][0]["max_velocity"].get<double>(), 3.2 * (1 + 1e-12));
  EXPECT_GT(j["results"][0]["v_bar"].get<double>(), 0.0);
  testing::expect_clean_failure(box, box.run({"optimize", "--family", "spline", "--out", "o.json"}),
                                {"family", "must be one of"});
}

}  // namespace
}  // namespace selfalign
