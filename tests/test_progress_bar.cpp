// Tests of the CLI's progress bar (apps/selfalign/progress_bar.hpp): the line's text, drawing
// only when enabled, never moving backwards, and ending the line exactly once.

#include <gtest/gtest.h>

#ifdef SELFALIGN_PROGRESS_BAR

#include <sstream>
#include <string>

#include "progress_bar.hpp"

namespace selfalign::cli {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ProgressBar, LineShowsPercentCountElapsedAndEta) {
  const std::string start = format_progress(0, 400, 0.0);
  EXPECT_TRUE(contains(start, "  0%")) << start;
  EXPECT_TRUE(contains(start, "0/400")) << start;
  EXPECT_TRUE(contains(start, "ETA --:--")) << start;  // no rate yet

  // Half done after 3 s: the mean rate gives 3 s more.
  const std::string half = format_progress(200, 400, 3.0);
  EXPECT_TRUE(contains(half, " 50%")) << half;
  EXPECT_TRUE(contains(half, "200/400")) << half;
  EXPECT_TRUE(contains(half, "elapsed 0:03")) << half;
  EXPECT_TRUE(contains(half, "ETA 0:03")) << half;

  const std::string done = format_progress(400, 400, 3725.0);
  EXPECT_TRUE(contains(done, "100%")) << done;
  EXPECT_TRUE(contains(done, "elapsed 1:02:05")) << done;
  EXPECT_TRUE(contains(done, "ETA 0:00")) << done;
  EXPECT_EQ(done.find('.'), std::string::npos) << "a finished bar is full: " << done;
}

TEST(ProgressBar, DisabledBarWritesNothing) {
  std::ostringstream out;
  {
    ProgressBar bar(out, false);
    bar.update(1, 2);
    bar.update(2, 2);
    bar.finish();
  }
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressBar, RedrawsInPlaceNeverBackwardsAndEndsTheLineOnce) {
  std::ostringstream out;
  {
    ProgressBar bar(out, true);
    bar.update(3, 4);  // first report: drawn at once
    bar.update(1, 4);  // late report from another worker: ignored (throttled, and not newer)
    bar.update(4, 4);  // the end is always drawn
    bar.finish();
  }  // the destructor does not end the line a second time
  const std::string text = out.str();
  EXPECT_EQ(text.front(), '\r');
  EXPECT_TRUE(contains(text, "3/4")) << text;
  EXPECT_FALSE(contains(text, "1/4")) << text;
  EXPECT_TRUE(contains(text, "100%  4/4")) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\n'), text.size() - 1) << "exactly one newline, at the end";
}

TEST(ProgressBar, NothingDrawnMeansNoNewline) {
  std::ostringstream out;
  { ProgressBar bar(out, true); }
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace selfalign::cli

#else
TEST(ProgressBar, NeedsTheCli) {
  GTEST_SKIP() << "built without the CLI (SELFALIGN_BUILD_CLI=OFF)";
}
#endif
