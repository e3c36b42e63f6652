// What a run of several views shows while it runs (Progress; docs/design.md, Views: what the
// terminal shows): a line at most every interval in a log, a bar on a terminal, nothing with
// `none`; `auto` chooses by the terminal.

#include <gtest/gtest.h>

#include <sstream>

#include "zrender/base/Error.hpp"
#include "zrender/cli/Progress.hpp"

namespace zrender {
namespace {

TEST(Progress, LinesComeAtMostEveryIntervalWithRateAndTimeLeft) {
  std::ostringstream err;
  double now = 0.0;
  Progress progress(err, ProgressMode::Lines, 10, 5000.0, [&] { return now; });
  for (int i = 0; i < 10; ++i) {
    now += 1000.0;  // a view a second
    progress.viewDone();
  }
  progress.finish();
  // At 5 s and 10 s; the last view is the summary line's, not a progress line.
  EXPECT_EQ(err.str(), "zrender: 5/10 views, 1.0 views/s, 5 s left\n");
}

TEST(Progress, ABarIsRedrawnInPlaceAndCleared) {
  std::ostringstream err;
  double now = 0.0;
  Progress progress(err, ProgressMode::Bar, 4, 5000.0, [&] { return now; });
  now = 500.0;
  progress.viewDone();
  const std::string first = err.str();
  EXPECT_EQ(first.rfind(
                "\rzrender: [#######.......................] 1/4 views, 2.0 views/s, 2 s left", 0),
            0u)
      << first;
  EXPECT_EQ(first.find('\n'), std::string::npos);
  progress.finish();
  EXPECT_EQ(err.str().back(), '\r');
}

TEST(Progress, NoneSaysNothing) {
  std::ostringstream err;
  double now = 0.0;
  Progress progress(err, ProgressMode::None, 3, 0.0, [&] { return now += 10000.0; });
  for (int i = 0; i < 3; ++i) progress.viewDone();
  progress.finish();
  EXPECT_EQ(err.str(), "");
}

TEST(Progress, AutoIsABarOnATerminalLinesInALogNothingForOneView) {
  EXPECT_EQ(progressMode("auto", true, 5), ProgressMode::Bar);
  EXPECT_EQ(progressMode("auto", false, 5), ProgressMode::Lines);
  EXPECT_EQ(progressMode("auto", true, 1), ProgressMode::None);
  EXPECT_EQ(progressMode("lines", true, 1), ProgressMode::Lines);
  EXPECT_EQ(progressMode("none", true, 5), ProgressMode::None);
  EXPECT_THROW(progressMode("fancy", true, 5), InputError);
}

}  // namespace
}  // namespace zrender
