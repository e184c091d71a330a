#pragma once
// Internal: the deterministic parallel loop of every grid study. Cell i is computed by
// body(i) into its own slot, so results do not depend on the thread count.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <mutex>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"

namespace selfalign::detail {

// Runs body(i) for i in [0, n) on options.threads workers, reporting progress.
template <class Body>
void parallel_cells(std::size_t n, const SweepOptions& o, const Body& body) {
  if (o.threads < 0) throw InvalidParameter("threads", o.threads, "must be >= 0 (0: all cores)");
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  std::size_t reported = 0;  // under progress_mutex: reports never go backwards
  const std::size_t grain = std::max<std::size_t>(1, n / 512);
  auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
                        const std::size_t now = done += r.size();
                        if (o.progress) {
                          std::lock_guard lock(progress_mutex);
                          reported = std::max(reported, now);
                          o.progress(reported, n);
                        }
                      });
  };
  if (o.threads == 0) {
    run();
  } else {
    tbb::task_arena arena(o.threads);
    arena.execute(run);
  }
}

}  // namespace selfalign::detail
