// BandOrder: bands start longest first by the times kept from the last frame, whatever the
// cut; row order when nothing is known.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "zrender/raster/BandOrder.hpp"

namespace zrender {
namespace {

using Order = std::vector<uint32_t>;

TEST(BandOrder, RowOrderBeforeAnyTimes) {
  EXPECT_EQ(BandOrder().longestFirst(RowBands(100, 4)), (Order{0, 1, 2, 3}));
}

TEST(BandOrder, LongestFirstWithTheSameCut) {
  const RowBands rows(100, 4);
  BandOrder order;
  order.keep(rows, {1.0, 4.0, 2.0, 3.0});
  EXPECT_EQ(order.longestFirst(rows), (Order{1, 3, 2, 0}));
}

TEST(BandOrder, TimesFollowTheRowsToAnotherCut) {
  BandOrder order;
  // Bands of 32 rows: rows 0-31 take 1/32 ms each, 32-63 4/32, 64-95 2/32, 96-127 3/32 (sums
  // exact in binary).
  order.keep(RowBands(128, 4), {1.0, 4.0, 2.0, 3.0});
  // Two bands of 64 rows: 5 and 5 ms, a tie left in row order.
  EXPECT_EQ(order.longestFirst(RowBands(128, 2)), (Order{0, 1}));
  // Eight of 16 rows: 0.5, 0.5, 2, 2, 1, 1, 1.5, 1.5 ms.
  EXPECT_EQ(order.longestFirst(RowBands(128, 8)), (Order{2, 3, 6, 7, 4, 5, 0, 1}));
  // Three of 43 rows, cut inside the kept bands: [0, 43) 1 + 11 x 4/32 = 2.375 ms,
  // [43, 86) 21 x 4/32 + 22 x 2/32 = 4 ms, [86, 128) 10 x 2/32 + 3 = 3.625 ms.
  EXPECT_EQ(order.longestFirst(RowBands(128, 3)), (Order{1, 2, 0}));
}

TEST(BandOrder, AnotherHeightStartsInRowOrder) {
  BandOrder order;
  order.keep(RowBands(100, 4), {1.0, 4.0, 2.0, 3.0});
  EXPECT_EQ(order.longestFirst(RowBands(120, 4)), (Order{0, 1, 2, 3}));
}

TEST(BandOrder, EveryBandDrawnOnceAndTheNextFrameStartsWithTheLongest) {
  const RowBands rows(64, 4);
  for (int count : {1, 2}) {
    const Threads threads(count);
    BandOrder order;
    std::vector<std::atomic<int>> drawn(4);
    // Band 2 takes 50 ms, the others next to nothing.
    order.forEachBand(threads, rows, [&](size_t b) {
      ++drawn[b];
      if (b == 2) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    });
    for (const std::atomic<int>& d : drawn) EXPECT_EQ(d.load(), 1);
    EXPECT_EQ(order.longestFirst(rows).front(), 2u) << count << " threads";
  }
}

}  // namespace
}  // namespace zrender
