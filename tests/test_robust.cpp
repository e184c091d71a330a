// The uncertainty model, Monte Carlo, worst case, fragility and robust design
// (include/selfalign/robust/). Expected values come from closed forms: the normal CDF, eq. (41)
// for where an accumulating part ends, the stop condition of eq. (40) for P(stop), the Wilson
// interval's formula; and from a second Monte Carlo with another seed (docs/robust-design.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>

#include "sanitized.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/uncertainty_file.hpp"
#include "selfalign/robust/fragility.hpp"
#include "selfalign/robust/monte_carlo.hpp"
#include "selfalign/robust/robust_design.hpp"
#include "selfalign/robust/worst_case.hpp"

namespace selfalign {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The sanitizer build (a Debug build, ~20x slower here) screens some robust searches on fewer
// draws (50 instead of 100) and checks a claim on fewer independent runs.
using testing_support::kSanitized;
constexpr int kScreeningRuns = kSanitized ? 50 : 100;

// The issue's task: a 20 g part, mu 0.2, c_mu 2.5 over a 3 mm transition, 2 mm stroke,
// 50 m/s^2, 30 Hz, 40 mm to go, +-0.1 mm.
DesignRequest issue_task() {
  DesignRequest q;
  q.mass = 0.02, q.width = 0.003, q.mu = 0.2, q.c_mu = 2.5, q.distance = 0.04;
  q.stroke_max = 0.002, q.acceleration_max = 50, q.frequency_max = 30, q.tolerance = 1e-4;
  return q;
}

// A three-phase process of the task's scale: a2 = k c_mu mu g, a3 = 0.7 a2, 10 Hz, 2 mm
// (physical: 1/a2 + 1/a3 <= period^2 / (8 stroke) for k >= 0.8).
Process process_at(double k, double x_mu = 0.037) {
  const double a2 = k * 2.5 * 0.2 * 9.81;
  return {0.1, 0.002, a2, 0.7 * a2, std::numeric_limits<double>::infinity(), x_mu};
}

TEST(Distribution, NormalQuantilesAreTheInverseCdf) {
  // Phi(1) = 0.841344746068543 (tables); the half-normal's median is Phi^-1(0.75) = 0.674489750.
  EXPECT_NEAR(quantile(Normal{0, 1}, 0.841344746068543, 0), 1.0, 1e-12);
  EXPECT_NEAR(quantile(Normal{0.2, 0.01}, 0.5, 0), 0.2, 1e-15);
  EXPECT_NEAR(quantile(Normal{0, 1, 0, std::numeric_limits<double>::infinity()}, 0.5, 0),
              0.6744897501960817, 1e-12);
  const double u = 0.999999;
  const double truncated = quantile(Normal{0, 1, -1, 1}, u, 0);
  EXPECT_LE(truncated, 1.0);
  EXPECT_GT(truncated, 0.99);
  EXPECT_DOUBLE_EQ(quantile(Uniform{1, 3}, 0.25, 0), 1.5);
  EXPECT_DOUBLE_EQ(quantile(Samples{{3, 1, 2}}, 0.5, 0), 2);  // sorted {1, 2, 3}, index 1
  EXPECT_DOUBLE_EQ(quantile(Known{}, 0.3, 7.5), 7.5);
}

TEST(Distribution, DrawsHaveTheStatedMomentsAndIndependentInputs) {
  DesignRequest q = issue_task();
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Uniform{2.3, 2.7};
  const int n = 200'000;
  double m = 0, m2 = 0, c = 0, mc = 0;
  for (int r = 0; r < n; ++r) {
    const InputValues v = draw_inputs(q, u, 42, static_cast<std::uint64_t>(r));
    m += v[0], m2 += v[0] * v[0], c += v[1], mc += v[0] * v[1];
    ASSERT_EQ(v[3], q.width);  // known inputs keep the request's value
  }
  m /= n, m2 /= n, c /= n, mc /= n;
  const double sd = std::sqrt(m2 - m * m);
  // Standard errors: 0.01/sqrt(n) = 2.2e-5 for the mean, 0.01/sqrt(2n) = 1.6e-5 for the sd.
  EXPECT_NEAR(m, 0.2, 5 * 2.2e-5);
  EXPECT_NEAR(sd, 0.01, 5 * 1.6e-5);
  EXPECT_NEAR(c, 2.5, 5 * 0.4 / std::sqrt(12.0 * n));
  // Independence: the correlation of mu and c_mu is 0 within 5 / sqrt(n).
  const double corr = (mc - m * c) / (sd * 0.4 / std::sqrt(12.0));
  EXPECT_LT(std::abs(corr), 5 / std::sqrt(static_cast<double>(n)));
  // A pure function of (seed, run, input).
  EXPECT_EQ(uniform_draw(1, 7, 2), uniform_draw(1, 7, 2));
  EXPECT_NE(uniform_draw(1, 7, 2), uniform_draw(2, 7, 2));
  EXPECT_NE(uniform_draw(1, 7, 2), uniform_draw(1, 8, 2));
}

TEST(Distribution, BadInputNamesTheParameter) {
  const auto name_of = [](auto f) {
    try {
      f();
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("no error");
  };
  EXPECT_EQ(name_of([] { parse_distribution("mu", "normal:0.2,-0.01"); }), "mu.sd");
  EXPECT_EQ(name_of([] { parse_distribution("mu", "normal:0.2,0.01,0.25,0.3"); }), "mu.lower");
  EXPECT_EQ(name_of([] { parse_distribution("width", "samples:"); }), "width.samples");
  EXPECT_EQ(name_of([] { parse_distribution("mu", "gauss:1,2"); }), "mu");
  EXPECT_EQ(name_of([] { parse_distribution("mu", "uniform:0.3,0.2"); }), "mu.upper");
  const Distribution pct = parse_distribution("mu", "normal:0.2,5%");
  EXPECT_DOUBLE_EQ(std::get<Normal>(pct).sd, 0.01);
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.05};  // reaches mu <= 0 within 8.3 sd: must be truncated
  EXPECT_EQ(name_of([&] { validate(u); }), "mu.lower");
  u.mu = Normal{0.2, 0.05, 0.01, 1};
  EXPECT_EQ(name_of([&] { validate(u); }), "no error");
  EXPECT_EQ(name_of([] { uncertain_input_index("friction"); }), "uncertain");
}

// D32: draws the model cannot take name the uncertain input the user gave, before any run (an
// offset of 8.3 sd = 8e40 m put x_mu 1e40 widths away, refused as "width = 1"; a width of
// 1e-300 m made the period 6e148 T, refused as "period").
TEST(Distribution, DrawsWithoutAProcessNameTheInput) {
  const DesignRequest q = issue_task();
  const Process p = process_at(0.9);
  const auto refusal = [&](const char* name, const char* dist) {
    ProcessUncertainty u;
    set_input(u, name, dist);
    validate(u);
    try {
      validate_draws(q, p, u);
    } catch (const InvalidParameter& e) {
      return e.name();
    }
    return std::string("no error");
  };
  EXPECT_EQ(refusal("x_mu_offset", "normal:0,1e40"), "x_mu_offset.lower");
  EXPECT_EQ(refusal("width", "samples:1e-300,2e-300"), "width.lower");
  EXPECT_EQ(refusal("width", "normal:0.003,5%,0.002,0.004"), "no error");
  // Two inputs fine alone, not together (the transition must be >= 1e-9 |x_mu|): a width down
  // to 1e-8 m keeps x_mu = 0.037 m (the offset's nominal 0) within 3.7e6 widths, an offset up
  // to 100 m keeps x_mu within 6.7e4 nominal widths (1.5 mm); both at once, 1e10 widths.
  ProcessUncertainty u;
  set_input(u, "width", "uniform:1e-8,0.003");
  set_input(u, "x_mu_offset", "normal:0,20,-0.01,100");
  validate(u);
  MonteCarloOptions o;
  o.runs = 1;
  try {
    monte_carlo(q, p, u, o);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "width, x_mu_offset");
  }
}

