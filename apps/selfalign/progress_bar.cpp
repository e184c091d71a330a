#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace selfalign::cli {
namespace {

constexpr int kBarCells = 24;  // characters of the bar itself

// m:ss, or h:mm:ss from one hour on.
std::string format_duration(double seconds) {
  const long long s = std::llround(std::max(0.0, seconds));
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%lld:%02lld", s / 60, s % 60);
  return text;
}

}  // namespace

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

std::string format_progress(std::size_t done, std::size_t total, double elapsed_s) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / total);
  const int filled = static_cast<int>(fraction * kBarCells);
  std::string line = "[";
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(kBarCells - filled), '.');
  line += ']';
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, " %3d%%  %zu/%zu  elapsed %s  ETA ",
                static_cast<int>(fraction * 100), done, total, format_duration(elapsed_s).c_str());
  line += numbers;
  if (done == 0)
    line += "--:--";
  else
    line += format_duration(elapsed_s * static_cast<double>(total - std::min(done, total)) /
                            static_cast<double>(done));
  return line;
}

ProgressBar::ProgressBar(std::ostream& out, bool enabled)
    : out_(out), enabled_(enabled), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  if (finished_) return;
  done_ = std::max(done_, done);
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done_ < total && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(done_, total);
}

void ProgressBar::draw(std::size_t done, std::size_t total) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line = format_progress(done, total, elapsed);
  const std::size_t width = line.size();
  if (width < last_width_) line += std::string(last_width_ - width, ' ');  // wipe a longer line
  last_width_ = width;
  out_ << '\r' << line << std::flush;
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (drawn_) out_ << '\n' << std::flush;
}

}  // namespace selfalign::cli
