// `selfalign planar simulate|steady|field|stop` (apps/selfalign/cmd_planar.cpp): runs from a
// config file, and bad input (zero inertia, degenerate or self-intersecting polygons, load
// fractions that are negative or do not sum to 1, a NaN grid level, unknown keys) gives one
// line naming the parameter, exit code 2 and no file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_sandbox.hpp"
#include "sanitized.hpp"

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
mu_static = 0.3
[run]
step = 0.01
periods = 3
every = 10
transient = 5
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
  // Each row says whether it was computed; the report counts the ones that were not.
  EXPECT_EQ(stop["failures"]["count"].get<int>(), 0);
  for (const char* cmd : {"field", "stop"}) {
    const std::string csv = std::string(cmd) + ".csv";
    ASSERT_EQ(box.run({"planar", cmd, "--config", cfg, "--csv", csv}).exit_code, 0);
    const std::vector<std::string> rows = lines(read_text(box.work_file(csv)));
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows[0].substr(rows[0].rfind(',')), ",status") << cmd;
    EXPECT_EQ(rows[1].substr(rows[1].rfind(',')), ",ok") << cmd;
  }
}

// planar steady and planar field against a second method (issue 21: they were checked by
// their exit code only). A symmetric patch on a uniform table moving along x is the 1-D
// problem: its drift is the 1-D steady v̄ of `selfalign steady` (the exact solver, the
// paper's eq. 10), up to Moreau's O(h) error, with no sideways drift and no turn; every
// sample of the drift field on a uniform table is that same drift.
TEST(CliPlanar, SteadyAndFieldOnAUniformTableAreTheOneDimensionalSteadyState) {
  CliSandbox box;
  const auto one_d = box.run({"steady", "--profile", "three-phase", "--period", "1", "--stroke",
                              "0.084", "--a2", "3", "--a3", "0.9", "--mu", "0.3",
                              "--mu-static", "0.45", "--json"});  // s/k = 1.5 as below
  ASSERT_EQ(one_d.exit_code, 0) << one_d.err;
  const double v_bar = json::parse(one_d.out)["v_bar"].get<double>();
  double previous_error = 0;
  for (const double h : {0.002, 0.0005}) {
    std::string text = kBase + kPart;
    text.replace(text.find("step = 0.01"), 11, "step = " + std::to_string(h));
    text.replace(text.find("transient = 5"), 13, "transient = 10");
    const std::string cfg = write_config(box, "u.toml", text);
    const auto steady = box.run({"planar", "steady", "--config", cfg, "--json"});
    ASSERT_EQ(steady.exit_code, 0) << steady.err;
    const json j = json::parse(steady.out);
    const double error = std::abs(j["drift_x"].get<double>() - v_bar);
    // Moreau's error, measured 3.7e-4 at h = 2e-3 and 2.3e-5 at h = 5e-4 (v̄ = 0.0844): at
    // most first order, bounded by 0.25 h.
    EXPECT_LT(error, 0.25 * h) << h;
    EXPECT_LT(std::abs(j["drift_y"].get<double>()), 1e-15);
    EXPECT_LT(std::abs(j["rotation_rate"].get<double>()), 1e-15);
    EXPECT_FALSE(j["level_changed"].get<bool>());
    EXPECT_TRUE(j["converged"].get<bool>());
    if (previous_error > 0) EXPECT_LT(error, previous_error / 2) << "first order in h";
    previous_error = error;
    const auto field = box.run({"planar", "field", "--config", cfg, "--json"});
    ASSERT_EQ(field.exit_code, 0) << field.err;
    EXPECT_NEAR(json::parse(field.out)["largest_drift"].get<double>(), j["drift_x"].get<double>(),
                1e-12);
  }
}

// One coefficient convention (issue 21, F07 of issue 20): [friction] mu_static is absolute, the
// kinetic coefficient is [scales] mu, as --mu-static and --mu in the 1-D subcommands. The keys of
// the relative convention before it are refused by name, never read as absolute values; a
// static coefficient below the kinetic one names both.
TEST(CliPlanar, FrictionTakesAbsoluteCoefficientsAndRefusesTheOldRelativeKeys) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"static = 1.5\nkinetic = 1.0\n", "friction.static"},
      {"kinetic = 1.0\n", "friction.kinetic"},
      {"mu_static = 0.1\n", "friction.mu_static"},  // below [scales] mu = 0.2 (the default)
  };
  for (const auto& [friction, name] : cases) {
    CliSandbox box;
    std::string text = kBase + kPart;
    text.replace(text.find("mu_static = 0.3\n"), 16, friction);
    const std::string cfg = write_config(box, "p.toml", text);
    expect_clean_failure(box, box.run({"planar", "simulate", "--config", cfg, "--csv", "t.csv",
                                       "--out", "r.json"}),
                         {name});
  }
}

