// The depth rule (docs/design.md, Rasterization rules): the nearer key wins, ties go to the
// smaller face id whatever the order, keys order by depth then id, and depths are clamped to the
// range of the face's corners; checked on the z-buffer with geometry built by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/CoverageOracle.hpp"
#include "support/TestSupport.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/transform/FaceTransformer.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

namespace zrender {
namespace {

using test::oriented;

// A FrameGeometry made directly of triangles (no camera), each its own face.
FrameGeometry geometryOf(const std::vector<std::array<FixedPoint, 3>>& tris,
                         const std::vector<DepthPlane>& planes, const std::vector<uint32_t>& ids,
                         int size) {
  FrameGeometry g;
  g.width = g.height = size;
  for (size_t i = 0; i < tris.size(); ++i) {
    const auto t = oriented(tris[i][0], tris[i][1], tris[i][2]);
    ScreenFace f{};
    f.id = ids[i];
    f.firstVertex = uint32_t(g.vertices.size());
    f.vertexCount = 3;
    f.firstTriangle = uint32_t(g.triangles.size());
    f.triangleCount = 1;
    f.frontFacing = true;
    f.rows =
        faceRowSpan(std::min({t[0].y, t[1].y, t[2].y}), std::max({t[0].y, t[1].y, t[2].y}), size);
    g.vertices.insert(g.vertices.end(), t.begin(), t.end());
    g.triangles.push_back(
        ScreenTriangle{{t[0], t[1], t[2]}, uint32_t(g.faces.size()), ids[i], planes[i]});
    g.faces.push_back(f);
  }
  return g;
}

FrameBuffer runZBuffer(FrameGeometry& g) {
  // The z-buffer reads only the geometry; scene, camera and transformer are not touched.
  auto mesh = test::makeMesh({{0, 0, 0}}, {{0}});
  Warnings w;
  const Scene scene = makeScene(test::tinySettings(g.width), mesh);
  const Camera camera = makeCamera(scene);
  test::GivenGeometry given;
  FrameInput input{scene, camera, given, g};
  FrameBuffer fb;
  fb.resize(g.width, g.height);
  RenderStats stats;
  ZBufferAlgorithm().render(input, fb, stats);
  return fb;
}

TEST(DepthRule, InterpenetratingTrianglesSplitAlongTheirIntersection) {
  // Two triangles covering the same square; depth 0.5 + 0.01 (x - 8) and 0.5 - 0.01 (x - 8):
  // they cross at x = 8, so face 1 is nearer left of it and face 0 right of it.
  const FixedPoint p0{0, 0}, p1{16 * kSubpixel, 0}, p2{0, 16 * kSubpixel};
  const DepthPlane rising{0.01, 0.0, 0.42}, falling{-0.01, 0.0, 0.58};
  FrameGeometry g = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {rising, falling}, {0, 1}, 16);
  const FrameBuffer fb = runZBuffer(g);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const DepthKey k = fb.row(y)[x];
      if (x + y >= 15) {  // outside the triangle (the hypotenuse is not a left edge)
        EXPECT_EQ(k, kClearKey) << x << "," << y;
        continue;
      }
      // Sample centre x + 0.5 < 8 -> falling (id 1) is farther... depth(rising) smaller
      // left of 8: rising = 0.5 + 0.01 (x + 0.5 - 8) < 0.5 there, so id 0 wins on the left.
      const uint32_t expected = x + 0.5 < 8 ? 0u : 1u;
      EXPECT_EQ(keyFaceId(k), expected) << x << "," << y;
    }
  }
}

TEST(DepthRule, CoplanarDuplicatesGoToTheSmallerIdWhateverTheOrder) {
  const FixedPoint p0{100, 50}, p1{3000, 700}, p2{900, 3900};
  const DepthPlane plane{0.001, 0.002, 0.3};
  FrameGeometry forward = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {plane, plane}, {5, 9}, 16);
  FrameGeometry backward = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {plane, plane}, {9, 5}, 16);
  const FrameBuffer a = runZBuffer(forward), b = runZBuffer(backward);
  EXPECT_EQ(test::countDifferences(a, b), 0u);
  size_t covered = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a.data()[i] == kClearKey) continue;
    ++covered;
    EXPECT_EQ(keyFaceId(a.data()[i]), 5u);
  }
  EXPECT_GT(covered, 50u);
}

