// The octree's node test (OctreeNodeTest): a node it calls hidden behind the z-pyramid holds
// no visible face, and it keeps a node lying on the occluder or whose edge snaps onto a sample
// the occluder leaves clear.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "support/ScreenGeometry.hpp"
#include "support/TestSupport.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"
#include "zrender/visibility/Octree.hpp"
#include "zrender/visibility/OctreeNodeTest.hpp"

namespace zrender {
namespace {

using test::makeTriangle;
using test::WallPyramid;

TEST(OctreeNodeTest, HiddenNodesHoldNoVisibleFace) {
  // A wall (faces 0, 1) with clusters of small triangles just in front of and just behind it,
  // and more far behind. Against a pyramid of the wall alone, every node the test calls
  // hidden must hold only faces that the z-buffer of the whole scene does not show.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p = {{-2.2, -2.2, 0.0}, {2.2, -2.2, 0.0}, {2.2, 2.2, 0.0}, {-2.2, 2.2, 0.0}};
  std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
  for (int cluster = 0; cluster < 300; ++cluster) {
    const bool far = cluster % 2 == 1;
    const Vec3 c(1.8 * u(rng), 1.8 * u(rng), far ? -4.0 + u(rng) : 0.05 * u(rng));
    for (int i = 0; i < 20; ++i) {
      const int b = int(p.size());
      for (int k = 0; k < 3; ++k) p.push_back(c + Vec3(0.1 * u(rng), 0.1 * u(rng), 0.01 * u(rng)));
      f.push_back({b, b + 1, b + 2});
    }
  }
  SceneSettings s = test::tinySettings(512);
  s.cull = false;
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  const test::Rendered ref = test::render(scene, "zbuffer");
  std::vector<bool> shown(scene.faceCount(), false);
  for (size_t i = 0; i < ref.buffer.size(); ++i)
    if (keyFaceId(ref.buffer.data()[i]) != kBackgroundId)
      shown[keyFaceId(ref.buffer.data()[i])] = true;

  const Camera camera = makeCamera(scene);
  const WallPyramid wall(scene, camera);

  Octree tree;
  tree.build(scene);
  const OctreeNodeTest test(camera, wall.fb.width(), wall.fb.height());
  int hiddenNodes = 0, hiddenFaces = 0;
  for (const OctreeNode& node : tree.nodes()) {
    if (!test.hidden(node, wall.r.pyramid())) continue;
    ++hiddenNodes;
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      ASSERT_FALSE(shown[tree.faces()[i]]) << "face " << tree.faces()[i] << " is visible";
      ++hiddenFaces;
    }
  }
  EXPECT_GT(hiddenNodes, 0);
  EXPECT_GT(hiddenFaces, 1000);
}

TEST(OctreeNodeTest, NodeOnTheOccluderIsNotHidden) {
  // The node test allows for rounding by lowering the box's nearest depth; lowering it, not
  // raising it, is what keeps it exact. A wall at z = 0 (faces 0, 1, 4 x 4 units) fills a
  // 64 x 64 pyramid; flat boxes 1 x 1 at z = 0 (on the wall: a face there ties with it, so must
  // be kept), at z = 1e-5 (in front) and at z = -0.01 (behind) are tested.
  SceneSettings s = test::tinySettings(64);
  Warnings warnings;
  const Scene scene = makeScene(
      s, test::makeMesh({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, {{0, 1, 2}, {0, 2, 3}}));
  const Camera camera = makeCamera(scene);
  const WallPyramid wall(scene, camera);
  const OctreeNodeTest test(camera, wall.fb.width(), wall.fb.height());
  const auto flatNode = [](float z) {
    OctreeNode node{};
    for (int a = 0; a < 2; ++a) node.lo[a] = -0.5f, node.hi[a] = 0.5f;
    node.lo[2] = node.hi[2] = z;
    return node;
  };
  EXPECT_FALSE(test.hidden(flatNode(0.0f), wall.r.pyramid()));
  EXPECT_FALSE(test.hidden(flatNode(1e-5f), wall.r.pyramid()));
  EXPECT_TRUE(test.hidden(flatNode(-0.01f), wall.r.pyramid()));
}

TEST(OctreeNodeTest, NodeWhoseEdgeSnapsOntoAClearSampleIsNotHidden) {
  // A flat box at z = -0.5 (2.5 units from the eye of a 64 x 64 tiny scene, window x =
  // (X / 2.5 + 1) * 32) whose left side projects to window x = 15.5 + 1.3e-6: a face with a
  // corner there snaps to x = 15.5 (1/256 sample grid) and, as a left edge, covers the centre
  // of sample column 15, the last of the first column of 16 x 16 pyramid tiles. An occluder
  // at depth 0.5 covers every sample but that column, so the node must be kept; with the
  // column covered too, it is hidden.
  SceneSettings s = test::tinySettings(64);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  const Camera camera = makeCamera(scene);
  OctreeNode node{};
  node.lo[0] = float((15.5 / 32.0 - 1.0) * 2.5 + 1e-7);
  node.hi[0] = 0.5f;
  node.lo[1] = -0.5f, node.hi[1] = 0.5f;
  node.lo[2] = node.hi[2] = -0.5f;
  const auto hiddenBehind = [&](bool coverColumn15) {
    FrameBuffer fb;
    fb.resize(64, 64);
    HzbRasterizer r;
    r.begin(fb);
    RenderStats stats;
    // Samples 0..14 (centres up to 14.5 < 15), and 16..63 (centres from 16.5 > 16) or 15..63.
    const double right = coverColumn15 ? 15 : 16;
    r.drawTriangle(makeTriangle(0, 0, 15, 0, 15, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(0, 0, 15, 64, 0, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(right, 0, 64, 0, 64, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(right, 0, 64, 64, right, 64, 7, 0.5), stats);
    EXPECT_EQ(keyFaceId(fb.row(30)[15]) == 7, coverColumn15);
    EXPECT_EQ(keyFaceId(fb.row(30)[14]), 7u);
    EXPECT_EQ(keyFaceId(fb.row(30)[16]), 7u);
    return OctreeNodeTest(camera, 64, 64).hidden(node, r.pyramid());
  };
  EXPECT_FALSE(hiddenBehind(false));
  EXPECT_TRUE(hiddenBehind(true));
}

}  // namespace
}  // namespace zrender