TEST(UncertaintyFile, TheExampleReadsAsTheFlagsWould) {
  const ProcessUncertainty u =
      load_uncertainty(std::string(SELFALIGN_SOURCE_DIR) + "/examples/uncertainty.toml");
  EXPECT_DOUBLE_EQ(std::get<Normal>(u.mu).sd, 0.01);
  EXPECT_DOUBLE_EQ(std::get<Normal>(u.c_mu).sd, 0.125);
  EXPECT_TRUE(std::holds_alternative<Known>(u.width));
  EXPECT_THROW(load_uncertainty(std::string(SELFALIGN_SOURCE_DIR) + "/examples/simulate.toml"),
               InvalidParameter);  // its keys are not uncertain inputs
}

TEST(MonteCarlo, ProbabilityOfStoppingIsTheClosedFormOfEq40) {
  // Only mu uncertain, peak = 0.97 c_mu mu_nominal g: a run can stop for good iff
  // c_mu mu g >= peak, i.e. mu >= 0.97 x 0.2, so P(stop) = 1 - Phi((0.194 - 0.2)/0.01)
  // = Phi(0.6) = 0.7257. (Every draw still slips: a2 > mu g for mu < 0.2 + 8 sd.)
  const DesignRequest q = issue_task();
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  MonteCarloOptions o;
  o.runs = 20'000;
  o.seed = 3;
  const MonteCarloResult r = monte_carlo(q, process_at(0.97), u, o);
  const double expected = normal_cdf(0.6);
  const double se = std::sqrt(expected * (1 - expected) / o.runs);  // binomial, 0.0032
  EXPECT_NEAR(r.p_stop, expected, 4 * se);
  EXPECT_EQ(r.never_entered, 0);
  // Each run's stop agrees with the condition on its own draw.
  for (int i = 0; i < r.runs; ++i)
    EXPECT_EQ(r.kind[i] != StopKind::not_stopped, r.inputs[0][i] >= 0.97 * 0.2) << i;
}

