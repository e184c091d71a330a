// Identification from measured motion (identify/identification.hpp, issue 25).
//
// The measured runs are synthesized independently of the fit: one continuous simulate() run
// of the true model (not the shooting windows the fit uses), sampled at 2 kHz, with Gaussian
// position noise of sd 2 um and a clock offset of 3 ms (data time = model time - 3 ms). The
// expected values are the truths chosen here. Coverage: of 100 noise seeds, the 95 % intervals
// must contain the truth in 90..99 runs (a binomial(100, 0.95) count lies in that range with
// probability 0.99; the fixed seeds make the test deterministic).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/identify/identification.hpp"
#include "selfalign/io/identification_report.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/io/uncertainty_file.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "temp_dir.hpp"

namespace selfalign::identification_test {

constexpr double kNoise = 2e-6;    // [m], position noise sd
constexpr double kOffset = 3e-3;   // [s], data clock behind the model's
constexpr double kRate = 2000;     // [Hz]

// The part on a table at 20 Hz (period 50 ms), the paper's Sect. 7.2 profile in SI with
// mu = 0.3 (a2 = 2.3 mu g, a3 = 1.3 mu g, stroke 0.084 mu g T^2), scaled by `amplitude`.
SimulateConfig truth_config(bool jerk, double amplitude = 1) {
  SimulateConfig c;
  c.units = "si";
  c.profile = "three-phase";
  c.period = 0.05;
  c.stroke = 6.2e-4 * amplitude;
  c.a2 = 6.77 * amplitude;
  c.a3 = 3.83 * amplitude;
  if (jerk) c.jerk = 800 * amplitude;
  c.friction = "uniform";
  c.mu = 0.3;
  c.g = 9.81;
  c.length_scale = 1e-3;
  c.x0 = 0;
  c.v0 = 0;
  return c;
}

// The same with the friction step: rough region from x_mu = 1.5 mm, footprint 1 mm, c_mu 2.5.
SimulateConfig step_config() {
  SimulateConfig c = truth_config(true);
  c.friction = "two-region";
  c.x_mu = 1.5e-3;
  c.width = 1e-3;
  c.c_mu = 2.5;
  return c;
}

// A measured run of `truth` over `periods`, samples before `skip` periods dropped.
MeasuredMotion synthesize(const SimulateConfig& truth, double periods, std::uint64_t seed,
                          double skip = 0) {
  SimulateConfig c = truth;
  c.periods = periods;
  c.output_step = 1 / kRate;
  const SimulateModel m = build_simulate_model(c);
  const SimulationResult r = simulate(*m.profile, *m.friction, m.law, m.initial, m.options);
  const OutputUnits out = m.output_units();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0, kNoise);
  MeasuredMotion d;
  d.source = "synthetic-" + std::to_string(seed) + ".csv";
  for (std::size_t i = 0; i + 1 < r.trajectory.size(); ++i) {
    const double t = out.time(r.trajectory.t[i]);
    if (t < skip * *c.period) continue;
    d.t.push_back(t - kOffset);
    d.x.push_back(out.length(r.trajectory.x[i]) + noise(rng));
    d.line.push_back(i + 2);
  }
  return d;
}

const IdentifiedParameter& parameter(const Identification& r, const std::string& name) {
  for (const IdentifiedParameter& p : r.parameters)
    if (p.name == name) return p;
  throw std::runtime_error("no parameter " + name);
}

struct Scenario {
  SimulateConfig truth;
  SimulateConfig start;  // the model the fit starts from (the truth perturbed)
  std::vector<std::string> free;
  std::vector<std::pair<std::string, double>> truths;
  double periods;
};

// Counts, per name in s.truths, the seeds whose Wald interval contains the truth.
std::vector<int> coverage(const Scenario& s, int seeds, int starts) {
  std::vector<int> hits(s.truths.size(), 0);
  IdentificationOptions o;
  o.free = s.free;
  o.free.push_back(kTimeOffset);
  o.starts = starts;
  for (int seed = 1; seed <= seeds; ++seed) {
    const Identification r = identify({{synthesize(s.truth, s.periods, seed), s.start}}, o);
    EXPECT_NEAR(r.runs[0].time_offset, kOffset, 5 * r.runs[0].time_offset_standard_error + 1e-9)
        << "seed " << seed;
    for (std::size_t k = 0; k < s.truths.size(); ++k) {
      const IdentifiedParameter& p = parameter(r, s.truths[k].first);
      EXPECT_TRUE(p.identifiable) << p.name << " seed " << seed << ": " << p.reason;
      hits[k] += p.lower <= s.truths[k].second && s.truths[k].second <= p.upper;
    }
  }
  return hits;
}

