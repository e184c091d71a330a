// `selfalign design` through the real binary: the report's keys, the controller CSV, and an
// infeasible request as a one-line error that leaves no file.
#include <gtest/gtest.h>

#include <string>
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
  EXPECT_EQ(rows[0], "t,y,y_dot,y_ddot");
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