TEST(MonteCarlo, AccumulatingRunsEndAtEq41OfTheirOwnDraw) {
  // x_stick,min = x_mu + w (peak/(mu g) - 1)/(c_mu - 1) (eq. 41) with the drawn mu, c_mu and w.
  const DesignRequest q = issue_task();
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.006};
  u.c_mu = Normal{2.5, 0.05};
  u.width = Uniform{0.0029, 0.0031};
  u.x_mu_offset = Interval{-1e-4, 1e-4};
  MonteCarloOptions o;
  o.runs = 2000;
  const Process p = process_at(0.85);
  const MonteCarloResult r = monte_carlo(q, p, u, o);
  int accumulated = 0;
  for (int i = 0; i < r.runs; ++i) {
    const double mu = r.inputs[0][i], c = r.inputs[1][i], w = r.inputs[3][i];
    const double x_mu = p.x_mu + r.inputs[4][i];
    const double x_stick_min = x_mu + w * (std::max(p.a2, p.a3) / (mu * q.gravity) - 1) / (c - 1);
    if (r.kind[i] == StopKind::accumulation) {
      ++accumulated;
      EXPECT_NEAR(r.end_position[i], x_stick_min, 1e-12) << i;
    } else if (r.kind[i] == StopKind::permanent_stick) {
      EXPECT_GE(r.end_position[i], x_stick_min - 1e-12) << i;  // eq. (40) holds there
    }
  }
  EXPECT_GT(accumulated, r.runs / 2);
}

TEST(MonteCarlo, IndependentOfThreadsAndChunks) {
  const DesignRequest q = issue_task();
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  MonteCarloOptions o;
  o.runs = 600;
  o.threads = 1;
  const Process p = process_at(0.9);
  const MonteCarloResult one = monte_carlo(q, p, u, o);
  o.threads = 2;
  const MonteCarloResult two = monte_carlo(q, p, u, o);
  std::vector<MonteCarloResult> parts;
  for (int first : {0, 250, 500}) {
    MonteCarloOptions c = o;
    c.first_run = static_cast<std::uint64_t>(first);
    c.runs = first == 500 ? 100 : 250;
    parts.push_back(monte_carlo(q, p, u, c));
  }
  const MonteCarloResult merged = merge_monte_carlo(parts);
  for (const MonteCarloResult* r : {&two, &merged}) {
    EXPECT_EQ(r->inputs, one.inputs);
    EXPECT_EQ(r->kind, one.kind);
    for (std::size_t i = 0; i < one.kind.size(); ++i) {
      EXPECT_EQ(std::memcmp(&r->end_position[i], &one.end_position[i], sizeof(double)), 0);
      EXPECT_EQ(std::memcmp(&r->process_time[i], &one.process_time[i], sizeof(double)), 0);
    }
    EXPECT_EQ(r->within, one.within);
  }
  std::swap(parts[0], parts[1]);
  EXPECT_THROW(merge_monte_carlo(parts), InvalidParameter);
}

