// Tests of the config layer (include/selfalign/io/): keys, loading, merging, SI resolution,
// model building, atomic files, CSV and JSON output. The CLI itself is tested in test_cli.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/io/trajectory_csv.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "expect_invalid.hpp"
#include "temp_dir.hpp"

namespace selfalign {
namespace {

using testing::read_text;
using testing::TempDir;
using testing::write_text;

// Unit conversions are a multiply or divide each way: a round trip is exact to a few ulps.
constexpr double kRoundTripTolerance = 1e-15;

using testing::expect_invalid;

TEST(SimulateConfigKeys, EveryKeyHasAFlagAndHelp) {
  for (const ConfigKey& key : simulate_config_keys()) {
    const std::string flag = config_flag(key);
    EXPECT_EQ(flag.find('_'), std::string::npos) << flag;
    EXPECT_EQ(flag.substr(0, 2), "--");
    EXPECT_FALSE(config_help(key).empty()) << key.name;
    EXPECT_EQ(find_simulate_config_key(key.name), &key);
  }
  EXPECT_EQ(config_flag(*find_simulate_config_key("c_mu")), "--c-mu");
  EXPECT_EQ(config_flag(*find_simulate_config_key("output_step")), "--output-step");
  EXPECT_EQ(find_simulate_config_key("nonsense"), nullptr);
  // Help states the unit in both systems and the default with its SI conversion.
  const std::string width = config_help(*find_simulate_config_key("width"));
  EXPECT_NE(width.find("[-]"), std::string::npos) << width;
  EXPECT_NE(width.find("[m]"), std::string::npos) << width;
  EXPECT_NE(width.find("0.05"), std::string::npos) << width;
}

TEST(SimulateConfigDefaults, AreThePapersSection72Setting) {
  const SimulateConfig d = simulate_config_defaults();
  EXPECT_EQ(*d.units, "dimensionless");
  EXPECT_EQ(*d.method, "exact");
  EXPECT_EQ(*d.profile, "three-phase");
  EXPECT_EQ(*d.period, 1.0);    // Δt = 1, Sect. 7.2
  EXPECT_EQ(*d.stroke, 0.084);  // Δy = 0.084, Sect. 7.2
  EXPECT_EQ(*d.a2, 2.3);        // (y2'', y3'') = (2.3, 1.3), Sect. 7.2
  EXPECT_EQ(*d.a3, 1.3);
  EXPECT_EQ(*d.width, 0.05);    // w = 0.05, Sect. 7.2
  EXPECT_EQ(*d.c_mu, 2.5);      // c_mu = 2.5, Sect. 7.2
  EXPECT_EQ(*d.periods, 20.0);
  EXPECT_FALSE(d.out);
  EXPECT_FALSE(d.summary);
  EXPECT_FALSE(d.samples);
}

TEST(LoadSimulateConfig, JsonAndTomlGiveTheSameConfig) {
  TempDir dir;
  write_text(dir.file("c.json"), R"({"width": 0.04, "a2": 2, "method": "time-stepping",
                                     "durations": [0.5, 0.5], "out": "run.csv"})");
  write_text(dir.file("c.toml"), "width = 0.04\na2 = 2\nmethod = \"time-stepping\"\n"
                                 "durations = [0.5, 0.5]\nout = \"run.csv\"\n");
  const SimulateConfig json = load_simulate_config(dir.file("c.json"));
  const SimulateConfig toml = load_simulate_config(dir.file("c.toml"));
  EXPECT_EQ(json, toml);
  EXPECT_EQ(*json.width, 0.04);
  EXPECT_EQ(*json.a2, 2.0);  // an integer is a number
  EXPECT_EQ(*json.method, "time-stepping");
  EXPECT_EQ(*json.durations, (std::vector<double>{0.5, 0.5}));
  EXPECT_FALSE(json.stroke);  // not given: stays unset
}

TEST(LoadSimulateConfig, ExamplesHoldTheDefaults) {
  const std::string dir = std::string(SELFALIGN_SOURCE_DIR) + "/examples/";
  EXPECT_EQ(load_simulate_config(dir + "simulate.json"), simulate_config_defaults());
  EXPECT_EQ(load_simulate_config(dir + "simulate.toml"), simulate_config_defaults());
}

TEST(LoadSimulateConfig, RejectsUnknownKeysWrongTypesAndMalformedFiles) {
  TempDir dir;
  write_text(dir.file("unknown.json"), R"({"widht": 0.05})");
  std::string m = expect_invalid([&] { load_simulate_config(dir.file("unknown.json")); },
                                 "config key");
  EXPECT_NE(m.find("widht"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean width?"), std::string::npos) << m;

  write_text(dir.file("unknown.toml"), "widht = 0.05\n");
  expect_invalid([&] { load_simulate_config(dir.file("unknown.toml")); }, "config key");

  write_text(dir.file("type.json"), R"({"width": "wide"})");
  m = expect_invalid([&] { load_simulate_config(dir.file("type.json")); }, "width");
  EXPECT_NE(m.find("must be a number"), std::string::npos) << m;
  write_text(dir.file("type.toml"), "durations = [0.5, \"x\"]\n");
  m = expect_invalid([&] { load_simulate_config(dir.file("type.toml")); }, "durations");
  EXPECT_NE(m.find("must be an array of numbers"), std::string::npos) << m;
  write_text(dir.file("table.toml"), "[profile]\nperiod = 1\n");
  expect_invalid([&] { load_simulate_config(dir.file("table.toml")); }, "profile");

  write_text(dir.file("bad.json"), "{\"width\": 0.05,\n");
  m = expect_invalid([&] { load_simulate_config(dir.file("bad.json")); }, "config file");
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  write_text(dir.file("bad.toml"), "width = = 1\n");
  m = expect_invalid([&] { load_simulate_config(dir.file("bad.toml")); }, "config file");
  EXPECT_NE(m.find("line 1"), std::string::npos) << m;
  write_text(dir.file("array.json"), "[1, 2]");
  expect_invalid([&] { load_simulate_config(dir.file("array.json")); }, "config file");

  expect_invalid([&] { load_simulate_config(dir.file("missing.json")); }, "config file");
  write_text(dir.file("c.yaml"), "width: 1\n");
  expect_invalid([&] { load_simulate_config(dir.file("c.yaml")); }, "config file");
}

TEST(SetSimulateConfigValue, ParsesNumbersListsAndText) {
  SimulateConfig c;
  set_simulate_config_value(c, "width", "0.04");
  set_simulate_config_value(c, "durations", "0.3, 0.2,0.5");
  set_simulate_config_value(c, "fourier_cos", "");
  set_simulate_config_value(c, "units", "si");
  set_simulate_config_value(c, "x0", "-1e-3");
  EXPECT_EQ(*c.width, 0.04);
  EXPECT_EQ(*c.durations, (std::vector<double>{0.3, 0.2, 0.5}));
  EXPECT_TRUE(c.fourier_cos->empty());
  EXPECT_EQ(*c.units, "si");
  EXPECT_EQ(*c.x0, -1e-3);
  set_simulate_config_value(c, "width", "nan");  // parsed; the model rejects it
  EXPECT_TRUE(std::isnan(*c.width));
  expect_invalid([&] { set_simulate_config_value(c, "width", "abc"); }, "width");
  expect_invalid([&] { set_simulate_config_value(c, "width", "1.0x"); }, "width");
  expect_invalid([&] { set_simulate_config_value(c, "durations", "0.3,,0.5"); }, "durations");
  expect_invalid([&] { set_simulate_config_value(c, "nonsense", "1"); }, "config key");
}

TEST(MergeSimulateConfig, OverridesWinAndUnsetKeysKeepTheBase) {
  SimulateConfig file, flags;
  file.width = 0.04;
  file.a2 = 2.0;
  flags.width = 0.06;
  const SimulateConfig m = merge(file, flags);
  EXPECT_EQ(*m.width, 0.06);
  EXPECT_EQ(*m.a2, 2.0);
  EXPECT_FALSE(m.a3);
}

TEST(ResolveSimulateConfig, SiDefaultsAreTheDimensionlessOnesConverted) {
  SimulateConfig c;
  c.units = "si";
  c.mu = 0.2;
  c.g = 9.8;
  c.length_scale = 2e-3;
  c.width = 1e-4;  // given: kept as is [m]
  const Scales s(2e-3, 0.2, 9.8);
  const SimulateConfig r = resolve_simulate_config(c);
  EXPECT_EQ(*r.width, 1e-4);
  EXPECT_DOUBLE_EQ(*r.stroke, 0.084 * 2e-3);                     // Δy L [m]
  EXPECT_DOUBLE_EQ(*r.period, std::sqrt(2e-3 / (0.2 * 9.8)));    // Δt T [s]
  EXPECT_DOUBLE_EQ(*r.a2, 2.3 * 0.2 * 9.8);                      // y2'' mu g [m/s^2]
  EXPECT_DOUBLE_EQ(*r.step, 1e-4 * s.time());
  EXPECT_EQ(*r.c_mu, 2.5);  // dimensionless in both systems
  EXPECT_EQ(*r.periods, 20.0);
  // Dimensionless runs: the defaults themselves.
  EXPECT_EQ(resolve_simulate_config({}), simulate_config_defaults());
  SimulateConfig bad;
  bad.units = "imperial";
  expect_invalid([&] { resolve_simulate_config(bad); }, "units");
}

TEST(ResolveSimulateConfig, ToSiAndBackRoundTrip) {
  const Scales s(2e-3, 0.2, 9.8);
  const SimulateConfig d = simulate_config_defaults();
  const SimulateConfig back = to_dimensionless(to_si(d, s), s);
  EXPECT_NEAR(*back.stroke, *d.stroke, kRoundTripTolerance);
  EXPECT_NEAR(*back.period, *d.period, kRoundTripTolerance);
  EXPECT_NEAR(*back.a3, *d.a3, kRoundTripTolerance);
  EXPECT_EQ(*back.mu, *d.mu);
}

TEST(ResolveOutputPaths, SummaryBesideTheCsvByDefault) {
  SimulateConfig c;
  EXPECT_FALSE(resolve_output_paths(c).trajectory);
  EXPECT_EQ(resolve_output_paths(c).summary, "-");
  c.out = "out/run.csv";
  EXPECT_EQ(*resolve_output_paths(c).trajectory, "out/run.csv");
  EXPECT_EQ(resolve_output_paths(c).summary, "out/run.summary.json");
  c.summary = "-";
  EXPECT_EQ(resolve_output_paths(c).summary, "-");
  c.summary = "out/run.csv";
  expect_invalid([&] { resolve_output_paths(c); }, "summary");
}

TEST(BuildSimulateModel, DefaultsGiveTheSection72Model) {
  const SimulateModel m = build_simulate_model({});
  EXPECT_EQ(m.units, UnitSystem::dimensionless);
  EXPECT_EQ(m.profile->kind(), "three-phase");
  EXPECT_EQ(m.profile->period(), 1.0);
  const TwoRegionTable* friction = m.friction->two_region();
  ASSERT_NE(friction, nullptr);
  EXPECT_EQ(friction->width(), 0.05);
  EXPECT_EQ(m.options.method, Method::exact);
  EXPECT_EQ(m.options.duration, 20.0);  // periods * Δt
  EXPECT_EQ(m.initial.x, 0.0);
}

TEST(BuildSimulateModel, OtherProfilesAndFrictionMaps) {
  SimulateConfig c;
  c.profile = "quadratic-sequence";
  c.durations = {0.5, 0.25, 0.25};
  c.accelerations = {0.0, -1.0, 1.0};
  c.friction = "uniform";
  c.periods = 3;
  SimulateModel m = build_simulate_model(c);
  EXPECT_EQ(m.profile->kind(), "quadratic-sequence");
  EXPECT_EQ(m.options.duration, 3.0);
  EXPECT_NE(dynamic_cast<const UniformFriction*>(m.friction.get()), nullptr);

  c.profile = "fourier";
  c.fourier_cos = {0.04};
  c.period = 2.0;
  m = build_simulate_model(c);
  EXPECT_EQ(m.profile->kind(), "fourier");
  EXPECT_EQ(m.options.duration, 6.0);

  TempDir dir;
  write_text(dir.file("samples.csv"), "t,ydd\n0,0\n0.5,-1\n0.75,1\n1,0\n");
  c.profile = "samples";
  c.samples = dir.file("samples.csv");
  m = build_simulate_model(c);
  EXPECT_EQ(m.profile->kind(), "samples-constant");
  EXPECT_EQ(m.profile->period(), 1.0);
}

TEST(BuildSimulateModel, RejectsMisuseNamingTheParameter) {
  auto with = [](auto set) {
    SimulateConfig c;
    set(c);
    return [c] { build_simulate_model(c); };
  };
  expect_invalid(with([](SimulateConfig& c) { c.width = 0; }), "width");
  expect_invalid(with([](SimulateConfig& c) { c.width = std::nan(""); }), "width");
  expect_invalid(with([](SimulateConfig& c) { c.c_mu = 1; }), "c_mu");
  expect_invalid(with([](SimulateConfig& c) { c.period = 0; }), "period");
  expect_invalid(with([](SimulateConfig& c) { c.periods = -1; }), "periods");
  expect_invalid(with([](SimulateConfig& c) { c.profile = "square"; }), "profile");
  expect_invalid(with([](SimulateConfig& c) { c.friction = "sticky"; }), "friction");
  expect_invalid(with([](SimulateConfig& c) { c.method = "rk4"; }), "method");
  expect_invalid(with([](SimulateConfig& c) { c.theta = 2; }), "theta");
  expect_invalid(with([](SimulateConfig& c) { c.mass = 0; }), "mass");
  expect_invalid(with([](SimulateConfig& c) { c.x0 = INFINITY; }), "x0");
  expect_invalid(with([](SimulateConfig& c) { c.profile = "samples"; }), "samples");
  // Case 0 (Appendix): 1/a2 + 1/a3 = 4 > Δt^2/(8 Δy) = 1.49.
  expect_invalid(with([](SimulateConfig& c) { c.a2 = 0.5, c.a3 = 0.5; }), "a2, a3");
  // SI runs restate the check with the SI value given.
  const std::string m = expect_invalid(with([](SimulateConfig& c) {
                                         c.units = "si";
                                         c.width = -1e-3;
                                       }),
                                       "width");
  EXPECT_NE(m.find("-0.001 [m]"), std::string::npos) << m;
}

TEST(BuildSimulateModel, SiInputsAreConvertedWithOneScales) {
  const Scales s(2e-3, 0.2, 9.8);
  SimulateConfig c;
  c.units = "si";
  c.length_scale = 2e-3;
  c.mu = 0.2;
  c.g = 9.8;
  c.width = 1e-4;  // 0.05 L
  c.x0 = 4e-4;     // 0.2 L
  const SimulateModel m = build_simulate_model(c);
  const TwoRegionTable* friction = m.friction->two_region();
  ASSERT_NE(friction, nullptr);
  EXPECT_NEAR(friction->width(), 0.05, kRoundTripTolerance);
  EXPECT_NEAR(m.initial.x, 0.2, kRoundTripTolerance);
  EXPECT_NEAR(m.profile->period(), 1.0, kRoundTripTolerance);  // default Δt = 1 T
  EXPECT_DOUBLE_EQ(m.scales.time(), s.time());
  EXPECT_TRUE(m.output_units().si());
}

TEST(BuildProfileModel, CaseZeroIsAValueOnlyWhenAllowed) {
  SimulateConfig c;
  c.a2 = 0.5;  // Appendix: 1/a2 + 1/a3 = 4 > Δt^2/(8 Δy) = 1.49, case 0
  c.a3 = 0.5;
  const ProfileModel m = build_profile_model(c, NonPhysicalProfile::allow);
  EXPECT_EQ(m.profile, nullptr);
  ASSERT_TRUE(m.three_phase);
  EXPECT_EQ(m.three_phase->a2, 0.5);
  EXPECT_EQ(m.three_phase->stroke, 0.084);
  expect_invalid([&] { build_profile_model(c); }, "a2, a3");
  // Misuse stays misuse, also when case 0 is allowed.
  c.a2 = -1;
  expect_invalid([&] { build_profile_model(c, NonPhysicalProfile::allow); }, "a2");
}

TEST(BuildProfileModel, IgnoresFrictionInitialStateAndSolverKeys) {
  SimulateConfig c;
  c.width = 0;  // misuse for simulate, unused here
  c.c_mu = 0.5;
  c.periods = -1;
  c.method = "rk4";
  const ProfileModel m = build_profile_model(c);
  ASSERT_NE(m.profile, nullptr);
  EXPECT_EQ(m.profile->kind(), "three-phase");
  c.profile = "quadratic-sequence";
  c.durations = {0.5, 0.25, 0.25};
  c.accelerations = {0.0, -1.0, 1.0};
  const ProfileModel q = build_profile_model(c);
  EXPECT_EQ(q.profile->kind(), "quadratic-sequence");
  EXPECT_FALSE(q.three_phase);
}

TEST(BuildProfileModel, SiInputsConvertedWithOneScales) {
  const Scales s(2e-3, 0.2, 9.8);
  SimulateConfig c;
  c.units = "si";
  c.length_scale = 2e-3;
  c.mu = 0.2;
  c.g = 9.8;
  c.stroke = 0.084 * 2e-3;
  const ProfileModel m = build_profile_model(c);
  EXPECT_NEAR(m.three_phase->stroke, 0.084, kRoundTripTolerance);
  EXPECT_NEAR(m.three_phase->a2, 2.3, kRoundTripTolerance);  // default, converted both ways
  EXPECT_NEAR(m.to_model_units(Dimension::velocity, s.velocity()), 1.0, kRoundTripTolerance);
  EXPECT_NEAR(m.to_model_units(Dimension::time, 3 * s.time()), 3.0, kRoundTripTolerance);
  EXPECT_EQ(m.to_model_units(Dimension::none, 0.7), 0.7);
  EXPECT_TRUE(m.output_units().si());
  c.stroke = -1e-4;
  const std::string e = expect_invalid([&] { build_profile_model(c); }, "stroke");
  EXPECT_NE(e.find("-1e-04 [m]"), std::string::npos) << e;  // restated in SI
}

TEST(ConvertOneValue, ToSiAndBackByDimension) {
  const Scales s(2e-3, 0.2, 9.8);
  EXPECT_DOUBLE_EQ(to_si(Dimension::length, 0.5, s), 1e-3);
  EXPECT_DOUBLE_EQ(to_si(Dimension::time, 2.0, s), 2 * s.time());
  EXPECT_DOUBLE_EQ(to_si(Dimension::velocity, 1.0, s), s.velocity());
  EXPECT_DOUBLE_EQ(to_si(Dimension::acceleration, 1.0, s), 0.2 * 9.8);
  EXPECT_EQ(to_si(Dimension::none, 0.3, s), 0.3);
  for (Dimension d : {Dimension::length, Dimension::time, Dimension::velocity,
                      Dimension::acceleration})
    EXPECT_NEAR(to_dimensionless(d, to_si(d, 0.37, s), s), 0.37, kRoundTripTolerance);
}

TEST(AtomicFileSet, CommitsAllOrNothing) {
  forget_run_files();
  TempDir dir;
  {
    AtomicFileSet files;
    files.add(dir.file("a.txt"), "alpha", "out");
    files.add(dir.file("b.txt"), "beta", "summary");
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.txt")));  // not before commit
    files.commit();
  }
  EXPECT_EQ(read_text(dir.file("a.txt")), "alpha");
  EXPECT_EQ(read_text(dir.file("b.txt")), "beta");
  {
    AtomicFileSet files;
    files.add(dir.file("c.txt"), "gamma", "out");
    EXPECT_THROW(files.add(dir.file("no/such/dir/d.txt"), "delta", "summary"), InvalidParameter);
    EXPECT_THROW(files.add(dir.file("c.txt"), "again", "out"), InvalidParameter);
  }  // destroyed without commit: the temporary of c.txt is removed
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++count;
  }
  EXPECT_EQ(count, 2u);  // a.txt, b.txt only
  write_file_atomically(dir.file("a.txt"), "replaced", "out");
  EXPECT_EQ(read_text(dir.file("a.txt")), "replaced");
}

TEST(TrajectoryCsv, HeaderRoundTripNumbersAndSiConversion) {
  Trajectory tr;
  tr.push(0.1, 1.0 / 3.0, -0.5, 0.084, 0.2, -2.3, true);
  const std::string csv = format_trajectory_csv(tr);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), kTrajectoryCsvHeader);
  const std::string row = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(row, "0.1,0.3333333333333333,-0.5,0.084,0.2,-2.3,1\n");
  EXPECT_EQ(std::stod(row.substr(row.find(',') + 1)), 1.0 / 3.0);  // round trip

