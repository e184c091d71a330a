// `selfalign parts simulate | stop` (apps/selfalign/cmd_parts.cpp, docs/rows.md): the example
// queue of examples/queue.toml through the CLI, against the library's row analyses, and bad
// input (overlapping parts, zero length or mass, restitution outside [0, 1]).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_sandbox.hpp"
#include "selfalign/analysis/row.hpp"
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
  // the same queue through the library (examples/queue.toml, written out here)
  const ThreePhaseProfile paper({1.0, 0.084, 3.0, 0.9});
  RowQueue q;
  q.parts = {{0.25, 1.0, FrictionLaw(1.1, 0.8), 0.0, 0.0},
             {0.25, 1.0, FrictionLaw(1.2, 1.0), 0.375, 0.0},
             {0.25, 1.0, FrictionLaw(1.2, 1.0), 0.75, 0.0}};
  const RowStop s = row_stop(paper, q, FrictionField::steps({1.5}, {1.0, 4.0}), 400,
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

}  // namespace cli_parts_test
}  // namespace selfalign
