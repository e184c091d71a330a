// Tests of the parameter view (io/parameter_view.hpp): which parameters a model has, and
// `with`. Expected values come from the model's definition (Sect. 3.2 scales, the profile
// families' closed forms evaluated on the unchanged profile), not from the view's code.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/robust/process_uncertainty.hpp"
#include "expect_invalid.hpp"

namespace selfalign::parameter_view_test {

// Rescaling multiplies each key once; the profiles then evaluate closed forms (polynomials,
// sines) of the rescaled keys: a few ulps of y, y', y'' relative to the stroke / peak.
constexpr double kScaledProfileTolerance = 1e-12;

std::vector<std::string> names(const SimulateConfig& c) {
  std::vector<std::string> out;
  for (const ModelParameter& p : model_parameters(c)) out.push_back(p.name);
  return out;
}

double value(const SimulateConfig& c, const std::string& name) {
  for (const ModelParameter& p : model_parameters(c))
    if (p.name == name) return p.value;
  ADD_FAILURE() << name << " not in the view";
  return NAN;
}

using ::selfalign::testing::expect_invalid;

SimulateConfig config_of(std::initializer_list<std::pair<const char*, const char*>> keys) {
  SimulateConfig c;
  for (const auto& [k, v] : keys) set_simulate_config_value(c, k, v);
  return c;
}

TEST(ParameterView, TheDefaultModelsParametersByGroup) {
  // The paper's model: two-region table, three-phase profile, Coulomb law, dimensionless.
  EXPECT_EQ(names(SimulateConfig{}),
            (std::vector<std::string>{"mu", "mu_static", "mu_backward", "stribeck_velocity",
                                      "stribeck_exponent", "viscous", "x_mu", "width", "c_mu",
                                      "period", "stroke", "a2", "a3", "amplitude_scale",
                                      "time_scale", "t0", "x0", "v0"}));
  // Sect. 7.2's values; absent law terms: mu_static = mu_backward = mu, no Stribeck decay
  // (NaN), no viscous term (0).
  EXPECT_EQ(value({}, "c_mu"), 2.5);
  EXPECT_EQ(value({}, "a2"), 2.3);
  EXPECT_EQ(value({}, "mu_static"), 0.3);
  EXPECT_EQ(value({}, "mu_backward"), 0.3);
  EXPECT_TRUE(std::isnan(value({}, "stribeck_velocity")));
  EXPECT_EQ(value({}, "viscous"), 0.0);
  EXPECT_EQ(value({}, "amplitude_scale"), 1.0);
}

TEST(ParameterView, DependsOnTheModelsKinds) {
  const auto uniform_fourier = config_of({{"friction", "uniform"}, {"profile", "fourier"},
                                          {"fourier_cos", "0.1,0.02"}, {"fourier_sin", "0.03"},
                                          {"units", "si"}});
  EXPECT_EQ(names(uniform_fourier),
            (std::vector<std::string>{"mu", "mu_static", "mu_backward", "stribeck_velocity",
                                      "stribeck_exponent", "viscous", "g", "period",
                                      "fourier_cos[0]", "fourier_cos[1]", "fourier_sin[0]",
                                      "amplitude_scale", "time_scale", "t0", "x0", "v0"}));
  const auto samples = config_of({{"profile", "samples"}, {"friction", "uniform"}});
  const auto n = names(samples);
  EXPECT_EQ(std::count(n.begin(), n.end(), "amplitude_scale"), 0);
  EXPECT_EQ(std::count(n.begin(), n.end(), "period"), 0);
  // The jerk is a parameter of a jerk-limited profile only.
  const auto jerk = names(config_of({{"jerk", "40"}}));
  EXPECT_EQ(std::count(jerk.begin(), jerk.end(), "jerk"), 1);
  EXPECT_EQ(std::count(n.begin(), n.end(), "jerk"), 0);
}

// y(t) -> a y(t / p): the rescaled profile at t is (a y, a/p y', a/p^2 y'') of the old one at
// t/p, for every family the view rescales.
void expect_rescaled(const SimulateConfig& base, double a, double p) {
  const auto old_profile = build_profile_model(base).profile;
  const auto new_profile =
      build_profile_model(with_parameters(base, {{"amplitude_scale", a}, {"time_scale", p}})).profile;
  const double y_scale = old_profile->stroke(), a_scale = old_profile->peak_acceleration();
  EXPECT_NEAR(new_profile->period(), p * old_profile->period(),
              kScaledProfileTolerance * p * old_profile->period());
  for (int i = 0; i < 97; ++i) {
    const double t = new_profile->period() * (i + 0.37) / 97;
    const TableState now = new_profile->state(t), then = old_profile->state(t / p);
    EXPECT_NEAR(now.y, a * then.y, kScaledProfileTolerance * a * y_scale) << base.profile.value_or("") << " t " << t;
    EXPECT_NEAR(now.yd, a / p * then.yd, kScaledProfileTolerance * a / p * y_scale * 10);
    EXPECT_NEAR(now.ydd, a / (p * p) * then.ydd, kScaledProfileTolerance * a / (p * p) * a_scale);
  }
}

TEST(ParameterView, TheMotionFactorsRescaleEveryFamily) {
  for (const double a : {0.8, 1.25})
    for (const double p : {0.9, 1.3}) {
      expect_rescaled({}, a, p);
      expect_rescaled(config_of({{"jerk", "40"}}), a, p);
      expect_rescaled(config_of({{"profile", "fourier"}, {"fourier_cos", "0.02,0.004"},
                                 {"fourier_sin", "0.03"}}),
                      a, p);
      expect_rescaled(config_of({{"profile", "quadratic-sequence"},
                                 {"durations", "0.3,0.2,0.5"},
                                 {"accelerations", "1,-2.5,0.4"}}),
                      a, p);
      expect_rescaled(config_of({{"profile", "piecewise-linear"}, {"times", "0,0.25,0.5"},
                                 {"accelerations", "1,-3,1"}, {"period", "1"}}),
                      a, p);
    }
}

TEST(ParameterView, ChangesTheLawInTheRunsCoefficients) {
  // Absolute coefficients (docs/config.md): the law is their ratio to mu.
  const FrictionLaw law = friction_law(with_parameters({}, {{"mu", 0.2}, {"mu_static", 0.3},
                                                 {"mu_backward", 0.16}, {"viscous", 0.5}}));
  EXPECT_DOUBLE_EQ(law.static_coefficient(), 1.5);
  EXPECT_DOUBLE_EQ(law.kinetic_backward(), 0.8);
  EXPECT_EQ(law.viscous(), 0.5);
  EXPECT_TRUE(friction_law(with_parameters({}, {{"stribeck_velocity", 0.01}})).velocity_dependent());
}

TEST(ParameterView, ChangingMuInAnSiRunChangesTheDimensionlessTable) {
  // Sect. 3.2: y''[-] = y''[m/s^2] / (mu g). The table is given in SI; mu x 2 halves it.
  const auto si = config_of({{"units", "si"}, {"a2", "30"}, {"a3", "17"}, {"stroke", "2e-4"},
                             {"period", "0.02"}, {"mu", "0.3"}, {"g", "9.81"}});
  const ProfileModel doubled = build_profile_model(with_parameters(si, {{"mu", 0.6}}));
  ASSERT_TRUE(doubled.three_phase);
  EXPECT_NEAR(doubled.three_phase->a2, 30 / (0.6 * 9.81), 1e-14);
  EXPECT_NEAR(doubled.three_phase->a3, 17 / (0.6 * 9.81), 1e-14);
  EXPECT_EQ(value(si, "a2"), 30.0);  // the view is in the run's units
}

TEST(ParameterView, SetsArrayElementsAndLeavesTheRest) {
  const auto c = config_of({{"profile", "quadratic-sequence"}, {"durations", "0.3,0.2,0.5"},
                            {"accelerations", "1,-2.5,0.4"}});
  const SimulateConfig changed = with_parameters(c, {{"accelerations[1]", -2.0}, {"accelerations[2]", 0.2}});
  EXPECT_EQ(*changed.accelerations, (std::vector<double>{1, -2.0, 0.2}));
  EXPECT_EQ(*changed.durations, (std::vector<double>{0.3, 0.2, 0.5}));
}

TEST(ParameterView, RefusesWhatIsNotAParameterOfTheModel) {
  const auto uniform = config_of({{"friction", "uniform"}});
  EXPECT_NE(expect_invalid([&] { with_parameters(uniform, {{"c_mu", 3}}); }, "c_mu").find("friction = uniform"),
            std::string::npos);
  EXPECT_NE(expect_invalid([&] { with_parameters({}, {{"step", 1e-3}}); }, "step").find("setting"),
            std::string::npos);
  EXPECT_NE(expect_invalid([&] { with_parameters({}, {{"mu_statc", 0.4}}); }, "mu_statc").find("mu_static"),
            std::string::npos);
  const auto q = config_of({{"profile", "quadratic-sequence"}, {"durations", "0.5,0.5"},
                            {"accelerations", "1,-1"}});
  EXPECT_NE(expect_invalid([&] { with_parameters(q, {{"accelerations[2]", 1}}); }, "accelerations[2]")
                .find("0..1"),
            std::string::npos);
  expect_invalid([&] { with_parameters(q, {{"accelerations", 1}}); }, "accelerations");
  expect_invalid([&] { with_parameters({}, {{"c_mu", NAN}}); }, "c_mu");
  expect_invalid([&] { with_parameters({}, {{"time_scale", 0}}); }, "time_scale");
  expect_invalid([&] { with_parameters({}, {{"amplitude_scale", -1}}); }, "amplitude_scale");
  // g converts SI inputs only: not a parameter of a dimensionless model.
  EXPECT_NE(expect_invalid([&] { with_parameters({}, {{"g", 9.8}}); }, "g").find("units = dimensionless"),
            std::string::npos);
}

}  // namespace selfalign::parameter_view_test

