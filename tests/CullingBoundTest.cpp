#include <gtest/gtest.h>

#include <vector>

#include "TestSupport.hpp"
#include "zrender/measure/CullingBound.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"

namespace zrender {
namespace {

// Three squares facing the eye: A (face 0) in front, B (face 1) larger at the back, and C
// (face 2) between them, small enough to be wholly behind A.
Scene threeSquares() {
  auto square = [](double half, double z, std::vector<Vec3>& p, std::vector<std::vector<int>>& f) {
    const int first = int(p.size());
    for (const auto& [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      p.push_back(Vec3(x * half, y * half, z));
    f.push_back({first, first + 1, first + 2, first + 3});
  };
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  square(0.5, 0.5, p, f);
  square(1.0, 0.0, p, f);
  square(0.25, 0.25, p, f);
  Warnings warnings;
  return makeScene(test::tinySettings(32), test::makeMesh(p, f));
}

bool showsFace(const FrameBuffer& fb, uint32_t face) {
  for (size_t i = 0; i < fb.size(); ++i)
    if (keyFaceId(fb.data()[i]) == face) return true;
  return false;
}

TEST(CullingBound, KeepsOnlyTheVisibleFacesAndTheSameBuffers) {
  const Scene scene = threeSquares();
  const CullingBound b = measureCullingBound(scene, makeCamera(scene), 3);
  EXPECT_EQ(b.triangles, 6u);  // two per square
  EXPECT_EQ(b.visibleFaces, 2u);
  EXPECT_EQ(b.visibleTriangles, 4u);
  EXPECT_TRUE(b.identical);
  EXPECT_GT(b.rasterMs, 0.0);
  EXPECT_GT(b.visibleRasterMs, 0.0);
  // Three faces make one octree leaf, which shows two of them.
  EXPECT_EQ(b.octreeLeavesDrawn, 1u);
  EXPECT_EQ(b.visibleLeaves, 1u);
  EXPECT_TRUE(b.leafBoundIdentical);
  EXPECT_GT(b.octreeFrameMs, 0.0);
  EXPECT_GT(b.leafBoundFrameMs, 0.0);
}

TEST(CullingBound, OctreesOfTheLeafSizeAsked) {
  // Leaves of one face: A and B each fill a leaf that shows, C's shows nothing.
  const Scene scene = threeSquares();
  const CullingBound b = measureCullingBound(scene, makeCamera(scene), 1, 1);
  EXPECT_EQ(b.visibleFaces, 2u);
  EXPECT_EQ(b.visibleLeaves, 2u);
  EXPECT_GE(b.octreeLeavesDrawn, 2u);
  EXPECT_TRUE(b.leafBoundIdentical);
}

TEST(CullingBound, OnTheBunnyPerfectLeafCullingDrawsFewerLeavesAndTheSameBuffers) {
  auto mesh = test::referenceModel("bunny");
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  SceneSettings settings = test::projectScene("bunny");
  settings.width = settings.height = 160;
  Warnings warnings;
  const Scene scene = makeScene(settings, mesh);
  const CullingBound b = measureCullingBound(scene, makeCamera(scene), 1);
  EXPECT_TRUE(b.identical);
  EXPECT_TRUE(b.leafBoundIdentical);
  // The bunny's back half is leaves of back faces and hidden faces.
  EXPECT_GT(b.visibleLeaves, 100u);
  EXPECT_LT(b.visibleLeaves, b.octreeLeavesDrawn);
}

TEST(CullingBound, SkippedLeavesAreNotDrawn) {
  // The octree's measurement hook really passes leaves over: skipping every leaf leaves the
  // background, counted as culled nodes.
  const Scene scene = threeSquares();
  const Camera camera = makeCamera(scene);
  Renderer renderer(scene, "octree");
  renderer.renderFrame(camera);
  EXPECT_TRUE(showsFace(renderer.buffer(), 0));
  EXPECT_EQ(renderer.stats().octreeNodesCulled, 0u);
  uint32_t asked = 0;
  dynamic_cast<OctreeAlgorithm&>(renderer.algorithm())
      .skipLeaves([&asked](const uint32_t*, uint32_t count) {
        asked += count;
        return true;
      });
  renderer.renderFrame(camera);
  EXPECT_EQ(asked, 3u);  // every face, once
  EXPECT_FALSE(showsFace(renderer.buffer(), 0));
  EXPECT_FALSE(showsFace(renderer.buffer(), 1));
  EXPECT_EQ(renderer.stats().octreeNodesCulled, 1u);
  EXPECT_TRUE(renderer.geometry().triangles.empty());
}

TEST(CullingBound, KeptTrianglesAreAllThatIsDrawn) {
  // Without the front square, the hidden one shows: the filter really drops triangles.
  const Scene scene = threeSquares();
  const Camera camera = makeCamera(scene);
  Renderer renderer(scene, "zbuffer");
  renderer.renderFrame(camera);
  EXPECT_TRUE(showsFace(renderer.buffer(), 0));
  EXPECT_FALSE(showsFace(renderer.buffer(), 2));
  renderer.keepTriangles([](const ScreenTriangle& t) { return t.id != 0; });
  renderer.renderFrame(camera);
  EXPECT_FALSE(showsFace(renderer.buffer(), 0));
  EXPECT_TRUE(showsFace(renderer.buffer(), 2));
  EXPECT_EQ(renderer.geometry().triangles.size(), 4u);
}

}  // namespace
}  // namespace zrender
