#pragma once
// Internal: the deterministic parallel loop of every grid study. Cell i is computed by
// body(i) into its own slot, so results do not depend on the thread count.

#ifndef SELFALIGN_SERIAL
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <string>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"

namespace selfalign::detail {

// The longest a worker computes cells without reporting progress: a front end's callback can
// then cancel a study (by throwing, e.g. on Ctrl-C) within about this plus one cell, however
// large the study's chunks of cells are.
inline constexpr std::chrono::milliseconds kProgressInterval{50};

// A monotonic clock cheap enough to read after every cell: Linux's coarse clock (~10 ns a read,
// a few ms resolution, plenty for kProgressInterval); steady_clock elsewhere.
inline std::chrono::nanoseconds coarse_now() {
#ifdef CLOCK_MONOTONIC_COARSE
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC_COARSE, &t);
  return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
#else
  return std::chrono::steady_clock::now().time_since_epoch();
#endif
}

// Runs body(i) for i in [0, n) on options.threads workers, reporting progress after each
// chunk of cells and, within a chunk, every kProgressInterval. A cell whose body throws does
// not abort the study: fail(i, message) records it in the cell's own slot. An exception from
// the progress callback aborts it: the other workers stop at their next cell, and the
// exception propagates.
template <class Body, class Fail>
void parallel_cells(std::size_t n, const SweepOptions& o, const Body& body, const Fail& fail) {
#ifdef SELFALIGN_SERIAL
  // The single-threaded build (WebAssembly, wasm/CMakeLists.txt): the same cells in order.
  for (std::size_t i = 0; i < n; ++i) {
    try {
      body(i);
    } catch (const std::exception& e) {
      fail(i, std::string(e.what()));
    }
    if (o.progress) o.progress(i + 1, n);
  }
#else
  const int threads = worker_threads(o.threads);
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  std::size_t reported = 0;  // under progress_mutex: reports never go backwards
  const std::size_t grain = std::max<std::size_t>(1, n / 512);
  auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        auto last_report = coarse_now();
                        std::size_t counted = r.begin();  // cells of r added to done
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          if (tbb::is_current_task_group_canceling()) return;
                          try {
                            body(i);
                          } catch (const std::exception& e) {
                            fail(i, std::string(e.what()));
                          }
                          if (!o.progress) continue;
                          const auto now = coarse_now();
                          if (i + 1 != r.end() && now - last_report < kProgressInterval) continue;
                          last_report = now;
                          const std::size_t total = done += i + 1 - counted;
                          counted = i + 1;
                          std::lock_guard lock(progress_mutex);
                          reported = std::max(reported, total);
                          o.progress(reported, n);
                        }
                      });
  };
  tbb::task_arena arena(threads);
  arena.execute(run);
#endif
}

// The same for studies whose cells cannot fail on their own (the first failure is rethrown).
template <class Body>
void parallel_cells(std::size_t n, const SweepOptions& o, const Body& body) {
  std::mutex first_mutex;
  std::exception_ptr first;
  parallel_cells(n, o, [&](std::size_t i) {
    try {
      body(i);
    } catch (...) {
      std::lock_guard lock(first_mutex);
      if (!first) first = std::current_exception();
    }
  }, [](std::size_t, const std::string&) {});
  if (first) std::rethrow_exception(first);
}

}  // namespace selfalign::detail
