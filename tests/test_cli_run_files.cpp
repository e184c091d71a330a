// The CLI's inputs and outputs as one registry (issue 20): an output never replaces an input of
// any subcommand, however spelled (D24), two outputs never name one file (D25), every JSON/TOML
// input is read with a nesting limit and clean errors (D23, D31), and a design report's values
// are typed (D30). Every case is refused while parsing or reading, before any work: cheap.
#include <gtest/gtest.h>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

using namespace selfalign::testing;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A design report as `selfalign design --json` writes it (the keys montecarlo reads), for the
// process of montecarlo's own flag examples (docs/cli.md).
json design_report() {
  return json::parse(R"({
    "units": "si", "feasible": true,
    "profile": {"kind": "three-phase", "jerk_m_per_s3": null, "period_s": 0.05,
                "stroke_m": 0.0005, "a2_m_per_s2": 5, "a3_m_per_s2": 4},
    "x_mu_m": 0.05,
    "request": {"mass_kg": 1, "width_m": 0.01, "mu": 0.3, "c_mu": 2.5, "g_m_per_s2": 9.81,
                "mu_static": null, "mu_backward": null, "distance_m": 0.055,
                "tolerance_m": 0.001}})");
}

const std::vector<std::string> kDesign = {"design", "--acceleration-grid", "4", "--period-grid",
                                          "2", "--stroke-grid", "1", "--entries", "3",
                                          "--quiet"};
const std::vector<std::string> kProcess = {"montecarlo", "--period-s", "0.05", "--stroke-m",
                                           "0.0005", "--a2", "5", "--a3", "4", "--x-mu", "0.05",
                                           "--runs", "20", "--quiet"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

const char kUncertainty[] = "mu = \"normal:0.3,3%\"\n";

}  // namespace

// D24: montecarlo --out over its --design report, --runs-csv over its --uncertainty-file, design
// --profile-csv through a link to the uncertainty file and --out as sub/../ of it: all refused
// while parsing, the inputs unchanged, nothing written.
TEST(CliRunFiles, NoOutputReplacesTheDesignReportOrTheUncertaintyFile) {
  CliSandbox box;
  const std::string report = design_report().dump();
  write_text(box.work_file("d.json"), report);
  write_text(box.work_file("u.toml"), kUncertainty);
  fs::create_directory(box.work_file("sub"));
  fs::create_symlink("u.toml", box.work_file("lnk"));
  expect_one_line_error(box.run({"montecarlo", "--design", "d.json", "--uncertain", "mu=normal:0.3,3%",
                          "--runs", "20", "--quiet", "--out", "d.json"}),
                 {"out = d.json", "--design"});
  expect_one_line_error(box.run({"montecarlo", "--design", "./d.json", "--uncertainty-file", "u.toml",
                          "--runs", "20", "--quiet", "--runs-csv", "u.toml"}),
                 {"runs-csv = u.toml", "--uncertainty-file"});
  expect_one_line_error(box.run(with(kDesign, {"--uncertainty-file", "u.toml", "--monte-carlo", "20",
                                        "--profile-csv", "lnk"})),
                 {"profile-csv = lnk", "--uncertainty-file"});
  expect_one_line_error(box.run(with(kDesign, {"--uncertainty-file", "u.toml", "--monte-carlo", "20",
                                        "--out", "sub/../u.toml"})),
                 {"out = sub/../u.toml", "--uncertainty-file"});
  // The input named after the output is refused the same way (order does not matter).
  expect_one_line_error(box.run({"montecarlo", "--out", "sub/../d.json", "--design", "d.json",
                          "--uncertain", "mu=normal:0.3,3%", "--runs", "20", "--quiet"}),
                 {"out = sub/../d.json", "--design"});
  EXPECT_EQ(read_text(box.work_file("d.json")), report);
  EXPECT_EQ(read_text(box.work_file("u.toml")), kUncertainty);
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"d.json", "lnk", "sub", "u.toml"}));
}

// D25: two outputs of one run naming one file differently (./x and x, sub/../x) are refused by
// design, montecarlo, planar and simulate alike, before any work.
TEST(CliRunFiles, TwoOutputsNamingOneFileAreRefused) {
  CliSandbox box;
  fs::create_directory(box.work_file("sub"));
  write_text(box.file("p.toml"),
             "units = \"dimensionless\"\n[table.x]\nprofile = \"three-phase\"\nperiod = 1.0\n"
             "stroke = 0.084\na2 = 3.0\na3 = 0.9\n[part]\nmass = 1.0\ninertia = 0.01\n"
             "shape = \"point\"\n[run]\nstep = 0.02\nperiods = 3\n");
  expect_one_line_error(box.run(with(kDesign, {"--out", "./same.out", "--profile-csv", "same.out"})),
                 {"profile-csv = same.out", "--out"});
  expect_one_line_error(box.run(with(kProcess, {"--uncertain", "mu=normal:0.3,3%", "--out",
                                         "sub/../same.out", "--runs-csv", "./same.out"})),
                 {"runs-csv = ./same.out", "--out"});
  expect_one_line_error(box.run({"planar", "simulate", "--config", box.file("p.toml"), "--quiet",
                          "--out", "./same.out", "--csv", "same.out"}),
                 {"same.out", "--csv"});
  expect_one_line_error(box.run({"simulate", "--periods", "1", "--out", "./o.csv", "--summary",
                          "sub/../o.csv"}),
                 {"summary = sub/../o.csv", "--out"});
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"sub"});
}