namespace selfalign::parameter_view_test {

// Robust design changes its model through the view (ProcessFamily): a draw's model in units of
// the drawn width and mu, by hand from Sect. 3.2: T = sqrt(w/(mu g)), y'' / (mu g), x / w; the
// table y(t) -> a y(t / p) (period x p, stroke x a, accelerations x a/p^2, jerk x a/p^3).
TEST(ParameterView, IsWhereRobustDesignDrawsItsModels) {
  DesignRequest q;
  q.width = 0.003, q.mu = 0.2, q.c_mu = 2.5, q.gravity = 9.81, q.mu_backward = 0.17;
  const Process p{0.1, 0.002, 4.9, 2.7, 900.0, 0.037};
  // mu, c_mu, static ratio, width, x_mu offset, amplitude, period factor.
  const InputValues v{0.21, 2.3, 1.15, 0.0032, -2e-4, 1.05, 0.97};
  const ProcessModel m(ProcessFamily(q, p), v);
  const double mu_g = v[0] * q.gravity, w = v[3], time = std::sqrt(w / mu_g);
  const double a = v[5], f = v[6];
  constexpr double kTol = 1e-13;  // a few roundings of each product and quotient
  EXPECT_NEAR(m.law.static_coefficient(), 1.15, kTol);
  EXPECT_NEAR(m.law.kinetic_backward(), 0.17 / 0.2, kTol);  // the request's ratio, < 1.15
  EXPECT_NEAR(m.c_mu, 2.3, kTol);
  EXPECT_NEAR(m.x_mu, (0.037 - 2e-4) / w, kTol * 12);
  EXPECT_NEAR(m.profile->period(), 0.1 * f / time, kTol);
  EXPECT_NEAR(m.profile->stroke(), 0.002 * a / w, kTol);
  // The jerk-limited profile's peak |y''| is the larger plateau, y2''.
  EXPECT_NEAR(m.profile->peak_acceleration(), 4.9 * a / (f * f) / mu_g, kTol * 10);
  ASSERT_NE(m.profile->kind().find("jerk"), std::string::npos) << m.profile->kind();
}

}  // namespace selfalign::parameter_view_test

