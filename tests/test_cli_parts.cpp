// `selfalign parts simulate | stop | montecarlo` (apps/selfalign/cmd_parts.cpp,
// cmd_parts_montecarlo.cpp, docs/rows.md): the example queue of examples/queue.toml through the
// CLI, against the library's row analyses and row_monte_carlo (under an uncertainty file), the
// per-run CSV, and bad input (overlapping parts, zero length or mass, restitution outside
// [0, 1], the Monte Carlo's inputs).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_sandbox.hpp"
#include "queue_example.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/io/uncertainty_file.hpp"
#include "selfalign/robust/row_monte_carlo.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace cli_parts_test {

using nlohmann::json;
using testing::CliSandbox;
using testing::expect_clean_failure;

const std::string kExample = std::string(SELFALIGN_SOURCE_DIR) + "/examples/queue.toml";

std::string write(const CliSandbox& box, const std::string& name, const std::string& text) {
  const std::string path = box.file(name);  // outside the work folder
  std::ofstream(path) << text;
  return path;
}

std::string example_text() {
  std::ifstream in(kExample);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(CliParts, StopReportsTheLibrarysQueueStop) {
  const CliSandbox box;
  const auto r = box.run({"parts", "stop", "--config", kExample, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  // the same queue through the library (examples/queue.toml, written out)
  const RowProcess p = testing_support::example_queue();
  const ThreePhaseProfile paper(p.table);
  const RowStop s = row_stop(paper, p.queue, FrictionField::steps({1.5}, {1.0, 4.0}), 400,
                             {Method::exact, 1}, 20);
  ASSERT_TRUE(s.stopped);
  EXPECT_TRUE(j["stopped"].get<bool>());
  EXPECT_TRUE(j["accumulated"].get<bool>());
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(j["x"][i].get<double>(), s.x[i]);
    EXPECT_EQ(j["error"][i].get<double>(), s.error[i]);
  }
  EXPECT_EQ(j["stop_time"].get<double>(), s.stop_time);
  EXPECT_EQ(j["method"], "exact");
  EXPECT_TRUE(j["steps_per_period"].is_null());
}

TEST(CliParts, SimulateWritesTheTrajectoriesAndThroughput) {
  const CliSandbox box;
  const auto r = box.run({"parts", "simulate", "--config", kExample, "--periods", "3",
                          "--frequency", "50", "--samples-per-period", "4", "--csv", "t.csv",
                          "--out", "r.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(box.work_file("r.json"));
  const json j = json::parse(in);
  EXPECT_NEAR(j["throughput_per_period"].get<double>(),
              j["queue_velocity"].get<double>() / 0.375, 1e-12);
  EXPECT_NEAR(j["parts_per_minute"].get<double>(), j["throughput_per_period"].get<double>() * 3000, 1e-9);
  std::ifstream csv(box.work_file("t.csv"));
  std::string line;
  int rows = 0;
  std::getline(csv, line);
  EXPECT_EQ(line, "t,x0,x1,x2");
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 13);  // t = 0 and 4 samples a period for 3 periods
}

TEST(CliParts, BadInputNamesThePartAndTheParameter) {
  std::string text = example_text();
  const auto replace = [](std::string s, const std::string& from, const std::string& to) {
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  {
    const CliSandbox box;
    const std::string cfg = write(box, "q.toml", replace(text, "x = 0.375", "x = 0.2"));
    expect_clean_failure(box, box.run({"parts", "stop", "--config", cfg, "--out", "r.json"}),
                         {"parts[1].x", "overlaps parts[0]"});
  }
  {
    const CliSandbox box;
    const std::string cfg = write(box, "q.toml", replace(text, "length = 0.25\nmu_static = 1.1", "length = 0\nmu_static = 1.1"));
    expect_clean_failure(box, box.run({"parts", "stop", "--config", cfg, "--out", "r.json"}),
                         {"parts[0].length", "(0, 1e50]"});
  }
  {
    const CliSandbox box;
    const std::string cfg = write(box, "q.toml", replace(text, "mu_static = 1.1", "mu_static = 1.1\nmass = 0"));
    expect_clean_failure(box, box.run({"parts", "simulate", "--config", cfg, "--csv", "t.csv"}),
                         {"parts[0].mass", "(0, 1e50]"});
  }
  {
    const CliSandbox box;
    expect_clean_failure(box, box.run({"parts", "stop", "--config", kExample, "--restitution",
                                       "1.5", "--out", "r.json"}),
                         {"restitution", "[0, 1]"});
  }
  {
    const CliSandbox box;
    const std::string cfg = write(box, "q.toml", replace(text, "count = 2", "count = 2\ncolour = 1"));
    expect_clean_failure(box, box.run({"parts", "stop", "--config", cfg}), {"parts[1]", "colour"});
  }
}

const char* kUncertainty =
    "mu = \"normal:0.3,5%\"\nc_mu = \"uniform:3.5,4.5\"\nx_mu_offset = \"uniform:-0.02,0.02\"\n";

TEST(CliPartsMonteCarlo, ReportsTheLibrarysStudy) {
  const CliSandbox box;
  const std::string file = write(box, "u.toml", kUncertainty);
  const auto r = box.run({"parts", "montecarlo", "--config", kExample, "--uncertainty-file", file,
                          "--runs", "12", "--seed", "4", "--tolerance", "0.27", "--threads", "1",
                          "--out", "r.json", "--runs-csv", "runs.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(box.work_file("r.json"));
  const json j = json::parse(in);
  const RowProcess p = testing_support::example_queue();  // examples/queue.toml, written out
  RowMonteCarloOptions o;
  o.runs = 12;
  o.seed = 4;
  o.tolerance = 0.27;
  o.max_periods = 400;
  const RowMonteCarloResult lib = row_monte_carlo(p, load_uncertainty(file), o);
  EXPECT_EQ(j["runs"], 12);
  EXPECT_EQ(j["queue_stopped"].get<int>(), lib.queue_stops);
  EXPECT_EQ(j["all_within"].get<int>(), lib.all_within);
  EXPECT_EQ(j["max_periods"], 400);
  ASSERT_EQ(j["per_part"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const json& part = j["per_part"][i];
    EXPECT_EQ(part["within"].get<int>(), lib.summary[i].within);
    EXPECT_EQ(part["end_position_mean"].get<double>(), lib.summary[i].end_mean);
    EXPECT_EQ(part["error_sd"].get<double>(), lib.summary[i].error_sd);
    EXPECT_EQ(part["end_position_quantiles"]["0.5"].get<double>(),
              row_end_position_quantile(lib, static_cast<int>(i), 0.5));
  }
  EXPECT_EQ(j["uncertainty"]["width"]["distribution"], "known");
  std::ifstream csv(box.work_file("runs.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "run,part,mu_factor,c_mu,static_ratio,x_mu_offset,amplitude,period_factor,"
            "queue_stopped,accumulated,end_position,error,process_time");
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 36);  // 12 runs x 3 parts
}

TEST(CliPartsMonteCarlo, BadInputNamesTheParameter) {
  const auto fails = [](const std::vector<std::string>& extra,
                        const std::vector<std::string>& expected) {
    const CliSandbox box;
    std::vector<std::string> args{"parts", "montecarlo", "--config", kExample, "--out", "r.json",
                                  "--runs-csv", "runs.csv"};
    args.insert(args.end(), extra.begin(), extra.end());
    expect_clean_failure(box, box.run(args), expected);
  };
  fails({}, {"uncertain", "needs an uncertain input"});
  fails({"--uncertain", "width=uniform:0.9,1.1"}, {"width.uncertain", "must be known"});
  fails({"--uncertain", "mu=normal:0.3,5%", "--runs", "0"}, {"runs", "[1, 1e7]"});
  fails({"--uncertain", "mu=normal:0.3,5%", "--tolerance", "0"}, {"tolerance", "(0, 1e50]"});
  fails({"--uncertain", "colour=uniform:1,2"}, {"uncertain", "colour", "must name one of"});
  fails({"--uncertain", "c_mu=uniform:0.5,2"}, {"c_mu.lower", "> 1"});
  fails({"--uncertain", "mu=normal:0.3,5%", "--max-periods", "0"}, {"max_periods"});
  {
    const CliSandbox box;
    const std::string cfg = write(box, "q.toml", "[[parts]]\nlength = 0.2\n");
    expect_clean_failure(box,
                         box.run({"parts", "montecarlo", "--config", cfg, "--uncertain",
                                  "mu=normal:0.3,5%", "--out", "r.json"}),
                         {"friction.step_position", "missing"});
  }
}

}  // namespace cli_parts_test
}  // namespace selfalign