// starts = 0: the local stage alone from the perturbed start; 16: the global stage first.
void expect_coverage(const Scenario& s, int starts = 0) {
  const std::vector<int> hits = coverage(s, 100, starts);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    EXPECT_GE(hits[k], 90) << s.truths[k].first;
    EXPECT_LE(hits[k], 99) << s.truths[k].first;
    std::printf("coverage of %s: %d / 100\n", s.truths[k].first.c_str(), hits[k]);
  }
}

TEST(IdentificationCoverage, ThreePhaseRunRecoversTheKineticCoefficient) {
  Scenario s{truth_config(false), truth_config(false), {"mu"}, {{"mu", 0.3}}, 20};
  s.start.mu = 0.32;
  expect_coverage(s);
}

TEST(IdentificationCoverage, FiniteJerkRunWithStaticAboveKinetic) {
  Scenario s{truth_config(true), truth_config(true), {"mu", "mu_static"},
             {{"mu", 0.3}, {"mu_static", 0.36}}, 20};
  s.truth.mu_static = 0.36;
  s.start.mu = 0.31;
  s.start.mu_static = 0.34;
  expect_coverage(s);
}

TEST(IdentificationCoverage, RunThroughTheFrictionStep) {
  Scenario s{step_config(), step_config(), {"mu", "mu_static", "c_mu", "x_mu"},
             {{"mu", 0.3}, {"mu_static", 0.36}, {"c_mu", 2.5}, {"x_mu", 1.5e-3}}, 30};
  s.truth.mu_static = 0.36;
  s.start.mu = 0.31;
  s.start.mu_static = 0.35;
  s.start.c_mu = 2.4;
  s.start.x_mu = 1.45e-3;
  expect_coverage(s);
}

// The global stage finds the basin from a start 20 % (mu), 11 % (mu_static), 20 % (c_mu) and
// 0.3 mm (x_mu) off, where the local stage alone ends at 10x the noise.
TEST(IdentificationGlobalStage, FindsTheFrictionStepFromAFarStart) {
  SimulateConfig truth = step_config(), start = step_config();
  truth.mu_static = 0.36;
  start.mu = 0.36, start.mu_static = 0.40, start.c_mu = 2.0, start.x_mu = 1.2e-3;
  const MeasuredMotion d = synthesize(truth, 30, 7);
  IdentificationOptions o;
  o.free = {"mu", "mu_static", "c_mu", "x_mu", kTimeOffset};
  o.starts = 0;
  const Identification local = identify({{d, start}}, o);
  o.starts = 16;
  o.global_evaluations = 4000;
  const Identification global = identify({{d, start}}, o);
  EXPECT_GT(local.sigma, 3 * kNoise);  // stuck in a local minimum
  EXPECT_LT(global.sigma, 1.1 * kNoise);
  for (auto [name, value] : std::vector<std::pair<std::string, double>>{
           {"mu", 0.3}, {"mu_static", 0.36}, {"c_mu", 2.5}, {"x_mu", 1.5e-3}}) {
    const IdentifiedParameter& p = parameter(global, name);
    EXPECT_NEAR(p.estimate, value, 4 * p.standard_error) << name;
  }
}

// A part that never sticks (the profile scaled by 10: the table's acceleration is beyond the
// static limit whenever the relative velocity passes zero; the run from rest dropped): its
// positions do not depend on mu_static, which is reported, not estimated. The control (the
// same profile at scale 1, where the part sticks 15 % of the time) identifies it.
TEST(IdentificationIdentifiability, PartThatNeverSticksReportsStaticNotIdentifiable) {
  IdentificationOptions o;
  o.free = {"mu", "mu_static", kTimeOffset};
  o.starts = 0;
  SimulateConfig fast = truth_config(true, 10);
  fast.mu_static = 0.36;
  SimulateConfig start = fast;
  start.mu_static = 0.34;
  const Identification r = identify({{synthesize(fast, 20, 1, 2), start}}, o);
  const IdentifiedParameter& ms = parameter(r, "mu_static");

  EXPECT_FALSE(ms.identifiable);
  EXPECT_TRUE(std::isnan(ms.estimate));
  EXPECT_TRUE(std::isnan(ms.standard_error));
  EXPECT_NE(ms.reason.find("never sticks"), std::string::npos) << ms.reason;
  EXPECT_TRUE(parameter(r, "mu").identifiable);
  EXPECT_NEAR(parameter(r, "mu").estimate, 0.3, 4 * parameter(r, "mu").standard_error);
  bool warned = false;
  for (const std::string& w : r.warnings) warned = warned || w.find("mu_static") != std::string::npos;
  EXPECT_TRUE(warned);

  SimulateConfig slow = truth_config(true, 1);
  slow.mu_static = 0.36;
  start = slow;
  start.mu_static = 0.34;
  const Identification control = identify({{synthesize(slow, 20, 1, 2), start}}, o);
  EXPECT_TRUE(parameter(control, "mu_static").identifiable);
  EXPECT_NEAR(parameter(control, "mu_static").estimate, 0.36,
              4 * parameter(control, "mu_static").standard_error);
}

