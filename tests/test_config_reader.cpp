// The one config reader (io/config_reader.hpp, issue 21 item 6): a key table with sections
// drives reading a document, parsing command-line text and converting to model units, for the
// 1-D config (one flat table) and the planar config (sections) alike. Expected values are the
// documents' own numbers and the unit conversions of Sect. 3.2 written out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "expect_invalid.hpp"
#include "temp_dir.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/planar_config.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {
namespace {

using nlohmann::json;
using testing::expect_invalid;
using testing::TempDir;
using testing::write_text;
using testing::read_text;
using D = Dimension;
using V = ValueType;

constexpr std::array<Dimension, 3> kPose{D::length, D::length, D::none};

// A small table written for this test: a top-level key, a section, a nested section.
const std::vector<KeySpec>& test_keys() {
  static const std::vector<KeySpec> keys{
      {"", "units", V::text},
      {"part", "radius", V::number, D::length},
      {"part", "loads", V::numbers, D::none},
      {"table.x", "period", V::number, D::time},
      {"table.x", "a2", V::number, D::acceleration},
      {"table.x", "stroke", V::number, D::length},
      {"table.x", "cos", V::numbers, D::length},
      {"run", "pose", V::numbers, D::none, kPose, "[x, y, angle]"},
      {"stop", "entries", V::rows, D::none, kPose, "[x, y, angle]"},
  };
  return keys;
}
const KeyTable kTable{test_keys(), "docs/test.md"};

TEST(ConfigReader, ReadsSectionsAndConvertsEachKeyByItsDimension) {
  const json doc = json::parse(R"({"units": "si",
      "part": {"radius": 0.02, "loads": [0.25, 0.75]},
      "table": {"x": {"period": 0.02, "a2": 4.5, "cos": [0.001, 0.002]}},
      "run": {"pose": [0.01, 0.03, 0.5]},
      "stop": {"entries": [[0.01, 0.0, 1.0], [0.0, 0.02, -1.0]]}})");
  const ConfigValues values = read_config_values(doc, kTable, "t.json");
  EXPECT_EQ(values.entries().size(), 8u);
  EXPECT_TRUE(values.has_section("table.x"));
  EXPECT_FALSE(values.has_section("table.y"));

  // SI with L = 0.01 m, mu = 0.2, g = 9.81 m/s^2: T = sqrt(L/(mu g)) (Sect. 3.2).
  const Scales scales(0.01, 0.2, 9.81);
  const InputUnits si(scales);
  const double L = 0.01, T = std::sqrt(0.01 / (0.2 * 9.81)), a = 0.2 * 9.81;
  const ConfigSection part(values, "part", si), x(values, "table.x", si), run(values, "run", si);
  EXPECT_DOUBLE_EQ(part.required("radius"), 0.02 / L);
  EXPECT_EQ(part.list("loads"), (std::vector<double>{0.25, 0.75}));  // [-]: as written
  EXPECT_DOUBLE_EQ(x.required("period"), 0.02 / T);
  EXPECT_DOUBLE_EQ(x.number("a2", 0.0), 4.5 / a);
  const std::vector<double> cos = x.list("cos");
  ASSERT_EQ(cos.size(), 2u);
  EXPECT_DOUBLE_EQ(cos[1], 0.002 / L);
  const std::vector<double> pose = run.list("pose");
  EXPECT_DOUBLE_EQ(pose[0], 0.01 / L);
  EXPECT_DOUBLE_EQ(pose[1], 0.03 / L);
  EXPECT_EQ(pose[2], 0.5);  // the angle component has no dimension
  const auto rows = ConfigSection(values, "stop", si).rows("entries");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[1][1], 0.02 / L);
  EXPECT_EQ(rows[1][2], -1.0);
  // A fallback is in file units and converts like a value; dimensionless input is as written.
  EXPECT_DOUBLE_EQ(x.number("stroke", 0.001), 0.001 / L);
  EXPECT_EQ(ConfigSection(values, "part", InputUnits()).required("radius"), 0.02);
  // Unset keys: required ones are named with their section.
  expect_invalid([&] { x.required("stroke"); }, "table.x.stroke");
}