// D23, D31: a deeply nested uncertainty file or design report is one error line naming the file
// and the place (was: SIGSEGV), and parse errors show no library internals.
TEST(CliRunFiles, NestedOrMalformedDocumentsAreOneCleanLine) {
  CliSandbox box;
  const int deep = 100000;
  write_text(box.file("u.json"),
             "{\"mu\": " + std::string(deep, '[') + std::string(deep, ']') + "}");
  write_text(box.file("d.json"),
             "{\"profile\": " + std::string(deep, '[') + std::string(deep, ']') + "}");
  write_text(box.file("dot.toml"), "mu" + std::string(deep, '.') + "a = 1\n");
  const std::string u = box.file("u.json"), d = box.file("d.json"), t = box.file("dot.toml");
  expect_one_line_error(box.run(with(kProcess, {"--uncertainty-file", u})),
                 {"uncertainty-file = " + u, "nests too deeply at line 1, column 9"});
  expect_one_line_error(box.run(with(kDesign, {"--uncertainty-file", u})), {"nests too deeply"});
  expect_one_line_error(box.run(with(kProcess, {"--uncertainty-file", t})),
                 {"uncertainty-file = " + t, "nests too deeply at line 1, column 4"});
  expect_one_line_error(box.run({"montecarlo", "--design", d, "--uncertain", "mu=normal:0.3,3%"}),
                 {"design = " + d, "nests too deeply at line 1, column"});
  write_text(box.file("o.json"), "{\"x_mu_m\": 1e999}");
  const CliResult r = box.run({"montecarlo", "--design", box.file("o.json")});
  expect_one_line_error(r, {"design = " + box.file("o.json"), "line 1, column 16", "number overflow"});
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  EXPECT_TRUE(box.work_entries().empty());
}

// D30: every value montecarlo reads from a design report has its type (a number; null only
// where the report writes null: no jerk limit, no mu_static / mu_backward), else the run is
// refused naming the key, instead of falling back to a default.
TEST(CliRunFiles, DesignReportValuesOfTheWrongTypeAreRefused) {
  CliSandbox box;
  const std::vector<std::pair<json::json_pointer, json>> wrong = {
      {json::json_pointer("/profile/jerk_m_per_s3"), json::array({1})},
      {json::json_pointer("/profile/jerk_m_per_s3"), "500"},
      {json::json_pointer("/profile/jerk_m_per_s3"), true},
      {json::json_pointer("/profile/period_s"), nullptr},
      {json::json_pointer("/x_mu_m"), "0.05"},
      {json::json_pointer("/request/distance_m"), true},
      {json::json_pointer("/request/c_mu"), "2.5"},
      {json::json_pointer("/request/mass_kg"), nullptr},
      {json::json_pointer("/request/mu_static"), "1.2"},
  };
  for (const auto& [pointer, value] : wrong) {
    json report = design_report();
    report[pointer] = value;
    write_text(box.file("bad.json"), report.dump());
    std::string key = pointer.to_string().substr(1);
    std::replace(key.begin(), key.end(), '/', '.');
    expect_one_line_error(box.run({"montecarlo", "--design", box.file("bad.json"), "--uncertain",
                            "mu=normal:0.3,3%", "--runs", "20", "--quiet"}),
                   {"invalid " + key + " = " + value.dump(), "--design report"});
  }
  json report = design_report();  // a missing key is refused too
  report["request"].erase("width_m");
  write_text(box.file("bad.json"), report.dump());
  expect_one_line_error(box.run({"montecarlo", "--design", box.file("bad.json")}),
                 {"request.width_m = missing"});
  // The report as written (null: no jerk limit) and with a jerk limit: evaluated as written.
  for (const json jerk : {json(nullptr), json(2000.0)}) {
    report = design_report();
    report["profile"]["jerk_m_per_s3"] = jerk;
    write_text(box.file("ok.json"), report.dump());
    const CliResult r = box.run({"montecarlo", "--design", box.file("ok.json"), "--uncertain",
                                 "mu=normal:0.3,3%", "--runs", "20", "--quiet", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["process"]["jerk_m_per_s3"], jerk);
    EXPECT_EQ(j["monte_carlo"]["target_m"].get<double>(), 0.055);
  }
  EXPECT_TRUE(box.work_entries().empty());
}

#endif  // SELFALIGN_CLI_PATH
