// Tests of the internal parallel loop of every grid study (src/analysis/parallel_cells.hpp):
// progress comes within a long chunk of cells, and an exception thrown by the progress
// callback (a front end cancelling the study on Ctrl-C) stops every worker at its next cell.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "../src/analysis/parallel_cells.hpp"

using namespace selfalign;

namespace {
struct CellsStop {};
constexpr std::size_t kCells = 512 * 16;
constexpr int kCellsPerInterval = 10;  // 50 ms / 5 ms
}  // namespace

TEST(ParallelCells, AThrowingProgressStopsTheStudyWithinAReportingInterval) {
  // 512 x 16 cells of 5 ms: chunks of >= 16 cells (the grain is n / 512), >= 80 ms each, longer
  // than the reporting interval (50 ms). The callback throws at its first call, which comes
  // after ~10 cells of one worker; every other worker stops at its next cell. Before, the
  // first report came at the end of a chunk (>= 16 cells) and the other workers finished
  // their chunks.
  using namespace std::chrono_literals;
  static_assert(detail::kProgressInterval == 50ms);
  for (int threads : {1, 2}) {
    std::atomic<int> computed{0};
    SweepOptions o;
    o.threads = threads;
    o.progress = [](std::size_t, std::size_t total) {
      EXPECT_EQ(total, kCells);
      throw CellsStop{};
    };
    EXPECT_THROW(detail::parallel_cells(kCells, o,
                                        [&](std::size_t) {
                                          ++computed;
                                          std::this_thread::sleep_for(5ms);
                                        }),
                 CellsStop);
    // Each worker: the cells of one interval, one more for the coarse clock (4 ms), one more,
    // and one started as the other threw.
    EXPECT_LE(computed.load(), threads * (kCellsPerInterval + 3)) << threads << " threads";
  }
}

TEST(ParallelCells, ReportsEveryCellOnceAndEndsAtTheTotal) {
  std::size_t last = 0;
  std::atomic<int> computed{0};
  SweepOptions o;
  o.threads = 2;
  o.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_GE(done, last);
    EXPECT_EQ(total, 1000u);
    last = done;
  };
  detail::parallel_cells(1000, o, [&](std::size_t) { ++computed; });
  EXPECT_EQ(computed.load(), 1000);
  EXPECT_EQ(last, 1000u);
}