// The paper's profile with jump accelerations: both jumps cross the static limit, so the part
// breaks loose at the jump instants whatever mu_static is (docs/identification.md,
// "Identifiability"); mu_static is not identifiable even though the part sticks.
TEST(IdentificationIdentifiability, JumpProfileHidesTheStaticCoefficient) {
  SimulateConfig truth = truth_config(false);
  truth.mu_static = 0.33;
  SimulateConfig start = truth;
  start.mu_static = 0.32;
  IdentificationOptions o;
  o.free = {"mu", "mu_static", kTimeOffset};
  o.starts = 0;
  const Identification r = identify({{synthesize(truth, 20, 3), start}}, o);
  EXPECT_FALSE(parameter(r, "mu_static").identifiable);
  EXPECT_TRUE(parameter(r, "mu").identifiable);
}

// A part that stops before the rough region: c_mu is never seen.
TEST(IdentificationIdentifiability, PartThatNeverReachesTheRoughRegion) {
  SimulateConfig truth = step_config();
  truth.x_mu = 0.05;  // 50 mm: the part moves about 5 mm in 30 periods
  IdentificationOptions o;
  o.free = {"mu", "c_mu", kTimeOffset};
  o.starts = 0;
  const Identification r = identify({{synthesize(truth, 30, 2), truth}}, o);
  const IdentifiedParameter& c = parameter(r, "c_mu");
  EXPECT_FALSE(c.identifiable);
  EXPECT_NE(c.reason.find("never reaches"), std::string::npos) << c.reason;
  EXPECT_TRUE(parameter(r, "mu").identifiable);
}

// Two runs at different drive settings (amplitude 1 and 1.4) in one fit: the estimates agree
// with the truth and are tighter than either run's alone.
TEST(IdentificationSeveralRuns, TwoDriveSettingsInOneFit) {
  SimulateConfig a = truth_config(true, 1), b = truth_config(true, 1.4);
  a.mu_static = b.mu_static = 0.36;
  SimulateConfig sa = a, sb = b;
  sa.mu = sb.mu = 0.31;
  sa.mu_static = sb.mu_static = 0.35;
  IdentificationOptions o;
  o.free = {"mu", "mu_static", kTimeOffset};
  o.starts = 0;
  const MeasuredMotion da = synthesize(a, 20, 11), db = synthesize(b, 20, 12);
  const Identification both = identify({{da, sa}, {db, sb}}, o);
  const Identification only_a = identify({{da, sa}}, o);
  const Identification only_b = identify({{db, sb}}, o);
  ASSERT_EQ(both.runs.size(), 2u);
  for (auto [name, value] :
       std::vector<std::pair<std::string, double>>{{"mu", 0.3}, {"mu_static", 0.36}}) {
    const IdentifiedParameter& p = parameter(both, name);
    EXPECT_NEAR(p.estimate, value, 4 * p.standard_error) << name;
    EXPECT_LT(p.standard_error, parameter(only_a, name).standard_error) << name;
    EXPECT_LT(p.standard_error, parameter(only_b, name).standard_error) << name;
  }
  for (const FittedRun& f : both.runs)
    EXPECT_NEAR(f.time_offset, kOffset, 5 * f.time_offset_standard_error);
}

