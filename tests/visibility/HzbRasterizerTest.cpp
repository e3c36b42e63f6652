// The triangle stage of `hierarchical` and `octree` (HzbRasterizer): what is behind the
// z-pyramid is rejected without pixel work, ties go to the smaller id, and a big triangle is
// judged by its plane over its sample bounds in the image.

#include <gtest/gtest.h>

#include <cstdint>

#include "support/ScreenGeometry.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"

namespace zrender {
namespace {

using test::makeTriangle;

// A 64 x 48 buffer behind a big occluder at depth 0.5 with id 7 (two triangles).
struct WalledBuffer {
  FrameBuffer fb;
  HzbRasterizer r;
  RenderStats stats;
  WalledBuffer() {
    fb.resize(64, 48);
    r.begin(fb);
    r.drawTriangle(makeTriangle(0, 0, 64, 0, 64, 48, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(0, 0, 64, 48, 0, 48, 7, 0.5), stats);
  }
};

TEST(HzbRasterizer, RejectsWhatIsBehindAndKeepsTies) {
  WalledBuffer w;
  FrameBuffer& fb = w.fb;
  HzbRasterizer& r = w.r;
  RenderStats& stats = w.stats;
  EXPECT_EQ(stats.trianglesRasterized, 2u);
  // Behind: rejected without pixel work.
  const uint64_t tested = stats.pixelsTested;
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 3, 0.75), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  EXPECT_EQ(stats.pixelsTested, tested);
  // Same depth, larger id: loses every tie (rejecting it is allowed, drawing it harmless).
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 9, 0.5), stats);
  const uint64_t culled = stats.trianglesHzbCulled;
  // Same depth, smaller id: wins every tie, so it must be drawn.
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 2, 0.5), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, culled);
  // In front: drawn.
  r.drawTriangle(makeTriangle(40, 10, 60, 10, 60, 40, 11, 0.25), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, culled);
  r.finish();
  EXPECT_EQ(keyFaceId(fb.row(6)[28]), 2u);
  EXPECT_EQ(keyFaceId(fb.row(30)[55]), 11u);
  EXPECT_EQ(keyFaceId(fb.row(40)[10]), 7u);
  // The farthest key left is (0.5, 7): a key at that depth with a larger id is hidden
  // everywhere, one with a smaller id nowhere.
  EXPECT_TRUE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.5f, 8)));
  EXPECT_FALSE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.5f, 6)));
  EXPECT_FALSE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.4f, 99)));
  EXPECT_TRUE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.6f, 0)));
}

TEST(HzbRasterizer, BigTriangleWhoseNearCornerIsOffScreenIsRejectedByItsPlane) {
  // A wall at depth 0.5 over the whole image, then a triangle reaching far to the right of it
  // whose depth falls from 0.98 at x = 10 to 0.2 at x = 400: its nearest corner (0.2) is in
  // front of the wall, but in the image (x < 64) it is behind (depth > 0.87), which only its
  // plane over its sample bounds in the image shows.
  WalledBuffer w;
  FrameBuffer& fb = w.fb;
  HzbRasterizer& r = w.r;
  RenderStats& stats = w.stats;
  ScreenTriangle t = makeTriangle(10, 5, 400, 5, 10, 40, 3, 0.0);
  t.plane.a = -0.002;
  t.plane.c = 1.0;
  t.plane.loBits = int32_t(floatBits(0.19f));
  t.plane.hiBits = int32_t(floatBits(0.99f));
  const uint64_t tested = stats.pixelsTested;
  r.drawTriangle(t, stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  EXPECT_EQ(stats.pixelsTested, tested);
  // Nearer than the wall in the image (0.3 at its left end): drawn.
  t.plane.c = 0.3;
  t.plane.loBits = int32_t(floatBits(0.0f));
  r.drawTriangle(t, stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  r.finish();
  EXPECT_EQ(keyFaceId(fb.row(10)[20]), 3u);
}

}  // namespace
}  // namespace zrender
