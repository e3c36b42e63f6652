// The culling bound (measureCullingBound) and the sources it measures with: KeptTriangles drops
// the triangles it is told to, SkippedBatches passes batches over; the frames they give are
// checked on three squares and the bunny.

#include <gtest/gtest.h>

#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/measure/CullingBound.hpp"
#include "zrender/measure/KeptTriangles.hpp"
#include "zrender/measure/SkippedBatches.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

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

TEST(CullingBound, SkippedBatchesAreNotDrawn) {
  // The measurement's source really passes batches over: the octree skipping every leaf leaves
  // the background, though every leaf is still pulled (and counted).
  const Scene scene = threeSquares();
  const Camera camera = makeCamera(scene);
  size_t pulled = 0;
  Renderer all(scene, std::make_unique<OctreeAlgorithm>(),
               [&pulled](GeometrySource& t, FaceBatches b) {
                 return std::make_unique<SkippedBatches>(
                     t, std::vector<bool>(b.starts->size() - 1, false), pulled);
               });
  all.renderFrame(camera);
  EXPECT_TRUE(showsFace(all.buffer(), 0));
  const size_t leaves = pulled;
  EXPECT_GE(leaves, 1u);
  size_t skippedPulls = 0;
  Renderer none(scene, std::make_unique<OctreeAlgorithm>(), [&](GeometrySource& t, FaceBatches b) {
    return std::make_unique<SkippedBatches>(t, std::vector<bool>(b.starts->size() - 1, true),
                                            skippedPulls);
  });
  none.renderFrame(camera);
  EXPECT_EQ(skippedPulls, leaves);
  for (uint32_t id = 0; id < 3; ++id) EXPECT_FALSE(showsFace(none.buffer(), id));
  EXPECT_TRUE(none.geometry().triangles.empty());
  EXPECT_TRUE(none.geometry().faces.empty());
}

TEST(CullingBound, KeptTrianglesAreAllThatIsDrawn) {
  // Without the front square, the hidden one shows: the source really drops triangles.
  const Scene scene = threeSquares();
  const Camera camera = makeCamera(scene);
  Renderer renderer(scene, "zbuffer");
  renderer.renderFrame(camera);
  EXPECT_TRUE(showsFace(renderer.buffer(), 0));
  EXPECT_FALSE(showsFace(renderer.buffer(), 2));
  Renderer kept(scene, std::make_unique<ZBufferAlgorithm>(), [](GeometrySource& t, FaceBatches) {
    return std::make_unique<KeptTriangles>(t,
                                           [](const ScreenTriangle& tri) { return tri.id != 0; });
  });
  kept.renderFrame(camera);
  EXPECT_FALSE(showsFace(kept.buffer(), 0));
  EXPECT_TRUE(showsFace(kept.buffer(), 2));
  EXPECT_EQ(kept.geometry().triangles.size(), 4u);
}

}  // namespace
}  // namespace zrender
