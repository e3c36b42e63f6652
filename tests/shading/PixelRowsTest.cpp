// PixelRows: the AVX2 run end and BGR packing give the scalar versions' results, on random rows
// of every length.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/shading/PixelRows.hpp"

namespace zrender {
namespace {

TEST(PixelRows, RunEndsOfTheVectorScanAreTheScalarOnes) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 rng(7);
  for (int trial = 0; trial < 3000; ++trial) {
    const int width = 1 + int(rng() % 90);
    std::vector<DepthKey> keys(static_cast<size_t>(width));
    // Runs of random lengths; the depth bits differ within a run, only the id counts.
    uint32_t id = rng() % 3 == 0 ? kBackgroundId : rng();
    for (int x = 0; x < width; ++x) {
      if (rng() % 12 == 0) id = rng() % 5 == 0 ? kBackgroundId : rng() % 4;
      keys[size_t(x)] = makeDepthKey(float(rng() % 1000) / 1000.0f, id);
    }
    for (int x = 0; x < width; ++x)
      ASSERT_EQ(runEndAvx2(keys.data(), x, width), runEndScalar(keys.data(), x, width))
          << "trial " << trial << ", x " << x;
  }
}

TEST(PixelRows, VectorPackingWritesTheScalarBytesAndNothingBeyond) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 rng(8);
  for (int count = 0; count < 70; ++count) {
    std::vector<uint32_t> colors(static_cast<size_t>(count));
    for (uint32_t& c : colors) c = rng() & 0xFFFFFFu;
    // Guard bytes after the row must stay as they were.
    std::vector<unsigned char> expected(3 * size_t(count) + 8, 0xAB), got(expected);
    packBgrScalar(colors.data(), count, expected.data());
    packBgrAvx2(colors.data(), count, got.data());
    EXPECT_EQ(got, expected) << count;
    for (int x = 0; x < count; ++x) {
      EXPECT_EQ(expected[3 * size_t(x)], colors[size_t(x)] & 0xFF);
      EXPECT_EQ(expected[3 * size_t(x) + 2], colors[size_t(x)] >> 16);
    }
    for (size_t i = 3 * size_t(count); i < expected.size(); ++i) EXPECT_EQ(expected[i], 0xAB);
  }
}

}  // namespace
}  // namespace zrender