  const Scales s(2e-3, 0.2, 9.8);
  const std::string si = format_trajectory_csv(tr, OutputUnits(s));
  const std::string si_row = si.substr(si.find('\n') + 1);
  EXPECT_NEAR(std::stod(si_row), s.time_to_si(0.1), 1e-18);  // t [s]
  EXPECT_EQ(si_row.substr(si_row.rfind(',')), ",1\n");
}

TEST(SummaryJson, HasEveryKeyInTheRunsUnits) {
  SimulateConfig c;
  c.periods = 2;
  const SimulateModel m = build_simulate_model(c);
  const SimulationResult r = simulate(*m.profile, *m.friction, m.initial, m.options);
  const nlohmann::json j = simulate_summary_json(m, r, std::string("run.csv"));
  for (const char* key : {"units", "method", "profile", "friction", "initial", "final", "periods",
                          "arcs", "mean_velocity_last_period", "stick_fraction", "scales",
                          "trajectory_file"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"kind", "period", "stroke", "peak_acceleration", "a2", "a3", "t1", "t2",
                          "t3", "y_ini", "y_dot_ini"})
    EXPECT_TRUE(j["profile"].contains(key)) << key;
  const auto& tp = dynamic_cast<const ThreePhaseProfile&>(*m.profile);
  EXPECT_EQ(j["profile"]["t1"].get<double>(), tp.solution().t1);
  EXPECT_EQ(j["final"]["x"].get<double>(), r.final_state.x);
  EXPECT_EQ(j["trajectory_file"], "run.csv");
  EXPECT_TRUE(j["scales"].is_null());  // dimensionless run

  c.units = "si";
  const SimulateModel msi = build_simulate_model(c);
  const SimulationResult rsi = simulate(*msi.profile, *msi.friction, msi.initial, msi.options);
  const nlohmann::json jsi = simulate_summary_json(msi, rsi, std::nullopt);
  EXPECT_TRUE(jsi["trajectory_file"].is_null());
  EXPECT_EQ(jsi["scales"]["length_m"].get<double>(), 1e-3);
  EXPECT_EQ(jsi["scales"]["mass_kg"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(jsi["final"]["x"].get<double>(), msi.scales.length_to_si(rsi.final_state.x));
}

}  // namespace
}  // namespace selfalign