TEST(MonteCarlo, SummaryStatistics) {
  // Wilson 95%: 0 of 10 gives [0, z^2/(n + z^2)] = [0, 0.27753].
  const auto [lo, hi] = wilson_interval(0, 10);
  EXPECT_EQ(lo, 0);
  EXPECT_NEAR(hi, 3.841458820694124 / 13.841458820694124, 1e-12);
  MonteCarloResult r;
  r.process_time = {3, 1, std::nan(""), 2};  // a run that never stops counts as +inf
  r.end_position = {1, 2, std::nan(""), 3};
  EXPECT_EQ(process_time_quantile(r, 0.5), 2);
  EXPECT_EQ(process_time_quantile(r, 0.75), 3);
  EXPECT_TRUE(std::isinf(process_time_quantile(r, 0.99)));
  EXPECT_EQ(end_position_quantile(r, 0.5), 2);  // over the three that stopped
  const Histogram h = histogram({0, 1, 2, 3, std::nan("")}, 3);
  EXPECT_EQ(h.counts, (std::vector<int>{1, 1, 2}));
  EXPECT_DOUBLE_EQ(h.edges.back(), 3);
}

TEST(WorstCase, FindsTheCornerEq41Predicts) {
  // mu in [0.19, 0.21], c_mu in [2.4, 2.6] on an accumulating process: the end of eq. (41)
  // falls with mu and with c_mu, so the worst |end - target| is at a corner, by hand.
  DesignRequest q = issue_task();
  const Process p = process_at(0.85, 0.0375);
  ProcessUncertainty u;
  u.mu = Interval{0.19, 0.21};
  u.c_mu = Interval{2.4, 2.6};
  const auto end = [&](double mu, double c) {
    return p.x_mu + q.width * (p.a2 / (mu * q.gravity) - 1) / (c - 1);
  };
  double expected = 0;
  for (double mu : {0.19, 0.21})
    for (double c : {2.4, 2.6}) expected = std::max(expected, std::abs(end(mu, c) - q.distance));
  const WorstCase w = worst_case(q, p, u);
  EXPECT_NEAR(w.worst_error, expected, 1e-9);
  EXPECT_GT(w.evaluations, 4 + 64);  // corners, Halton points and a local search
  EXPECT_NE(w.method.find("Nelder-Mead"), std::string::npos);
  EXPECT_TRUE(std::isfinite(w.slowest_time));
}