TEST(ConfigReader, RefusesUnknownKeysWrongTypesAndLengthsNamingTheKeyWithItsSection) {
  const auto read = [](const char* text) { return read_config_values(json::parse(text), kTable, "t.json"); };
  std::string m = expect_invalid([&] { read(R"({"part": {"radus": 1}})"); }, "config key");
  EXPECT_NE(m.find("part.radus"), std::string::npos) << m;
  EXPECT_NE(m.find("unknown key of [part] (did you mean radius?)"), std::string::npos) << m;
  EXPECT_NE(m.find("keys of [part]: radius, loads; every one in docs/test.md (in t.json)"),
            std::string::npos)
      << m;
  m = expect_invalid([&] { read(R"({"tabel": {}})"); }, "config key");
  EXPECT_NE(m.find("(did you mean table?)"), std::string::npos) << m;
  m = expect_invalid([&] { read(R"({"table": {"z": {}}})"); }, "config key");
  EXPECT_NE(m.find("keys of [table]: x;"), std::string::npos) << m;

  m = expect_invalid([&] { read(R"({"part": {"radius": "big"}})"); }, "part.radius");
  EXPECT_NE(m.find("must be a number (in t.json)"), std::string::npos) << m;
  expect_invalid([&] { read(R"({"units": 1})"); }, "units");
  expect_invalid([&] { read(R"({"part": 3})"); }, "part");
  expect_invalid([&] { read(R"({"table": {"x": {"cos": [1, "a"]}}})"); }, "table.x.cos");
  m = expect_invalid([&] { read(R"({"run": {"pose": [1, 2]}})"); }, "run.pose");
  EXPECT_NE(m.find("2 values: must be [x, y, angle]"), std::string::npos) << m;
  expect_invalid([&] { read(R"({"stop": {"entries": [[1, 2, 3], [1, 2]]}})"); }, "stop.entries");
  expect_invalid([&] { read(R"({"stop": {"entries": [1, 2, 3]}})"); }, "stop.entries");
  expect_invalid([&] { read(R"([1, 2])"); }, "config file");
}

