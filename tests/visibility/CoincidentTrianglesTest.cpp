// The table of triangles seen in a frame (CoincidentTriangles): an exact copy of a triangle
// seen with a smaller id is hidden by it; any difference in coverage or depth is not a copy.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/visibility/CoincidentTriangles.hpp"

namespace zrender {
namespace {

ScreenTriangle triangle(uint32_t id) {
  ScreenTriangle t{};
  t.v[0] = {0, 0};
  t.v[1] = {40 * kSubpixel, 0};
  t.v[2] = {0, 30 * kSubpixel};
  t.id = id;
  t.plane.a = 1e-3, t.plane.b = -2e-3, t.plane.c = 0.5;
  t.plane.loBits = int32_t(floatBits(0.45f)), t.plane.hiBits = int32_t(floatBits(0.55f));
  return t;
}

TEST(CoincidentTriangles, ACopyLosesToTheSmallestIdSeenWhateverTheOrder) {
  CoincidentTriangles seen;
  EXPECT_FALSE(seen.hiddenByEarlier(triangle(7)));
  EXPECT_TRUE(seen.hiddenByEarlier(triangle(9)));   // 7 wins every tie
  EXPECT_FALSE(seen.hiddenByEarlier(triangle(3)));  // wins against 7: drawn
  EXPECT_TRUE(seen.hiddenByEarlier(triangle(5)));   // now loses to 3
  EXPECT_FALSE(seen.hiddenByEarlier(triangle(3)));  // the same face again (a polygon's piece)
  seen.clear();                                     // a new frame
  EXPECT_FALSE(seen.hiddenByEarlier(triangle(9)));
}

TEST(CoincidentTriangles, AnyDifferenceInCoverageOrDepthIsNotACopy) {
  // One step of the 1/256 grid on any corner coordinate, or one bit of any plane value: the
  // samples or their depths may differ, so the later triangle must be drawn.
  std::vector<ScreenTriangle> variants;
  for (int corner = 0; corner < 3; ++corner) {
    ScreenTriangle t = triangle(8);
    ++t.v[corner].x;
    variants.push_back(t);
    t = triangle(8);
    --t.v[corner].y;
    variants.push_back(t);
  }
  for (double DepthPlane::*value : {&DepthPlane::a, &DepthPlane::b, &DepthPlane::c}) {
    ScreenTriangle t = triangle(8);
    t.plane.*value = std::nextafter(t.plane.*value, 1.0);
    variants.push_back(t);
  }
  ScreenTriangle lo = triangle(8), hi = triangle(8);
  --lo.plane.loBits, ++hi.plane.hiBits;
  variants.push_back(lo);
  variants.push_back(hi);
  for (size_t i = 0; i < variants.size(); ++i) {
    CoincidentTriangles seen;
    EXPECT_FALSE(seen.hiddenByEarlier(triangle(1)));
    EXPECT_FALSE(seen.hiddenByEarlier(variants[i])) << "variant " << i;
    EXPECT_TRUE(seen.hiddenByEarlier(triangle(2))) << "variant " << i;
  }
}

TEST(CoincidentTriangles, KeepsEveryTriangleAsTheTableGrows) {
  CoincidentTriangles seen;
  constexpr int kCount = 5000;
  for (int i = 0; i < kCount; ++i) {
    ScreenTriangle t = triangle(uint32_t(i));
    t.v[1].x += i;
    ASSERT_FALSE(seen.hiddenByEarlier(t)) << i;
  }
  for (int i = 0; i < kCount; ++i) {
    ScreenTriangle t = triangle(uint32_t(kCount + i));
    t.v[1].x += i;
    EXPECT_TRUE(seen.hiddenByEarlier(t)) << i;
  }
}

}  // namespace
}  // namespace zrender
