// The octree of the `octree` algorithm (Octree): every face in exactly one leaf, inside the
// boxes of its nodes, and leaves no larger than asked.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/visibility/Octree.hpp"

namespace zrender {
namespace {

TEST(Octree, EveryFaceOnceAndInsideItsNodes) {
  // Three instances of a random soup, rotated: every face id appears once, every node's box
  // holds its faces' corners, and children split their parent's face range.
  SceneSettings s = test::tinySettings(64);
  s.angle = 30.0;
  s.axis = Vec3(1, 2, 3);
  s.grid = Grid{{3, 1, 1}, Vec3(2.5, 0, 0)};
  Warnings warnings;
  const Scene scene = makeScene(s, test::randomSoup(11, 700, false));
  Octree tree;
  tree.build(scene);
  ASSERT_FALSE(tree.empty());
  std::vector<uint32_t> ids = tree.faces();
  std::sort(ids.begin(), ids.end());
  ASSERT_EQ(ids.size(), size_t(scene.faceCount()));
  for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i);

  const Mesh& mesh = *scene.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  size_t leaves = 0;
  for (const OctreeNode& node : tree.nodes()) {
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const uint32_t id = tree.faces()[i];
      const Mat4 m = scene.modelMatrix(id / nf);
      const Corner* c = mesh.faceCorners(id % nf);
      for (uint32_t j = 0; j < mesh.cornerCount(id % nf); ++j) {
        const Vec3 p = transformPoint(m, mesh.positions[size_t(c[j].position)]);
        for (int a = 0; a < 3; ++a) {
          ASSERT_LE(node.lo[a], p[a]);
          ASSERT_GE(node.hi[a], p[a]);
        }
      }
    }
    if (node.childMask == 0) {
      ++leaves;
      continue;
    }
    uint32_t next = node.faceBegin;
    const int children = __builtin_popcount(node.childMask);
    for (int k = 0; k < children; ++k) {
      const OctreeNode& child = tree.nodes()[node.firstChild + uint32_t(k)];
      EXPECT_EQ(child.faceBegin, next);
      EXPECT_LT(child.faceBegin, child.faceEnd);
      next = child.faceEnd;
    }
    EXPECT_EQ(next, node.faceEnd);
  }
  EXPECT_GT(leaves, 8u);
}

TEST(Octree, LeafSizeBoundsEveryLeaf) {
  // Leaves hold at most the faces asked for; smaller leaves make more of them. 700 random
  // faces have distinct centroids, far from kMaxDepth's cells, so the bound is never waived.
  Warnings warnings;
  const Scene scene = makeScene(test::tinySettings(64), test::randomSoup(12, 700, false));
  auto leafSizes = [&scene](uint32_t leafFaces) {
    Octree tree;
    tree.build(scene, leafFaces);
    std::vector<uint32_t> sizes;
    for (const OctreeNode& node : tree.nodes())
      if (node.childMask == 0) sizes.push_back(node.faceEnd - node.faceBegin);
    return sizes;
  };
  const std::vector<uint32_t> small = leafSizes(8), big = leafSizes(Octree::kLeafFaces);
  EXPECT_LE(*std::max_element(small.begin(), small.end()), 8u);
  EXPECT_GT(*std::max_element(big.begin(), big.end()), 8u);
  EXPECT_GT(small.size(), 4 * big.size());
}

}  // namespace
}  // namespace zrender