TEST(Fragility, TheNominalDesignOfTheIssueIsFlagged) {
  // `design` for the task gives y2'' = c_mu mu g exactly (the issue's report, below; the CLI
  // test NominalDesignOfTheIssueCarriesAFragilityWarning runs the design itself): margin 0.
  const DesignRequest q = issue_task();
  const Process nominal{0.09767186838611738, 0.002, 2.5 * 0.2 * 9.81, 2.6568750000000003,
                        std::numeric_limits<double>::infinity(), 0.037};
  const Fragility f = fragility(q, nominal);
  EXPECT_NEAR(f.stop_margin, 0, 1e-15);
  EXPECT_NEAR(f.motion_margin, 2.5 - 1, 1e-14);  // y2''/(mu g) - 1 = c_mu - 1
  EXPECT_LT(f.stop_margin, 0.05);
  EXPECT_FALSE(f.warnings.empty());
  EXPECT_TRUE(std::isnan(f.end_mu[0]));  // mu 5% low: never stops
  // mu_static: the request gave none, so the design assumed mu_static = mu; a plain warning
  // says what 5% more does. Ratio max(1, 0.95) = 1 is the nominal run itself; at 1.05 the part
  // sticks for good where 1.05 m(x) >= peak, at or beyond x_mu + w (peak/(1.05 mu g) - 1)/(c_mu
  // - 1) (eqs. 40, 41 with the static coefficient).
  EXPECT_TRUE(f.assumes_equal_static);
  EXPECT_EQ(f.end_static[0], f.end_nominal);
  const double peak = 2.5 * 0.2 * 9.81 / (0.2 * 9.81);  // [mu g]
  EXPECT_GE(f.end_static[1], 0.037 + 0.003 * (peak / 1.05 - 1) / (2.5 - 1) - 1e-12);
  EXPECT_GT(f.end_shift_static, 0);
  const auto plain = std::find_if(f.warnings.begin(), f.warnings.end(), [](const std::string& w) {
    return w.find("assumes mu_static = mu") != std::string::npos;
  });
  EXPECT_NE(plain, f.warnings.end());
  // Given mu_static, the design no longer assumes it.
  DesignRequest with_static = q;
  with_static.mu_static = 0.24;
  const Fragility s = fragility(with_static, nominal);
  EXPECT_FALSE(s.assumes_equal_static);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("assumes mu_static"), std::string::npos) << w;
  // A design with a 15% margin and a wide tolerance is not fragile in stopping.
  DesignRequest wide = q;
  wide.tolerance = 1e-3;
  const Fragility g = fragility(wide, process_at(0.85));
  EXPECT_NEAR(g.stop_margin, 0.15, 1e-12);
  for (const std::string& w : g.warnings) EXPECT_EQ(w.find("stopping"), std::string::npos) << w;
}

TEST(RobustDesign, MeetsTheTargetUnderAnIndependentMonteCarlo) {
  // +-0.5 mm is reachable under mu, c_mu +-5% (1 sd); checked with another seed, 10000 runs.
  DesignRequest q = issue_task();
  q.tolerance = 5e-4;
  q.acceleration_grid = 16, q.period_grid = 6, q.stroke_grid = 1;  // coarser: faster
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  RobustOptions o;
  o.screening_runs = 100;  // (50 do not find a design that meets the target)
  o.verification_runs = 2000;
  const RobustDesignResult r = design_robust(q, u, o);
  ASSERT_TRUE(r.meets_target) << r.message;
  MonteCarloOptions check;
  check.seed = 20261130;
  check.runs = 10'000;
  const MonteCarloResult mc = monte_carlo(q, r.process, u, check);
  EXPECT_GE(mc.p_within, 0.99) << mc.within;
  EXPECT_TRUE(std::isfinite(r.time_quantile_value));
}

TEST(RobustDesign, TheIssueTaskIsInfeasibleAndSaysWithWhatProbability) {
  // +-0.1 mm cannot be reached: the end moves by w r/(c_mu - 1) per unit relative error of mu
  // (eq. 41, r = peak/(mu g) >= 1), 0.1 mm per 5% at best. The result says so with the best
  // probability, and an independent Monte Carlo of that profile agrees with it.
  DesignRequest q = issue_task();
  q.acceleration_grid = 8, q.period_grid = 2, q.stroke_grid = 1;  // a coarser grid: faster
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  RobustOptions o;
  o.screening_runs = kScreeningRuns, o.finalists = 3;
  o.verification_runs = 2000;
  const RobustDesignResult r = design_robust(q, u, o);
  ASSERT_FALSE(r.meets_target);
  EXPECT_NE(r.message.find("no profile within the limits reaches"), std::string::npos);
  // What is achievable: the tolerance the best profile holds at P >= 0.99, wider than asked.
  EXPECT_GT(r.achievable_tolerance, q.tolerance);
  EXPECT_NE(r.message.find("this design holds +-"), std::string::npos) << r.message;
  EXPECT_EQ(r.binding, "end-position spread");
  const double best = r.verification.p_within;
  EXPECT_GT(best, 0.4);
  EXPECT_LT(best, 0.9);
  MonteCarloOptions check;
  check.seed = 777;
  check.runs = 10'000;
  const MonteCarloResult mc = monte_carlo(q, r.process, u, check);
  const double se = std::sqrt(best * (1 - best) * (1.0 / check.runs + 1.0 / r.verification.runs));
  EXPECT_NEAR(mc.p_within, best, 4 * se);
  EXPECT_LT(mc.p_within_high, 0.99);
}

