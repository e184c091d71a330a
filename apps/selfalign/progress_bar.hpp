#pragma once
// A one-line progress bar on a terminal for long runs (sweeps):
//   [##########..........]  50%  200/400  elapsed 0:03  ETA 0:03
// Redrawn in place ("\r") at most every kRedrawInterval, and always at the end; finished with
// a newline. Disabled (draws nothing) when not wanted: use it only when stderr is a terminal.

#include <chrono>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>

namespace selfalign::cli {

/// True when standard error is a terminal (isatty).
bool stderr_is_terminal();

/// The bar's text for `done` of `total` after `elapsed_s` seconds, without "\r" or newline.
/// The ETA extrapolates the mean rate so far ("--:--" before the first item).
std::string format_progress(std::size_t done, std::size_t total, double elapsed_s);

class ProgressBar {
 public:
  static constexpr std::chrono::milliseconds kRedrawInterval{100};

  /// Draws on `out` only when `enabled`; the clock starts now.
  ProgressBar(std::ostream& out, bool enabled);
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  /// Ends the line (finish()), also when a run fails part-way.
  ~ProgressBar();

  /// Reports progress; thread-safe. Out-of-order reports never move the bar backwards.
  void update(std::size_t done, std::size_t total);
  /// Ends the line with a newline once, if anything was drawn.
  void finish();

 private:
  void draw(std::size_t done, std::size_t total);  // with mutex_ held

  std::ostream& out_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::size_t done_ = 0;
  std::size_t last_width_ = 0;
  bool drawn_ = false, finished_ = false;
  std::mutex mutex_;
};

}  // namespace selfalign::cli
