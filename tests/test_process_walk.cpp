// Tests for robust/process_walk.hpp: a draw walked once and finished at any x_mu gives the
// outcome of the exact stopping run from rest at that x_mu (run_process, the second method),
// for every stop kind: permanent sticks (static > kinetic with a jerk limit), accumulation (the
// paper's law and profile) and runs that never stop.
#include <gtest/gtest.h>

#include "selfalign/special_values.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "selfalign/robust/process_walk.hpp"

namespace selfalign {
namespace {

// The walk restarts the exact solver at a period start t_k = k Δt, where the run from rest
// passes a switch of the profile anyway: the two differ by the rounding of the restart state
// only (seen: end positions bit-identical, times within 3e-13 s over runs of ~5 s).
constexpr double kEndTol = 1e-12;   // [m], of end positions ~0.04 m
constexpr double kTimeTol = 1e-10;  // [s], of times ~5 s

struct Case {
  const char* name;
  DesignRequest request;
  Process process;
};

std::vector<Case> cases() {
  DesignRequest q;  // the part: 20 g, 3 mm wide, mu 0.2, c_mu 2.5, 40 mm to go
  q.mass = 0.02, q.width = 0.003, q.mu = 0.2, q.c_mu = 2.5, q.distance = 0.04;
  q.tolerance = 5e-4;
  DesignRequest stick = q;  // R01: mu_static = 1.2 mu and a 5000 m/s^3 jerk limit
  stick.mu_static = 0.24, stick.jerk_max = 5000;
  // A three-phase profile with peak 0.97 c_mu mu g: a low-mu draw never stops (eq. 40).
  const double a2 = 0.97 * 2.5 * 0.2 * 9.81;
  return {{"permanent stick", stick, {0.09767186838611738, 0.0013333333333333333, 2.943, 1.839, 5000, 0}},
          {"accumulation", q, {0.1, 0.002, a2, 0.7 * a2, kInf, 0}}};
}

TEST(ProcessWalk, FinishesAtAnyXMuAsTheRunFromRest) {
  ProcessUncertainty u;
  u.mu = Normal{0.2, 0.01};
  u.c_mu = Normal{2.5, 0.125};
  u.width = Normal{0.003, 1e-4};
  u.x_mu_offset = Normal{0, 1e-4};
  for (const Case& c : cases()) {
    std::map<StopKind, int> kinds;
    for (std::uint64_t run = 0; run < 12; ++run) {
      const InputValues v = draw_inputs(c.request, u, 3, run);
      ProcessWalk walk(c.request, c.process, v, 3000);
      // x_mu over two walking steps (~0.5 mm each), out of order: the walk is extended on
      // demand and reused for the nearer ones.
      for (double x : {0.0395, 0.0385, 0.03905, 0.0388, 0.0392, 0.03875, 0.0396, 0.001}) {
        Process p = c.process;
        p.x_mu = x;
        const ProcessOutcome a = walk.at(x), b = run_process(c.request, p, v, 3000);
        SCOPED_TRACE(std::string(c.name) + ", run " + std::to_string(run) + ", x_mu " +
                     std::to_string(x));
        ASSERT_EQ(a.kind, b.kind);
        ++kinds[a.kind];
        EXPECT_NEAR(a.entry_time, b.entry_time, kTimeTol);
        if (b.kind == StopKind::not_stopped) continue;
        EXPECT_NEAR(a.end_position, b.end_position, kEndTol);
        EXPECT_NEAR(a.process_time, b.process_time, kTimeTol);
      }
    }
    // The cases reach the stop kinds they are for.
    if (c.process.jerk < kInf) EXPECT_GT(kinds[StopKind::permanent_stick], 50) << c.name;
    else EXPECT_GT(kinds[StopKind::accumulation], 20) << c.name;
  }
}

TEST(ProcessWalk, ABudgetSpentOnTheSmoothRegionNeverEnters) {
  // 3 periods cannot bring the part 40 mm: not stopped, never entered, as from rest.
  const Case c = cases()[1];
  const InputValues v = nominal_inputs(c.request, {});
  ProcessWalk walk(c.request, c.process, v, 3);
  const ProcessOutcome a = walk.at(0.037);
  EXPECT_EQ(a.kind, StopKind::not_stopped);
  EXPECT_TRUE(std::isnan(a.entry_time));
  EXPECT_LE(walk.periods(), 3);
  Process p = c.process;
  p.x_mu = 0.037;
  EXPECT_TRUE(std::isnan(run_process(c.request, p, v, 3).entry_time));
}

}  // namespace
}  // namespace selfalign