TEST(RobustDesign, JerkLimitedProfilesAndStaticAboveKinetic) {
  // --jerk-max and mu_static != mu: the candidates are jerk-limited, the runs use the drawn
  // static ratio, and an independent Monte Carlo of the result agrees with its verification.
  DesignRequest q = issue_task();
  q.tolerance = 5e-4, q.jerk_max = 3000, q.mu_static = 0.22;
  q.acceleration_grid = 10, q.period_grid = 3, q.stroke_grid = 1;
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.006};
  u.static_ratio = Uniform{1.05, 1.15};
  RobustOptions o;
  o.screening_runs = kScreeningRuns, o.finalists = 3;
  o.verification_runs = kSanitized ? 1000 : 2000;
  const RobustDesignResult r = design_robust(q, u, o);
  ASSERT_GT(r.verified, 0) << r.message;
  EXPECT_EQ(r.process.jerk, 3000);
  EXPECT_TRUE(std::isfinite(r.design.jerk));
  MonteCarloOptions check;
  check.seed = 99;
  check.runs = 4000;
  const MonteCarloResult mc = monte_carlo(q, r.process, u, check);
  const double p = r.verification.p_within;
  const double se = std::sqrt(std::max(p * (1 - p), 1e-4) * (1.0 / check.runs + 1.0 / o.verification_runs));
  EXPECT_NEAR(mc.p_within, p, 4 * se);
  // The static ratio drawn is the one the runs used: it spans the uniform's range.
  const auto [lo, hi] = std::minmax_element(mc.inputs[2].begin(), mc.inputs[2].end());
  EXPECT_GE(*lo, 1.05);
  EXPECT_LE(*hi, 1.15);
  EXPECT_GT(*hi - *lo, 0.09);
}

// R01 on a coarse grid: mu_static = 1.2 mu and a 5000 m/s^3 jerk limit (permanent sticks, whose
// end moves with x_mu by a walking step, not rigidly), mu and c_mu +-1% (1 sd), +-0.1 mm.
DesignRequest permanent_stick_task() {
  DesignRequest q = issue_task();
  q.mu_static = 0.24, q.jerk_max = 5000;
  q.acceleration_grid = 10, q.period_grid = 6, q.stroke_grid = 1;
  return q;
}
ProcessUncertainty one_percent() {
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.002};
  u.c_mu = Normal{2.5, 0.025};
  return u;
}

// The selection's order (robust_design.hpp), on the selection runs: a design that passes (95%
// Wilson lower bound >= target) before one that does not; then the lower T_p quantile, else
// the higher P(within).
bool no_worse(const RobustDesignResult& more, const RobustDesignResult& less,
              const RobustOptions& o) {
  const auto passes = [&](const RobustDesignResult& r) {
    return r.selection.p_within_low >= o.probability_target;
  };
  const auto time = [&](const RobustDesignResult& r) {
    return process_time_quantile(r.selection, o.time_quantile);
  };
  if (passes(less)) return passes(more) && time(more) <= time(less);
  return passes(more) || more.selection.p_within >= less.selection.p_within;
}

// The design of permanent_stick_task for (screening_runs, finalists), computed once each.
const RobustDesignResult& permanent_stick_design(int screening_runs, int finalists) {
  static std::map<std::pair<int, int>, RobustDesignResult> done;
  auto [it, fresh] = done.try_emplace({screening_runs, finalists});
  if (fresh) {
    RobustOptions o;
    o.screening_runs = screening_runs, o.finalists = finalists, o.verification_runs = 1000;
    it->second = design_robust(permanent_stick_task(), one_percent(), o);
  }
  return it->second;
}