TEST(CliPlanar, BadInputNamesTheParameterAndLeavesNoFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[part]\ninertia = 0.0\n", "inertia"},
      {"[part]\ninertia = -1.0\n", "inertia"},
      {"[part]\ninertia = 0.01\nshape = \"polygon\"\nxs = [0.0, 1.0]\nys = [0.0, 1.0]\n",
       "part.xs, part.ys"},
      {"[part]\ninertia = 0.01\nshape = \"polygon\"\nxs = [0.0, 1.0, 1.0, 0.0]\nys = [0.0, 1.0, 0.0, 1.0]\n",
       "part.xs, part.ys"},
      {"[part]\ninertia = 0.01\nshape = \"points\"\nxs = [-0.1, 0.1]\nys = [0.0, 0.0]\nloads = [0.45, 0.45]\n",
       "part.loads"},
      {"[part]\ninertia = 0.01\nshape = \"points\"\nxs = [-0.1, 0.1, 0.0]\nys = [0.0, 0.0, 0.0]\nloads = [0.75, 0.75, -0.5]\n",
       "part.loads"},
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

// --set SECTION.KEY=VALUE (the one config reader's key table, issue 21): the same rows as a
// file that holds the value; an unknown key or a bad value is one line naming it, exit 2, no
// file, and the config is never changed.
TEST(CliPlanar, SetGivesAKeyOnTheCommandLineAsTheFileWould) {
  CliSandbox box;
  std::string edited = kBase + kPart;
  edited.replace(edited.find("periods = 3\n"), 12, "periods = 2\n");
  edited.replace(edited.find("step = 0.01\n"), 12, "step = 0.02\n");
  const std::string base = write_config(box, "p.toml", kBase + kPart);
  const std::string file = write_config(box, "q.toml", edited);
  ASSERT_EQ(box.run({"planar", "simulate", "--config", file, "--csv", "file.csv", "--quiet"}).exit_code, 0);
  const auto set = box.run({"planar", "simulate", "--config", base, "--set", "run.periods=2",
                            "--set", "run.step=0.02", "--csv", "set.csv", "--quiet"});
  ASSERT_EQ(set.exit_code, 0) << set.err;
  EXPECT_EQ(read_text(box.work_file("set.csv")), read_text(box.work_file("file.csv")));
  EXPECT_EQ(read_text(base), kBase + kPart);
  for (const auto& [assignment, name] :
       std::vector<std::pair<std::string, std::string>>{{"run.stepp=0.02", "--set = run.stepp"},
                                                        {"run.step=fast", "run.step"},
                                                        {"run.step=-1", "run.step"},
                                                        {"run.pose=0,0", "run.pose"},
                                                        {"run.step", "--set"}}) {
    CliSandbox bad;
    const std::string cfg = write_config(bad, "p.toml", kBase + kPart);
    expect_clean_failure(bad, bad.run({"planar", "simulate", "--config", cfg, "--set", assignment,
                                       "--csv", "t.csv", "--out", "r.json"}),
                         {name});
  }
}

// planar parameters: the view's names, values as the file gives them, and the CSV of them; a
// change by element name (field.levels[1]) is listed after it, and a bad one refused.
TEST(CliPlanar, ParametersListsTheModelsNumbersAsTheFileGivesThem) {
  CliSandbox box;
  const std::string cfg = write_config(
      box, "p.toml",
      kBase + kPart + "[field]\ntype = \"axis\"\npositions = [0.2, 0.4]\nlevels = [1, 3]\n");
  const auto r = box.run({"planar", "parameters", "--config", cfg, "--set", "field.levels[1]=2.5",
                          "--json", "--csv", "p.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["units"], "dimensionless");
  std::map<std::string, json> by_name;
  for (const json& p : j["parameters"]) by_name[p["name"].get<std::string>()] = p;
  EXPECT_EQ(by_name.at("table.x.a2")["value"].get<double>(), 3.0);
  EXPECT_EQ(by_name.at("table.x.a2")["unit"], "[-]");
  EXPECT_EQ(by_name.at("friction.mu_static")["value"].get<double>(), 0.3);
  EXPECT_EQ(by_name.at("part.length")["value"].get<double>(), 0.2);
  EXPECT_EQ(by_name.at("field.positions[1]")["value"].get<double>(), 0.4);
  EXPECT_EQ(by_name.at("field.levels[1]")["value"].get<double>(), 2.5);  // after --set
  EXPECT_EQ(by_name.count("run.step"), 0u);  // a setting
  EXPECT_EQ(by_name.count("part.nx"), 0u);   // discretisation
  const auto rows = lines(read_text(box.work_file("p.csv")));
  ASSERT_EQ(rows.size(), 1u + j["parameters"].size());
  EXPECT_EQ(rows[0], "name,value,unit,group");
  CliSandbox bad;
  const std::string bad_cfg = write_config(bad, "p.toml", kBase + kPart);
  expect_clean_failure(bad, bad.run({"planar", "parameters", "--config", bad_cfg, "--set",
                                     "run.pose[0]=1", "--csv", "p.csv"}),
                       {"--set", "run.pose"});
}

// examples/planar_axis.toml: a measured friction profile along the track (an axis field of
// ramps through (20, 1), (22, 1.6), (24, 2.3), (26, 2.8) mm). By hand: the 8 x 4 mm part's patch
// points (4 x 2 cells, equal loads) lie at x +- 1 and +- 3 mm; held in pure translation (the
// field and the patch are symmetric across the track) while s mean(m) >= peak/(mu_1 g), i.e.
// mean(m) >= (4.5/1.962)/1.2 = 1.911. The straight entry must stop where that first holds:
// holding at its end, not holding 1 mm before it (it stops within a millimetre of the spot).
TEST(CliPlanar, TheAxisFieldExampleStopsWhereThePatchIsFirstHeld) {
  CliSandbox box;
  std::vector<std::string> args{"planar", "stop", "--config",
                                std::string(SELFALIGN_SOURCE_DIR) + "/examples/planar_axis.toml",
                                "--csv", "runs.csv"};
  // The sanitizer build (a Debug build, ~100x slower here) takes 100 steps a period instead of
  // 500: where the patch is first held moves by 0.01 mm, far inside the 1 mm checked below.
  if (testing_support::kSanitized) args.insert(args.end(), {"--set", "run.step=2e-4"});
  const auto r = box.run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(read_text(box.work_file("runs.csv")));
  ASSERT_EQ(rows.size(), 4u);  // header and the three entries
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_NE(rows[i].find(",true,"), std::string::npos) << rows[i];  // stopped
  std::vector<std::string> cells;  // the straight entry's row: entry x, y, angle, stopped, end_x_m
  std::stringstream row(rows[1]);
  for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
  ASSERT_GT(cells.size(), 4u);
  const double end_x = std::stod(cells[4]);
  const auto level = [](double x_mm) {  // the ramps of the example, by hand
    const double p[] = {20, 22, 24, 26}, m[] = {1, 1.6, 2.3, 2.8};
    if (x_mm <= p[0]) return m[0];
    for (int k = 0; k < 3; ++k)
      if (x_mm <= p[k + 1]) return m[k] + (m[k + 1] - m[k]) * (x_mm - p[k]) / (p[k + 1] - p[k]);
    return m[3];
  };
  const auto mean_under = [&](double centre_mm) {
    return (level(centre_mm - 3) + level(centre_mm - 1) + level(centre_mm + 1) +
            level(centre_mm + 3)) / 4;
  };
  const double needed = (4.5 / (0.2 * 9.81)) / (0.24 / 0.2);
  EXPECT_GE(mean_under(end_x * 1e3), needed) << end_x;
  EXPECT_LT(mean_under(end_x * 1e3 - 1), needed) << end_x;
}

// A key the config's kinds do not read is said to have no effect, in one warning line after the
// output (exit 0); the run is the one without the key.
// [run] method = "exact": planar simulate by the exact point solver (planar_run.hpp). Second
// method: Moreau's run of the same config, which converges to it at first order, ends within
// 10 h x (its slip speed) of it; a patch part is refused by the key's name, nothing written.
TEST(CliPlanar, SimulateTakesTheExactPointSolver) {
  CliSandbox box;
  const std::string point = write_config(box, "point.toml", kBase + "[part]\ninertia = 0.01\n");
  const auto exact = box.run({"planar", "simulate", "--config", point, "--set",
                              "run.method=exact", "--json"});
  const auto moreau = box.run({"planar", "simulate", "--config", point, "--json"});
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  ASSERT_EQ(moreau.exit_code, 0) << moreau.err;
  const json e = json::parse(exact.out), m = json::parse(moreau.out);
  EXPECT_EQ(e["method"], "exact");
  EXPECT_EQ(m["method"], "time-stepping");
  const double ex = e["end_pose"]["x"].get<double>(), mx = m["end_pose"]["x"].get<double>();
  EXPECT_NE(ex, mx);
  EXPECT_NEAR(ex, mx, 10 * 0.01 * 0.5);  // 10 h at slip speeds below 0.5
  EXPECT_GT(std::abs(ex), 0.01);          // it moved
  CliSandbox bad;
  const std::string patch = write_config(bad, "patch.toml", kBase + kPart);
  expect_clean_failure(bad, bad.run({"planar", "simulate", "--config", patch, "--set",
                                     "run.method=exact", "--csv", "t.csv"}),
                       {"run.method"});
}

TEST(CliPlanar, AKeyNothingReadsIsWarnedAbout) {
  CliSandbox box;
  const std::string field = "[field]\ntype = \"axis\"\npositions = [0.2, 0.4]\nlevels = [1, 3]\n";
  const std::string with_key = write_config(box, "p.toml", kBase + kPart + field + "c_mu = 3\n");
  const std::string without = write_config(box, "q.toml", kBase + kPart + field);
  const auto r = box.run({"planar", "simulate", "--config", with_key, "--csv", "p.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "selfalign: warning: planar: field.c_mu is not used by this config (its kinds "
                   "do not read it): it has no effect\n");
  const auto q = box.run({"planar", "simulate", "--config", without, "--csv", "q.csv"});
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_TRUE(q.err.empty()) << q.err;
  EXPECT_EQ(read_text(box.work_file("p.csv")), read_text(box.work_file("q.csv")));
}

// planar steady is the fixed point of the period map (issue 21), and reports a part that walks
// into another region of the field instead of a drift. examples/planar.toml's pocket (a
// rectangle centred at x = 30 mm, half-length 8 mm, its band rising inward from x = 22 mm) with
// the 5 mm disc started at x = 17.8 mm: after 40 periods of transient the disc is in the band
// and still moving (checked independently on `planar simulate`'s path), so within 20 more
// periods there is no fixed point and the level under it changed: drift null, one warning.
// Started at the origin it stays clear of x = 22 mm and converges with no warning.
TEST(CliPlanar, SteadyReportsAPartEnteringThePocketInsteadOfADrift) {
  CliSandbox box;
  std::string text = read_text(std::string(SELFALIGN_SOURCE_DIR) + "/examples/planar.toml");
  const auto set = [&text](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  set("periods = 200", "periods = 60");
  set("every = 25 ", "every = 500");  // one row a period (500 steps of 4e-5 s in 0.02 s)
  const std::string clear = write_config(box, "clear.toml", text);
  set("pose = [0.0, 0.0, 0.0]", "pose = [0.0178, 0.0, 0.0]");
  set("transient = 20", "transient = 40");
  set("steady_periods = 2000", "steady_periods = 20");
  const std::string entering = write_config(box, "entering.toml", text);
  constexpr double kRadius = 0.005, kBandEdge = 0.022;  // [m], from the config

  const auto flagged = box.run({"planar", "steady", "--config", entering, "--json"});
  ASSERT_EQ(flagged.exit_code, 0) << flagged.err;
  const json f = json::parse(flagged.out);
  EXPECT_TRUE(f["level_changed"].get<bool>());
  EXPECT_FALSE(f["converged"].get<bool>());
  EXPECT_TRUE(f["drift_x"].is_null());
  EXPECT_TRUE(f["drift_y"].is_null());
  EXPECT_LT(f["level_under_part"]["min"].get<double>(), f["level_under_part"]["max"].get<double>());
  ASSERT_EQ(lines(flagged.err).size(), 1u) << flagged.err;
  EXPECT_EQ(flagged.err.rfind("selfalign: warning: planar steady: the friction level under the "
                              "part changed", 0),
            0u)
      << flagged.err;
  // The second method: the path itself reaches the band and still moves in its last periods.
  ASSERT_EQ(box.run({"planar", "simulate", "--config", entering, "--csv", "p.csv", "--quiet"})
                .exit_code,
            0);
  const auto rows = lines(read_text(box.work_file("p.csv")));
  ASSERT_EQ(rows.size(), 62u);  // header, t = 0 and 60 periods
  const auto x_at = [&rows](std::size_t i) { return std::stod(rows[i].substr(rows[i].find(',') + 1)); };
  EXPECT_GT(x_at(41) + kRadius, kBandEdge);
  EXPECT_GT(x_at(61), x_at(41) + 1e-5);

  const auto plain = box.run({"planar", "steady", "--config", clear, "--json"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_TRUE(plain.err.empty()) << plain.err;
  const json p = json::parse(plain.out);
  EXPECT_FALSE(p["level_changed"].get<bool>());
  EXPECT_TRUE(p["converged"].get<bool>());
  EXPECT_LT(p["end_pose"]["x"].get<double>() + kRadius, kBandEdge);
}

}  // namespace
}  // namespace selfalign
#endif