namespace selfalign::parameter_view_test {

TEST(ParameterView, AViewWithFreeParametersEvaluatesManyValues) {
  const ParameterView view(SimulateConfig{}, {"c_mu", "mu_static", "time_scale"});
  EXPECT_EQ(view.values(), (std::vector<double>{2.5, 0.3, 1.0}));  // Sect. 7.2; mu_static = mu
  const SimulateConfig c = view.with({3.0, 0.36, 2.0});
  EXPECT_EQ(*c.c_mu, 3.0);
  EXPECT_EQ(*c.mu_static, 0.36);
  EXPECT_EQ(*c.period, 2.0);
  EXPECT_EQ(*c.a2, 2.3 / 4);  // x 1/p^2: exact for p = 2
  EXPECT_EQ(*view.config().c_mu, 2.5);  // the view is unchanged
  expect_invalid([&] { view.with({3.0}); }, "values");
  expect_invalid([&] { view.with({3.0, INFINITY, 1.0}); }, "mu_static");
  expect_invalid([&] { ParameterView(SimulateConfig{}, {"x_mu", "fourier_cos[0]"}); }, "fourier_cos[0]");
}

}  // namespace selfalign::parameter_view_test

#include "temp_dir.hpp"

namespace selfalign::parameter_view_test {

// The field's samples in the config are the rows of a field_file: the two give the same map
// (the file through FrictionField's CSV reader, the second path).
TEST(ParameterView, TheFieldsSamplesInTheConfigAreTheRowsOfAFieldFile) {
  ::selfalign::testing::TempDir dir;
  const std::string file = (dir.path() / "f.csv").string();
  ::selfalign::testing::write_text(file, "position,level\n0,1\n0.5,2.5\n0.8,1.5\n");
  for (const char* interpolation : {"steps", "linear"})
    for (const char* footprint : {"point", "uniform"}) {
      const auto in_file = config_of({{"field_file", file.c_str()},
                                      {"field_interpolation", interpolation},
                                      {"footprint", footprint}});
      const auto inline_ = config_of({{"field_positions", "0,0.5,0.8"},
                                      {"field_levels", "1,2.5,1.5"},
                                      {"field_interpolation", interpolation},
                                      {"footprint", footprint}});
      const auto a = build_friction_map(in_file), b = build_friction_map(inline_);
      for (double x = -0.2; x < 1.2; x += 0.01) EXPECT_EQ(a->bound(x), b->bound(x)) << x;
    }
}

TEST(ParameterView, TheFieldsLevelsAreParameters) {
  // Point footprint, steps: m(x) = 1 before 0.5, 2.5 from 0.5 on (the rows' levels).
  const auto c = config_of({{"field_positions", "0,0.5"}, {"field_levels", "1,2.5"},
                            {"footprint", "point"}});
  const auto n = names(c);
  EXPECT_EQ(std::count(n.begin(), n.end(), "field_levels[1]"), 1);
  EXPECT_EQ(std::count(n.begin(), n.end(), "width"), 0);  // a point footprint has none
  const auto raised = build_friction_map(with_parameters(c, {{"field_levels[1]", 3.0},
                                                 {"field_positions[1]", 0.6}}));
  EXPECT_EQ(raised->bound(0.55), 1.0);
  EXPECT_EQ(raised->bound(0.6), 3.0);
  // SI: positions in metres, converted with L (length_scale).
  const auto si = config_of({{"units", "si"}, {"length_scale", "0.002"},
                             {"field_positions", "0,0.001"}, {"field_levels", "1,2"},
                             {"footprint", "point"}});
  const auto map = build_friction_map(si);
  EXPECT_EQ(map->bound(0.49), 1.0);  // 0.98 mm
  EXPECT_EQ(map->bound(0.5), 2.0);   // 1 mm = 0.5 L
}

TEST(ParameterView, RefusesAnInlineFieldThatIsNotOne) {
  expect_invalid([] { build_friction_map(config_of({{"field_positions", "0,0.5,0.4"},
                                                    {"field_levels", "1,2,3"}})); },
                 "field_positions[2]");
  expect_invalid([] { build_friction_map(config_of({{"field_positions", "0,0.5"},
                                                    {"field_levels", "1"}})); },
                 "field_levels");
  expect_invalid([] { build_friction_map(config_of({{"field_levels", "1,2"}})); },
                 "field_positions");
  expect_invalid([] { build_friction_map(config_of({{"field_positions", "0,0.5"},
                                                    {"field_levels", "1,-2"}})); },
                 "field_levels[1]");
  expect_invalid([] { build_friction_map(config_of({{"field_positions", "0,0.5"},
                                                    {"field_levels", "0,0"}})); },
                 "field_levels");
  expect_invalid([] { resolve_simulate_config(config_of({{"friction", "two-region"},
                                                         {"field_positions", "0"},
                                                         {"field_levels", "1"}})); },
                 "field_positions");
  expect_invalid([] { resolve_simulate_config(config_of({{"field_file", "f.csv"},
                                                         {"field_positions", "0"},
                                                         {"field_levels", "1"}})); },
                 "field_positions");
}

}  // namespace selfalign::parameter_view_test