TEST(IdentificationBadInput, NamesTheParameterOrTheFile) {
  const SimulateConfig c = truth_config(true);
  const MeasuredMotion d = synthesize(c, 4, 1);
  const auto message = [&](IdentificationOptions o, const MeasuredMotion& data) -> std::string {
    try {
      identify({{data, c}}, o);
    } catch (const InvalidParameter& e) {
      return e.what();
    }
    return "(no error)";
  };
  IdentificationOptions o;
  o.starts = 0;
  o.free = {"mu", "friction_coefficient"};
  EXPECT_NE(message(o, d).find("friction_coefficient"), std::string::npos) << message(o, d);
  o.free = {"c_mu"};  // uniform friction: no c_mu
  EXPECT_NE(message(o, d).find("c_mu"), std::string::npos) << message(o, d);
  o.free = {"mu", "mu"};
  EXPECT_NE(message(o, d).find("named twice"), std::string::npos);
  o.free = {"x0"};
  EXPECT_NE(message(o, d).find("shooting window"), std::string::npos);
  o.free = {};
  EXPECT_NE(message(o, d).find("free"), std::string::npos);
  o.free = {"mu"};
  o.window_periods = 0;
  EXPECT_NE(message(o, d).find("window_periods"), std::string::npos);
  o.window_periods = 1;
  // 4 samples, 1 free + 2 per window: 3 estimated, then 2 samples: fewer than that.
  MeasuredMotion few = d;
  few.t.resize(2), few.x.resize(2), few.line.resize(2);
  const std::string m = message(o, few);
  EXPECT_NE(m.find("synthetic-1.csv samples"), std::string::npos) << m;
  EXPECT_NE(m.find("estimated parameters"), std::string::npos) << m;
  o.bounds["mu"] = {0.4, 0.5};  // does not contain the config's 0.3
  EXPECT_NE(message(o, d).find("bounds mu"), std::string::npos) << message(o, d);
}

// The uncertainty file of a hand-made result reads back through load_uncertainty with the
// delta method for mu_static / mu: mu = 0.3 (var 1e-6), mu_static = 0.36 (var 4e-6), cov 1e-6:
//   ratio 1.2, var = 4e-6/0.09 + 0.1296 * 1e-6/0.0081 - 2 * 0.36 * 1e-6/0.027
//                  = 4.4444e-5 + 1.6e-5 - 2.6667e-5 = 3.3778e-5, sd = 5.8119e-3.
TEST(IdentificationReport, UncertaintyFileReadsBackWithTheDeltaMethod) {
  Identification r;
  IdentifiedParameter mu{"mu", 0.3, 0.3, 1e-3, 0.298, 0.302, NAN, NAN, true, ""};
  IdentifiedParameter ms{"mu_static", 0.36, 0.36, 2e-3, 0.356, 0.364, NAN, NAN, true, ""};
  IdentifiedParameter xm{"x_mu", 1.5e-3, 1.5e-3, 1e-6, 0, 0, NAN, NAN, true, ""};
  IdentifiedParameter cm{"c_mu", 2.5, NAN, NAN, NAN, NAN, NAN, NAN, false, "never seen"};
  r.parameters = {mu, ms, xm, cm};
  r.covariance = {1e-6, 1e-6, 0, NAN, 1e-6, 4e-6, 0, NAN, 0, 0, 1e-12, NAN, NAN, NAN, NAN, NAN};
  const std::string text = identification_uncertainty(r, 0.3);
  EXPECT_NE(text.find("# c_mu: not identifiable"), std::string::npos) << text;
  testing::TempDir dir;
  const std::string path = dir.file("u.toml");
  std::ofstream(path) << text;
  const ProcessUncertainty u = load_uncertainty(path);
  const auto& n_mu = std::get<Normal>(u.mu);
  EXPECT_DOUBLE_EQ(n_mu.mean, 0.3);
  EXPECT_DOUBLE_EQ(n_mu.sd, 1e-3);
  const auto& n_ratio = std::get<Normal>(u.static_ratio);
  EXPECT_NEAR(n_ratio.mean, 1.2, 1e-15);
  EXPECT_NEAR(n_ratio.sd, 5.8119e-3, 1e-7);
  const auto& n_x = std::get<Normal>(u.x_mu_offset);
  EXPECT_EQ(n_x.mean, 0);
  EXPECT_DOUBLE_EQ(n_x.sd, 1e-6);
  EXPECT_TRUE(std::holds_alternative<Known>(u.c_mu));
  // The JSON report: absent values are null.
  const nlohmann::json j = identification_json(r);
  EXPECT_TRUE(j["parameters"][3]["estimate"].is_null());
  EXPECT_EQ(j["parameters"][3]["reason"], "never seen");
}

}  // namespace selfalign::identification_test