TEST(ConfigReader, ParsesCommandLineTextByTheKeysType) {
  const KeySpec& radius = *kTable.find("part", "radius");
  EXPECT_EQ(std::get<double>(parse_config_value(radius, " +4e-5 ")), 4e-5);
  EXPECT_TRUE(std::isnan(std::get<double>(parse_config_value(radius, "nan"))));  // ranges: the model's
  expect_invalid([&] { parse_config_value(radius, "4e-5m"); }, "part.radius");
  const KeySpec& loads = *kTable.find("part", "loads");
  EXPECT_EQ(std::get<std::vector<double>>(parse_config_value(loads, "[0.25, 0.75]")),
            (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(std::get<std::vector<double>>(parse_config_value(loads, "0.25,0.75")),
            (std::vector<double>{0.25, 0.75}));
  EXPECT_TRUE(std::get<std::vector<double>>(parse_config_value(loads, "")).empty());
  expect_invalid([&] { parse_config_value(loads, "0.25;0.75"); }, "part.loads");
  expect_invalid([&] { parse_config_value(*kTable.find("run", "pose"), "0,0"); }, "run.pose");
  const KeySpec& entries = *kTable.find("stop", "entries");
  EXPECT_EQ(std::get<std::vector<std::vector<double>>>(parse_config_value(entries, "[[0, 1, 2]]")),
            (std::vector<std::vector<double>>{{0, 1, 2}}));
  expect_invalid([&] { parse_config_value(entries, "[[0, 1]]"); }, "stop.entries");
  expect_invalid([&] { parse_config_value(entries, "[[0, 1, 2]"); }, "stop.entries");
  EXPECT_EQ(std::get<std::string>(parse_config_value(*kTable.find("", "units"), "si")), "si");
}

TEST(ConfigReader, KnowsItsSections) {
  EXPECT_TRUE(kTable.has_section(""));
  EXPECT_TRUE(kTable.has_section("table"));
  EXPECT_TRUE(kTable.has_section("table.x"));
  EXPECT_FALSE(kTable.has_section("tab"));
  EXPECT_FALSE(kTable.has_section("table.xx"));
  EXPECT_FALSE(kTable.has_section("part.radius"));
}

// The 1-D config (one flat table) and the planar config (sections) are read by the same
// reader: the same refusal for an unknown key and a wrong type, each naming its table's docs.
TEST(ConfigReader, OneReaderForTheOneDimensionalAndThePlanarConfig) {
  TempDir dir;
  write_text(dir.file("c.toml"), "widht = 0.05\n");
  std::string m = expect_invalid([&] { load_simulate_config(dir.file("c.toml")); }, "config key");
  EXPECT_NE(m.find("unknown key (did you mean width?); keys: units, method, profile, period, "
                   "stroke, a2, a3, ..., every one in docs/config.md"),
            std::string::npos)
      << m;
  write_text(dir.file("p.toml"), "[part]\ninertia = 1e-8\nradus = 0.01\n");
  m = expect_invalid([&] { load_planar_config(dir.file("p.toml")); }, "config key");
  EXPECT_NE(m.find("part.radus: unknown key of [part] (did you mean radius?); keys of [part]: "
                   "mass, inertia, shape, radius, rings, sectors, length, ..., every one in "
                   "docs/planar.md"),
            std::string::npos)
      << m;
  write_text(dir.file("c.json"), R"({"width": "wide"})");
  m = expect_invalid([&] { load_simulate_config(dir.file("c.json")); }, "width");
  EXPECT_NE(m.find("must be a number (in "), std::string::npos) << m;
  write_text(dir.file("p.json"), R"({"part": {"inertia": "heavy"}})");
  m = expect_invalid([&] { load_planar_config(dir.file("p.json")); }, "part.inertia");
  EXPECT_NE(m.find("must be a number (in "), std::string::npos) << m;
  // A flag's text is parsed by the same table: --width wide.
  SimulateConfig c;
  expect_invalid([&] { set_simulate_config_value(c, "width", "wide"); }, "width");
  set_simulate_config_value(c, "accelerations", "[1, -1]");
  EXPECT_EQ(c.accelerations, (std::vector<double>{1, -1}));
}

const char* kPlanar = R"(
[scales]
length = 0.01
[table.x]
period = 0.02
stroke = 0.00008
a2 = 4.5
a3 = 3.0
[part]
inertia = 1e-8
[run]
step = 1e-4
periods = 3
)";

// Regression: a section's key refused inside a builder that names its library parameters with
// the section as prefix was named twice ("field.field.nx", "scales.scales.mu").
TEST(PlanarConfig, NamesAKeyWithItsSectionOnce) {
  TempDir dir;
  write_text(dir.file("g.toml"), std::string(kPlanar) +
                                     "[field]\ntype = \"grid\"\ndx = 0.01\ndy = 0.01\nnx = 2.5\n"
                                     "ny = 2\nlevels = [1, 1, 1, 1]\n");
  expect_invalid([&] { load_planar_config(dir.file("g.toml")); }, "field.nx");
  write_text(dir.file("c.toml"), std::string(kPlanar) + "[field]\ntype = \"circle\"\n");
  expect_invalid([&] { load_planar_config(dir.file("c.toml")); }, "field.radius");
  write_text(dir.file("s.toml"), "[scales]\nmu = \"a\"\n");
  expect_invalid([&] { load_planar_config(dir.file("s.toml")); }, "scales.mu");
}

// --set SECTION.KEY=VALUE is the file's value given on the command line: the same setup as a
// file that holds it, converted by the key's dimension.
TEST(PlanarConfig, SetIsTheFilesValueGivenOnTheCommandLine) {
  TempDir dir;
  write_text(dir.file("p.toml"), kPlanar);
  write_text(dir.file("q.toml"), std::regex_replace(std::string(kPlanar), std::regex("periods = 3"),
                                                    "periods = 5\npose = [0.001, 0.0, 0.5]"));
  const PlanarSetup set = load_planar_config(dir.file("p.toml"), {"run.periods=5", "run.pose=0.001,0,0.5"});
  const PlanarSetup file = load_planar_config(dir.file("q.toml"));
  EXPECT_EQ(set.periods, 5);
  EXPECT_EQ(set.pose.x, file.pose.x);
  EXPECT_DOUBLE_EQ(set.pose.x, 0.001 / 0.01);  // [m] / L
  EXPECT_EQ(set.pose.angle, 0.5);
  // A new table is made for a key of a section the file lacks; the value is checked as the
  // file's would be.
  const PlanarSetup y = load_planar_config(
      dir.file("p.toml"), {"table.y.profile=fourier", "table.y.period=0.01", "table.y.cos=0.00001",
                           "table.y.sin=0"});
  EXPECT_NE(y.problem.motion.second, nullptr);
  expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"run.step=-1"}); }, "run.step");
  expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"run.pose=0,0"}); }, "run.pose");
  std::string m = expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"run.stepp=1"}); }, "--set");
  EXPECT_NE(m.find("did you mean step?"), std::string::npos) << m;
  expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"run.step"}); }, "--set");
  expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"table.x=1"}); }, "--set");
  expect_invalid([&] { load_planar_config(dir.file("p.toml"), {"tabel.x.a2=1"}); }, "--set");
}

