// The viewer's timing figures (view/FrameTimes.hpp): the median of the last 30 frame times and
// the frames shown per second over them.

#include <gtest/gtest.h>

#include "zrender/view/FrameTimes.hpp"

namespace zrender {
namespace {

TEST(FrameTimes, NothingBeforeTheFirstFrames) {
  FrameTimes t;
  EXPECT_EQ(t.medianFrameMs(), 0.0);
  EXPECT_EQ(t.framesPerSecond(), 0.0);
  t.add(5.0, 100.0);
  EXPECT_EQ(t.medianFrameMs(), 5.0);
  EXPECT_EQ(t.framesPerSecond(), 0.0);
}

TEST(FrameTimes, TheMedianAndTheRateOfTheLastThirtyFrames) {
  FrameTimes t;
  // 40 frames shown every 20 ms; the first ten took 1000 ms to render, the others 1..30 ms.
  for (int i = 0; i < 40; ++i) t.add(i < 10 ? 1000.0 : double(i - 9), 20.0 * i);
  EXPECT_EQ(t.count(), FrameTimes::kFrames);
  EXPECT_DOUBLE_EQ(t.medianFrameMs(), 15.5);  // of 1..30: the slow ones are forgotten
  EXPECT_DOUBLE_EQ(t.framesPerSecond(), 50.0);
}

}  // namespace
}  // namespace zrender