TEST(DepthRule, ReversedSubmissionGivesTheSameBuffers) {
  // A random soup through the whole pipeline, then the same triangles submitted backwards.
  auto mesh = test::randomSoup(42, 300, true);
  SceneSettings s = test::tinySettings(96);
  s.cull = false;
  Warnings w;
  const Scene scene = makeScene(s, mesh);
  const Camera camera = makeCamera(scene);
  FaceTransformer transformer(scene, camera, 1, false);
  FrameGeometry g;
  transformer.pull(FaceRequest::frame(), g);
  FrameGeometry reversed = g;
  std::reverse(reversed.triangles.begin(), reversed.triangles.end());
  const FrameBuffer a = runZBuffer(g), b = runZBuffer(reversed);
  EXPECT_EQ(test::countDifferences(a, b), 0u);
  size_t faces = 0;
  std::vector<bool> seen(300, false);
  for (size_t i = 0; i < a.size(); ++i)
    if (keyFaceId(a.data()[i]) != kBackgroundId && !seen[keyFaceId(a.data()[i])])
      seen[keyFaceId(a.data()[i])] = true, ++faces;
  EXPECT_GT(faces, 50u);  // a real mix of visible faces
}

TEST(DepthRule, FloatStepsMatchNextafter) {
  // Every sign, zeros, denormals, 1, infinities and random bit patterns of finite floats.
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,
                               -0.0f,
                               1.0f,
                               -1.0f,
                               inf,
                               -inf,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               -std::numeric_limits<float>::max(),
                               std::nextafter(1.0f, 0.0f),
                               0.5f,
                               1e-30f,
                               -1e-30f};
  std::mt19937 rng(3);
  for (int i = 0; i < 100000; ++i) {
    const float f = bitsToFloat(uint32_t(rng()));
    if (!std::isnan(f)) values.push_back(f);
  }
  for (float f : values) {
    if (f >= 0.0f) {
      EXPECT_EQ(floatBits(nextFloatTowardZero(f)), floatBits(std::nextafter(f, 0.0f))) << f;
    }
    if (f <= 1.0f) {
      EXPECT_EQ(floatBits(nextFloatTowardOne(f)), floatBits(std::nextafter(f, 1.0f))) << f;
    }
  }
}

TEST(DepthRule, KeyOrdersByDepthThenId) {
  EXPECT_LT(makeDepthKey(0.25f, 900), makeDepthKey(0.5f, 1));
  EXPECT_LT(makeDepthKey(0.5f, 1), makeDepthKey(0.5f, 2));
  EXPECT_LT(makeDepthKey(0.0f, 7), makeDepthKey(std::nextafter(0.0f, 1.0f), 0));
  EXPECT_LT(makeDepthKey(1.0f, 3), kClearKey);  // a face on the far plane beats the background
  EXPECT_EQ(keyDepth(makeDepthKey(0.375f, 12)), 0.375f);
  EXPECT_EQ(keyFaceId(makeDepthKey(0.375f, 12)), 12u);
}

TEST(DepthRule, DepthIsClampedToTheFaceCornerRange) {
  DepthPlane p{0.1, 0.0, 0.0};
  p.loBits = int32_t(floatBits(0.25f));
  p.hiBits = int32_t(floatBits(0.5f));
  EXPECT_EQ(p.at(0, p.rowBase(0)), 0.25f);  // 0.05 raised to the nearest corner
  EXPECT_EQ(p.at(3, p.rowBase(0)), 0.35f);  // inside the range: the plane itself
  EXPECT_EQ(p.at(9, p.rowBase(0)), 0.5f);   // 0.95 lowered to the farthest corner
  DepthPlane negativeZero{0.0, 0.0, -0.0};
  EXPECT_EQ(floatBits(negativeZero.at(0, -0.0)), 0u);  // -0.0 becomes +0.0
}

TEST(DepthRule, TransformSetsTheRangeFromTheCornerDepths) {
  // A triangle from z = 0 to z = 1 seen from z = 2: corner depths at view distances 2 and 1.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 1}}, {{0, 1, 2}});
  Warnings w;
  const Scene scene = makeScene(test::tinySettings(16), mesh);
  const Camera camera = makeCamera(scene);
  FaceTransformer transformer(scene, camera, 1, true);
  FrameGeometry g;
  transformer.pull(FaceRequest::frame(), g);
  ASSERT_EQ(g.faces.size(), 1u);
  const double n = 0.1, f = 10.0;
  auto windowDepth = [&](double d) {
    return 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)) + 0.5;
  };
  const DepthPlane& p = g.triangles[g.faces[0].firstTriangle].plane;
  EXPECT_LE(double(p.minDepth()), windowDepth(1.0));
  EXPECT_NEAR(p.minDepth(), windowDepth(1.0), 1e-7);
  EXPECT_GE(double(p.maxDepth()), windowDepth(2.0));
  EXPECT_NEAR(p.maxDepth(), windowDepth(2.0), 1e-7);
}

}  // namespace
}  // namespace zrender
