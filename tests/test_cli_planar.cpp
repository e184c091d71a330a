// `selfalign planar simulate|steady|field|stop` (apps/selfalign/cmd_planar.cpp): runs from a
// config file, and bad input (zero inertia, degenerate or self-intersecting polygons, load
// fractions that are negative or do not sum to 1, a NaN grid level, unknown keys) gives one
// line naming the parameter, exit code 2 and no file.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH
namespace selfalign {
namespace {

using nlohmann::json;
using testing::CliSandbox;
using testing::expect_clean_failure;
using testing::lines;
using testing::read_text;

// Dimensionless: the paper's profile along x, 100 steps per period, a 2 x 2 rectangle patch.
const std::string kBase = R"(units = "dimensionless"
[table.x]
period = 1.0
stroke = 0.084
a2 = 3.0
a3 = 0.9
[friction]
static = 1.5
kinetic = 1.0
[run]
step = 0.01
periods = 3
every = 10
transient = 5
window = 2
[field_map]
x = [0.0, 0.5]
y = [0.0]
angles = [0.0, 0.5]
[stop]
entries = [[0.0, 0.0, 0.0], [0.0, 0.1, 0.3]]
max_periods = 200
)";

std::string write_config(const CliSandbox& box, const std::string& name, const std::string& text) {
  const std::string path = box.file(name);
  std::ofstream(path) << text;
  return path;
}

const std::string kPart = "[part]\ninertia = 0.01\nshape = \"rectangle\"\nlength = 0.2\nwidth = 0.1\nnx = 2\nny = 2\n";

TEST(CliPlanar, SimulateSteadyFieldAndStopRun) {
  CliSandbox box;
  const std::string cfg = write_config(
      box, "p.toml",
      kBase + kPart +
          "[field]\ntype = \"half-plane\"\norigin = [0.3, 0.0]\nwidth = 0.05\nc_mu = 2.5\n");
  const auto sim = box.run({"planar", "simulate", "--config", cfg, "--csv", "t.csv", "--out", "r.json"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_TRUE(sim.out.empty());
  EXPECT_TRUE(sim.err.empty());
  const auto rows = lines(read_text(box.work_file("t.csv")));
  ASSERT_EQ(rows.size(), 1u + 1u + 3u * 100u / 10u);  // header, t = 0, every 10th of 300 steps
  EXPECT_EQ(rows[0].rfind("t,x,y,angle_rad,ux,uy,omega,mode", 0), 0u);
  const json r = json::parse(read_text(box.work_file("r.json")));
  EXPECT_EQ(r["contact_points"].get<int>(), 4);
  EXPECT_EQ(r["census"]["stick"].get<int>() + r["census"]["pivot"].get<int>() +
                r["census"]["slip"].get<int>(),
            300);
  for (const char* cmd : {"steady", "field", "stop"}) {
    const auto res = box.run({"planar", cmd, "--config", cfg, "--json"});
    ASSERT_EQ(res.exit_code, 0) << cmd << ": " << res.err;
    const json j = json::parse(res.out);
    EXPECT_EQ(j["command"].get<std::string>(), std::string("planar ") + cmd);
  }
  const json stop = json::parse(box.run({"planar", "stop", "--config", cfg, "--json"}).out);
  EXPECT_EQ(stop["stopped"].get<int>(), 2);  // peak |y''| 3 < s c_mu = 3.75: held in the rough region
  EXPECT_GT(stop["mean_end"]["x"].get<double>(), 0.3);
}

TEST(CliPlanar, BadInputNamesTheParameterAndLeavesNoFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[part]\ninertia = 0.0\n", "inertia"},
      {"[part]\ninertia = -1.0\n", "inertia"},
      {"[part]\ninertia = 0.01\nshape = \"polygon\"\nxs = [0.0, 1.0]\nys = [0.0, 1.0]\n", "polygon"},
      {"[part]\ninertia = 0.01\nshape = \"polygon\"\nxs = [0.0, 1.0, 1.0, 0.0]\nys = [0.0, 1.0, 0.0, 1.0]\n",
       "polygon"},
      {"[part]\ninertia = 0.01\nshape = \"points\"\nxs = [-0.1, 0.1]\nys = [0.0, 0.0]\nloads = [0.45, 0.45]\n",
       "load_fractions"},
      {"[part]\ninertia = 0.01\nshape = \"points\"\nxs = [-0.1, 0.1, 0.0]\nys = [0.0, 0.0, 0.0]\nloads = [0.75, 0.75, -0.5]\n",
       "load_fractions"},
      {kPart + "[field]\ntype = \"grid\"\ndx = 1.0\ndy = 1.0\nnx = 2\nny = 2\nlevels = [1.0, nan, 1.0, 1.0]\n",
       "levels"},
      {kPart + "colour = \"red\"\n", "part.colour"},
  };
  for (const auto& [extra, name] : cases) {
    CliSandbox box;
    const std::string cfg = write_config(box, "p.toml", kBase + extra);
    expect_clean_failure(box, box.run({"planar", "simulate", "--config", cfg, "--csv", "t.csv",
                                       "--out", "r.json"}),
                         {name});
  }
}

}  // namespace
}  // namespace selfalign
#endif