// [field] type = "axis": the 1-D field along a direction, from positions/levels or a CSV file
// (positions in [m], converted by L = 0.01 m: 0.003 m is 0.3 L), each the same field.
TEST(PlanarConfig, AnAxisFieldIsTheOneDimensionalFieldFromTheConfigOrAFile) {
  TempDir dir;
  write_text(dir.file("f.csv"), "position,level\n0.003,1\n0.004,2.5\n");
  write_text(dir.file("a.toml"), std::string(kPlanar) +
                                     "[field]\ntype = \"axis\"\npositions = [0.003, 0.004]\n"
                                     "levels = [1, 2.5]\nangle = 0.5\norigin = [0.001, 0]\n");
  write_text(dir.file("b.toml"), std::string(kPlanar) + "[field]\ntype = \"axis\"\nfile = \"" +
                                     dir.file("f.csv") + "\"\nangle = 0.5\norigin = [0.001, 0]\n");
  const PlanarSetup a = load_planar_config(dir.file("a.toml"));
  const PlanarSetup b = load_planar_config(dir.file("b.toml"));
  const auto* fa = std::get_if<AxisField>(&a.problem.field);
  const auto* fb = std::get_if<AxisField>(&b.problem.field);
  ASSERT_NE(fa, nullptr);
  ASSERT_NE(fb, nullptr);
  EXPECT_EQ(*fa, *fb);
  EXPECT_DOUBLE_EQ(fa->origin_x, 0.1);  // 0.001 m / L
  EXPECT_EQ(fa->angle, 0.5);
  ASSERT_EQ(fa->field.nodes().size(), 1u);  // steps: 1 before 0.4 L, 2.5 from there
  EXPECT_DOUBLE_EQ(fa->field.nodes()[0].position, 0.4);
  EXPECT_EQ(fa->field.nodes()[0].left, 1.0);
  EXPECT_EQ(fa->field.nodes()[0].right, 2.5);
  // linear interpolation: a ramp between the samples
  const PlanarSetup lin = load_planar_config(dir.file("a.toml"), {"field.interpolation=linear"});
  EXPECT_NEAR(planar_level(lin.problem.field, 0.1 + 0.35 * std::cos(0.5), 0.35 * std::sin(0.5)),
              1.75, 1e-12);
  // bad input names the key
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.levels=1,0"}); },
                 "field.levels");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.levels=1"}); },
                 "field.levels");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.positions=0.004,0.003"}); },
                 "field.positions");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.interpolation=cubic"}); },
                 "field.interpolation");
  expect_invalid([&] { load_planar_config(dir.file("b.toml"), {"field.levels=1,2"}); },
                 "field.file");
}

