// The nearest key of a depth plane over a rectangle of samples (nearestKeyOver): a bound that
// never exceeds the key of a sample in it, and is within a few ulps of the least one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "zrender/raster/RasterRules.hpp"
#include "zrender/visibility/NearestKey.hpp"

namespace zrender {
namespace {

TEST(NearestKey, IsABoundOfEverySampleKeyInTheRectangle) {
  // Random planes, including steep and nearly flat ones and ones that leave [0, 1], over
  // random rectangles: the bound never exceeds a sample's key, and is not far below it.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tight = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    DepthPlane p;
    const double scale = std::pow(10.0, -7.0 + 8.0 * unit(rng));
    p.a = (unit(rng) - 0.5) * scale;
    p.b = (unit(rng) - 0.5) * scale;
    p.c = unit(rng) * 1.2 - 0.1;
    const int x0 = int(unit(rng) * 1000), y0 = int(unit(rng) * 1000);
    const int x1 = x0 + int(unit(rng) * 40), y1 = y0 + int(unit(rng) * 40);
    const uint32_t id = uint32_t(unit(rng) * 1e6);
    const DepthKey bound = nearestKeyOver(p, id, x0, y0, x1, y1);
    DepthKey smallest = ~DepthKey(0);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        smallest = std::min(smallest, makeDepthKey(p.at(x, p.rowBase(y)), id));
    ASSERT_LE(bound, smallest) << "trial " << trial;
    tight += keyDepth(smallest) - keyDepth(bound) < 1e-6f;
  }
  EXPECT_GT(tight, 2900);  // the margin is a few ulps, not a loose bound
}

TEST(NearestKey, NanPlaneBoundStaysBelowItsSamples) {
  // A NaN plane gives the face's farthest corner depth at every sample (DepthPlane's clamp);
  // the bound must not exceed that.
  DepthPlane p;
  p.a = std::nan("");
  p.loBits = int32_t(floatBits(0.25f));
  p.hiBits = int32_t(floatBits(0.75f));
  EXPECT_EQ(p.at(2, p.rowBase(1)), 0.75f);
  EXPECT_LE(nearestKeyOver(p, 5, 0, 0, 3, 3), makeDepthKey(0.75f, 5));
  EXPECT_GE(nearestKeyOver(p, 5, 0, 0, 3, 3), makeDepthKey(0.25f, 5));
}

}  // namespace
}  // namespace zrender
