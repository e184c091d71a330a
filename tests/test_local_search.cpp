// Tests for local_search.hpp's progress contract: a long local run reports progress while it
// is under way, and an exception thrown by progress stops the search at once and propagates
// (how a front end cancels an optimisation on Ctrl-C).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "selfalign/design/local_search.hpp"

using namespace selfalign;

namespace {
struct SearchStop {};  // the front end's own exception type: must come out as is
}  // namespace

TEST(LocalSearch, AThrowingProgressStopsARunUnderWay) {
  // One COBYLA run of up to 400 evaluations of 2 ms each (~0.8 s) on a function it cannot
  // finish early (an oscillating valley, tolerance 0). The heartbeat comes every 50 ms, so the
  // first call to progress, which throws, ends the run after ~25 evaluations, not ~400.
  int evaluations = 0;
  LocalSearchProblem p;
  p.lower = {-10, -10, -10};
  p.upper = {10, 10, 10};
  p.max_evaluations = 400;
  p.relative_tol = 0;
  p.restarts = 0;
  p.evaluate = [&](std::span<const double> x) {
    ++evaluations;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    DesignEvaluation e;
    for (double v : x) e.objective += v * v + std::sin(40 * v);
    return e;
  };
  int calls = 0;
  EXPECT_THROW(local_search(p, {{9, -9, 7}},
                            [&](int done, int total) {
                              ++calls;
                              EXPECT_EQ(done, 0);
                              EXPECT_EQ(total, 1);
                              throw SearchStop{};
                            }),
               SearchStop);
  EXPECT_EQ(calls, 1);
  // 50 ms / 2 ms = 25 evaluations, and a few more where the machine is slow to wake a sleeper.
  EXPECT_LT(evaluations, 100);
}
