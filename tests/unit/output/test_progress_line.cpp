#include "plyform/output/progress_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace plyform::output {
namespace {

std::size_t count(const std::string& text, char c) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), c));
}

TEST(ProgressLine, QuietWhenNotEnabled) {
  std::ostringstream out;
  ProgressLine progress(out, false);
  progress.update(0.5, 1.0, 10, 1e-3, 1.0);
  progress.finish();
  EXPECT_TRUE(out.str().empty());
  EXPECT_FALSE(progress.enabled());
}

TEST(ProgressLine, ShowsTimePercentCycleStepWallAndEta) {
  std::ostringstream out;
  ProgressLine progress(out, true);
  progress.update(0.0, 0.01, 0, 1e-6, 0.0);
  progress.update(0.0025, 0.01, 2500, 1e-6, 30.0);  // a quarter in 30 s: 90 s left
  const std::string text = out.str();
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_EQ(last.rfind("t 2.5000e-03 / 1.0000e-02 ( 25.0%)  cycle 2500  dt 1.000e-06  wall 30s  "
                       "ETA 1m30s",
                       0),
            0u)
      << last;
  EXPECT_EQ(count(text, '\n'), 0u);
}

TEST(ProgressLine, AtMostFiveTimesPerSecond) {
  std::ostringstream out;
  ProgressLine progress(out, true);
  for (int i = 0; i <= 1000; ++i) {  // 1000 updates over 2 s of wall time
    progress.update(1e-5 * i, 1e-2, i, 1e-5, 0.002 * i);
  }
  const std::size_t draws = count(out.str(), '\r');
  EXPECT_GE(draws, 10u);
  EXPECT_LE(draws, 11u);
}

TEST(ProgressLine, FinishShowsTheLastStateAndEndsTheLine) {
  std::ostringstream out;
  ProgressLine progress(out, true);
  progress.update(0.0, 1.0, 0, 0.1, 0.0);
  progress.update(1.0, 1.0, 10, 0.1, 0.05);  // throttled
  EXPECT_EQ(count(out.str(), '\r'), 1u);
  progress.finish();
  const std::string text = out.str();
  EXPECT_EQ(count(text, '\r'), 2u);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("(100.0%)  cycle 10"), std::string::npos) << text;
  EXPECT_NE(text.find("ETA 0s"), std::string::npos) << text;
}

TEST(ProgressLine, ShorterLineClearsTheLongerOne) {
  std::ostringstream out;
  ProgressLine progress(out, true, 0.0);
  progress.update(0.0, 1.0, 123456789, 0.1, 0.0);
  const std::size_t first = out.str().size();
  progress.update(0.5, 1.0, 1, 0.1, 4000.0);
  const std::string text = out.str();
  EXPECT_EQ(text.size() - first, first);  // padded to the same width
}

TEST(ProgressLine, TerminalCheckDoesNotThrow) {
  EXPECT_NO_THROW((void)stdout_is_terminal());
}

}  // namespace
}  // namespace plyform::output