// The planar parameter view: the numbers the model read, as the file gives them (defaults where
// unset), settings left out, arrays by element, only the keys the config's kinds read; and a
// parameter changed by its name is the file that holds that value (second method: the file).
TEST(PlanarConfig, TheParameterViewListsWhatTheModelReadAsTheFileGivesIt) {
  TempDir dir;
  const std::string axis = "[field]\ntype = \"axis\"\npositions = [0.003, 0.004]\nlevels = [1, 2.5]\n";
  write_text(dir.file("a.toml"), std::string(kPlanar) + axis);
  std::map<std::string, ModelParameter> view;
  for (const ModelParameter& p : planar_model_parameters(dir.file("a.toml"))) {
    EXPECT_TRUE(view.emplace(p.name, p).second) << "listed twice: " << p.name;
  }
  const auto expect = [&](const std::string& name, double value, const std::string& unit) {
    const auto it = view.find(name);
    ASSERT_NE(it, view.end()) << name;
    EXPECT_EQ(it->second.value, value) << name;
    EXPECT_EQ(it->second.unit, unit) << name;
  };
  expect("table.x.a2", 4.5, "[m/s^2]");            // the file's numbers, in its units
  expect("table.x.period", 0.02, "[s]");
  expect("part.inertia", 1e-8, "[kg m^2]");
  expect("scales.mu", 0.2, "[-]");                 // defaults where the file is silent
  expect("scales.g", 9.81, "[m/s^2]");
  expect("field.positions[0]", 0.003, "[m]");
  expect("field.levels[1]", 2.5, "[-]");
  expect("field.angle", 0.0, "[rad]");
  expect("run.pose[0]", 0.0, "[m]");
  expect("run.pose[2]", 0.0, "[rad]");
  expect("run.twist[2]", 0.0, "[rad/s]");
  for (const char* absent : {"field.c_mu", "field.width", "run.step", "run.periods",
                             "scales.length", "part.mass", "table.x.jerk", "stop.max_periods"})
    EXPECT_EQ(view.count(absent), 0u) << absent;
  EXPECT_EQ(view.at("field.levels[1]").group, "field");

  // By name, as the file: levels [1, 3] and a2 = 5.
  write_text(dir.file("b.toml"), std::regex_replace(std::string(kPlanar) + axis,
                                                    std::regex("levels = \\[1, 2.5\\]"),
                                                    "levels = [1, 3]"));
  write_text(dir.file("b.toml"), std::regex_replace(read_text(dir.file("b.toml")),
                                                    std::regex("a2 = 4.5"), "a2 = 5"));
  const PlanarSetup set = load_planar_config(dir.file("a.toml"), {"field.levels[1]=3", "table.x.a2=5"});
  const PlanarSetup file = load_planar_config(dir.file("b.toml"));
  EXPECT_EQ(std::get<AxisField>(set.problem.field), std::get<AxisField>(file.problem.field));
  EXPECT_EQ(set.problem.motion.first->peak_acceleration(),
            file.problem.motion.first->peak_acceleration());
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.levels[2]=3"}); }, "--set");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"run.pose[0]=3"}); }, "--set");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"run.step[0]=3"}); }, "--set");
  expect_invalid([&] { load_planar_config(dir.file("a.toml"), {"field.levels[x]=3"}); }, "--set");

  // A dimensionless config: lengths in [-], angles in [rad].
  write_text(dir.file("d.toml"), "units = \"dimensionless\"\n[table.x]\nperiod = 1\nstroke = 0.084\n"
                                 "a2 = 3\na3 = 0.9\n[part]\ninertia = 0.5\n[run]\nstep = 0.01\n"
                                 "pose = [0.1, 0.2, 0.3]\n");
  std::map<std::string, ModelParameter> d;
  for (const ModelParameter& p : planar_model_parameters(dir.file("d.toml"))) d.emplace(p.name, p);
  EXPECT_EQ(d.at("run.pose[1]").value, 0.2);
  EXPECT_EQ(d.at("run.pose[1]").unit, "[-]");
  EXPECT_EQ(d.at("run.pose[2]").unit, "[rad]");
  EXPECT_EQ(d.at("table.x.a2").unit, "[-]");
  EXPECT_EQ(d.at("part.inertia").unit, "[-]");
  EXPECT_EQ(d.count("field.level"), 1u);  // the default uniform field's level
}

// Keys a config gives that its kinds do not read are listed (the CLI warns): an axis field has
// no band (width, c_mu), a three-phase motion no Fourier coefficients, a point part no radius.
TEST(PlanarConfig, KeysNothingReadsAreListed) {
  TempDir dir;
  write_text(dir.file("a.toml"),
             std::string(kPlanar) + "[field]\ntype = \"axis\"\npositions = [0.003]\nlevels = [1]\n"
                                    "c_mu = 3\nwidth = 0.001\n");
  const PlanarSetup a = load_planar_config(dir.file("a.toml"), {"table.x.cos=1", "part.radius=0.01"});
  std::vector<std::string> unused = a.unused_keys;
  std::sort(unused.begin(), unused.end());
  EXPECT_EQ(unused, (std::vector<std::string>{"field.c_mu", "field.width", "part.radius",
                                              "table.x.cos"}));
  write_text(dir.file("b.toml"), kPlanar);
  EXPECT_TRUE(load_planar_config(dir.file("b.toml")).unused_keys.empty());
}

// Every key of the planar key table is documented in docs/planar.md (as `key`).
TEST(PlanarConfig, EveryKeyIsDocumented) {
  std::ifstream in(std::string(SELFALIGN_SOURCE_DIR) + "/docs/planar.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(doc.empty());
  for (const KeySpec& key : planar_config_keys().keys) {
    EXPECT_NE(doc.find("`" + std::string(key.name) + "`"), std::string::npos) << key.name;
    EXPECT_FALSE(key.help.empty()) << key.name;
  }
}

}  // namespace
}  // namespace selfalign