TEST(RobustDesign, MoreEffortNeverSelectsAWorseDesign) {
  // Rungs of 25, 50, ... draws, each independent of the effort after it, and the same
  // selection draws: (25, 1) -> (50, 2) repeats the first rung and verifies a superset of the
  // finalists (the old screen, sliding x_mu rigidly, gave P = 0.941 at 25 runs and 0.939 at 50).
  // (The sanitizer build: one rung of 10 draws, 1 then 2 finalists.)
  const std::vector<std::pair<int, int>> efforts =
      kSanitized ? std::vector<std::pair<int, int>>{{10, 1}, {10, 2}}
                 : std::vector<std::pair<int, int>>{{25, 1}, {50, 2}};
  RobustOptions o;
  const RobustDesignResult* previous = nullptr;
  for (const auto& [runs, finalists] : efforts) {
    const RobustDesignResult& r = permanent_stick_design(runs, finalists);
    ASSERT_GT(r.verified, 0) << r.message;
    EXPECT_EQ(r.rungs.back(), runs);
    if (previous) {
      EXPECT_GE(r.verified, previous->verified);
      EXPECT_TRUE(no_worse(r, *previous, o))
          << runs << " runs, " << finalists << " finalists: P = " << r.selection.p_within
          << " after " << previous->selection.p_within;
    }
    previous = &r;
  }
}

TEST(RobustDesign, TheClaimAgreesWithAnIndependentMonteCarlo) {
  // The claim is the verification's, on draws that selected nothing: a Monte Carlo of 10^4 runs
  // with another seed lands within its 95% interval.
  const RobustDesignResult& r = permanent_stick_design(kSanitized ? 10 : 50, 2);
  ASSERT_GT(r.verified, 0) << r.message;
  EXPECT_NE(r.selection.seed, r.verification.seed);
  MonteCarloOptions check;
  check.seed = 20261202;
  check.runs = kSanitized ? 2000 : 10'000;
  const MonteCarloResult mc = monte_carlo(permanent_stick_task(), r.process, one_percent(), check);
  EXPECT_GE(mc.p_within, r.verification.p_within_low);
  EXPECT_LE(mc.p_within, r.verification.p_within_high);
  // When the target is missed the result says what the design holds: the 0.99-quantile of
  // |end - distance| over the verification, which the independent runs bear out.
  if (!r.meets_target) EXPECT_NE(r.message.find("this design holds"), std::string::npos);
  ASSERT_TRUE(std::isfinite(r.achievable_tolerance));
  int held = 0;
  for (double end : mc.end_position) held += std::abs(end - mc.target) <= r.achievable_tolerance;
  // The quantile comes from 1000 runs: 4 binomial standard errors of 0.99 at that count.
  const double se = std::sqrt(0.99 * 0.01 / r.verification.runs);
  EXPECT_NEAR(static_cast<double>(held) / mc.runs, 0.99, 4 * se);
}

TEST(RobustDesign, TheR01TaskMeetsItsTarget) {
  // The reproducer's task (docs/robust-design.md): mu_static = 1.2 mu, a jerk limit, mu and
  // c_mu +-5% (1 sd), +-0.5 mm, the default grid and effort. A profile on the grid reaches
  // P = 0.9987 (montecarlo, 10^4 runs); the old screen answered "none reaches P >= 0.99".
#ifdef SELFALIGN_SANITIZED_TESTS
  GTEST_SKIP() << "the default grid's search (3 s in release)";
#endif
  DesignRequest q = issue_task();
  q.mu_static = 0.24, q.jerk_max = 5000, q.tolerance = 5e-4;
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  const RobustDesignResult r = design_robust(q, u);
  ASSERT_TRUE(r.meets_target) << r.message;
  EXPECT_GE(r.verification.p_within, 0.99);
  EXPECT_GE(r.selection.p_within_low, 0.99);
}

TEST(RobustDesign, BadOptionsNameTheParameter) {
  DesignRequest q = issue_task();
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  RobustOptions o;
  o.probability_target = 1;
  EXPECT_THROW(design_robust(q, u, o), InvalidParameter);
  o.probability_target = 0.99;
  q.tolerance = 0;
  EXPECT_THROW(design_robust(q, u, o), InvalidParameter);
  // D36: the largest grid of the flags' ranges (8e7 points) is refused up front, naming it.
  q = issue_task();
  q.acceleration_grid = 200, q.period_grid = 100, q.stroke_grid = 20;
  try {
    design_robust(q, u, RobustOptions{});
    ADD_FAILURE() << "no error";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("acceleration_grid^2 x period_grid x stroke_grid"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace selfalign
