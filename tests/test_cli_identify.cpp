// `selfalign identify` (apps/selfalign/cmd_identify.cpp, docs/identification.md): a measured
// run (synthesized by the library's simulate() with a hidden truth, noise and a clock offset,
// written in mm and ms) through the CLI to its report, fit CSV and uncertainty file, which
// `design --robust` and `montecarlo` read; and bad input (no time column, time that does not
// increase, fewer samples than estimated parameters, a free name the model lacks): one line,
// exit 2, no file.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

#include "cli_sandbox.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/uncertainty_file.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign {
namespace cli_identify_test {

using nlohmann::json;
using testing::CliSandbox;
using testing::expect_clean_failure;

// The finite-jerk run of test_identification.cpp (mu 0.3, mu_static 0.36), as a config file.
const char* kModel = R"(units = "si"
profile = "three-phase"
period = 0.05
stroke = 6.2e-4
a2 = 6.77
a3 = 3.83
jerk = 800
friction = "uniform"
g = 9.81
length_scale = 1e-3
)";

std::string write(const CliSandbox& box, const std::string& name, const std::string& text) {
  const std::string path = box.file(name);  // outside the work folder
  std::ofstream(path) << text;
  return path;
}

// 20 periods at 2 kHz of the truth, x + N(0, 2 um), the clock 3 ms behind, in ms and mm.
std::string measured_csv() {
  SimulateConfig c;
  set_simulate_config_value(c, "units", "si");
  c.profile = "three-phase", c.period = 0.05, c.stroke = 6.2e-4, c.a2 = 6.77, c.a3 = 3.83;
  c.jerk = 800, c.friction = "uniform", c.mu = 0.3, c.mu_static = 0.36, c.g = 9.81;
  c.length_scale = 1e-3, c.periods = 20, c.output_step = 5e-4;
  const SimulateModel m = build_simulate_model(c);
  const SimulationResult r = simulate(*m.profile, *m.friction, m.law, m.initial, m.options);
  const OutputUnits out = m.output_units();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0, 2e-6);
  std::ostringstream s;
  s.precision(12);
  s << "tracked part\nt [ms],x [mm],frame\n";
  for (std::size_t i = 0; i + 1 < r.trajectory.size(); ++i)
    s << (out.time(r.trajectory.t[i]) - 3e-3) * 1e3 << ','
      << (out.length(r.trajectory.x[i]) + noise(rng)) * 1e3 << ',' << i << '\n';
  return s.str();
}

TEST(CliIdentify, ReportFitAndUncertaintyFileThatDesignAndMonteCarloRead) {
  CliSandbox box;
  const std::string data = write(box, "run.csv", measured_csv());
  const std::string model =
      write(box, "model.toml", std::string(kModel) + "mu = 0.31\nmu_static = 0.34\n");
  const auto r = box.run({"identify", "--data", data, "--config", model, "--free",
                          "mu,mu_static,time_offset", "--starts", "0", "--out", "report.json",
                          "--fit-csv", "fit.csv", "--uncertainty-out", "id.toml"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  std::ifstream in(box.work_file("report.json"));
  const json report = json::parse(in);
  ASSERT_EQ(report["parameters"].size(), 2u);
  for (const auto& [i, truth] : {std::pair{0, 0.3}, std::pair{1, 0.36}}) {
    const json& p = report["parameters"][i];
    EXPECT_TRUE(p["identifiable"].get<bool>());
    EXPECT_NEAR(p["estimate"].get<double>(), truth, 4 * p["standard_error"].get<double>());
    // mu and mu_static are profiled by default.
    EXPECT_FALSE(p["profile_interval"][0].is_null());
  }
  EXPECT_NEAR(report["runs"][0]["time_offset"].get<double>(), 3e-3, 1e-4);
  EXPECT_EQ(report["residuals"]["samples"].get<int>(), 2000);
  // The fit CSV: a header and one row per sample.
  std::ifstream fit(box.work_file("fit.csv"));
  std::string header;
  std::getline(fit, header);
  EXPECT_EQ(header, "run,t,x_measured,x_fitted,residual,window,stick");
  int rows = 0;
  for (std::string line; std::getline(fit, line);) ++rows;
  EXPECT_EQ(rows, 2000);
  // The uncertainty file: mu and static_ratio as normals, readable by load_uncertainty.
  const ProcessUncertainty u = load_uncertainty(box.work_file("id.toml"));
  EXPECT_NEAR(std::get<Normal>(u.mu).mean, report["parameters"][0]["estimate"].get<double>(),
              1e-15);
  EXPECT_NEAR(std::get<Normal>(u.static_ratio).mean, 1.2, 0.05);
  // design --robust and montecarlo take it as their uncertainty.
  const auto d = box.run({"design", "--mass", "0.02", "--width", "0.001", "--mu", "0.3",
                          "--mu-static", "0.36", "--c-mu", "2.5", "--distance", "0.04",
                          "--stroke-max", "0.002", "--acceleration-max", "50", "--frequency-max",
                          "30", "--tolerance", "0.0005", "--uncertainty-file", "id.toml",
                          "--robust", "--out", "d.json"});
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto mc = box.run({"montecarlo", "--design", "d.json", "--uncertainty-file", "id.toml",
                           "--runs", "500", "--json"});
  ASSERT_EQ(mc.exit_code, 0) << mc.err;
  EXPECT_GT(json::parse(mc.out)["monte_carlo"]["p_within"].get<double>(), 0.95);
}

TEST(CliIdentify, BadInputIsOneLineAndNoFile) {
  CliSandbox box;
  const std::string model = write(box, "model.toml", std::string(kModel) + "mu = 0.3\n");
  const std::string good = write(box, "good.csv", measured_csv());
  const std::string no_time = write(box, "no_time.csv", "frame,x\n1,0\n2,1\n3,2\n");
  const std::string backwards = write(box, "back.csv", "t,x\n0,0\n0.2,1\n0.1,2\n");
  const std::string short_run = write(box, "short.csv", "t,x\n0,0\n0.001,0\n");
  const std::vector<std::string> outputs{"--out", "r.json", "--fit-csv", "f.csv",
                                         "--uncertainty-out", "u.toml"};
  auto run = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "identify");
    args.insert(args.end(), outputs.begin(), outputs.end());
    return box.run(args);
  };
  expect_clean_failure(box, run({"--data", no_time, "--config", model, "--free", "mu"}),
                       {"no_time.csv", "time"});
  expect_clean_failure(box, run({"--data", backwards, "--config", model, "--free", "mu"}),
                       {"back.csv:4", "time strictly increasing"});
  expect_clean_failure(box, run({"--data", short_run, "--config", model, "--free", "mu"}),
                       {"short.csv samples", "estimated parameters"});
  expect_clean_failure(box, run({"--data", good, "--config", model, "--free", "mu,c_mu"}),
                       {"c_mu", "not a parameter"});
  expect_clean_failure(box, run({"--data", good, "--config", model, "--free", "mu", "--loss",
                                 "huber"}),
                       {"loss"});
  expect_clean_failure(box, run({"--data", good, "--config", model, "--free", "mu",
                                 "--window-periods", "0"}),
                       {"window_periods"});
}

}  // namespace cli_identify_test
}  // namespace selfalign
