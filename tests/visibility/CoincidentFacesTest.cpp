// Faces that repeat: a copy of a face with a larger id loses every sample to the original by
// the tie-break. The hierarchical algorithms reject such copies exactly (CoincidentTriangles),
// and use the smallest id they know in their bound keys (octree nodes, grid instances).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "support/ScreenGeometry.hpp"
#include "support/TestSupport.hpp"
#include "zrender/visibility/Octree.hpp"
#include "zrender/visibility/OctreeNodeTest.hpp"

namespace zrender {
namespace {

TEST(CoincidentFaces, TwoHundredThousandCopiesOfOneTriangle) {
  // The model: v 0 0 0, v 1 0 0, v 0 1 0 and `f 1 2 3` listed 200,000 times, framed by
  // fit at 512 x 512. Face 0 takes every sample; the hierarchical algorithms draw it alone and
  // reject the other 199,999 before any pixel work.
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  constexpr uint32_t kCopies = 50000;  // the same paths at a quarter of the cost
#else
  constexpr uint32_t kCopies = 200000;
#endif
  const auto mesh = test::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                   std::vector<std::vector<int>>(kCopies, {0, 1, 2}));
  SceneSettings s = test::tinySettings(512);
  s.fit = true;
  s.shading = ShadingMode::Id;
  Warnings warnings;
  const Scene scene = makeScene(s, mesh);
  const test::Rendered ref = test::render(scene, "zbuffer");
  EXPECT_EQ(ref.stats.trianglesRasterized, kCopies);
  // Fit: the sphere (radius sqrt(1/2)) plus 5% fills the 90-degree view, whose height at the
  // sphere's centre is then 2 x 1.05 sqrt(1/2) / sin 45 = 2.1 units: the triangle's half unit
  // of area covers 0.5 / 2.1^2 of the 512 x 512 samples.
  EXPECT_NEAR(double(test::coveredSamples(ref.buffer)), 0.5 / (2.1 * 2.1) * 512 * 512, 300.0);
  for (size_t i = 0; i < ref.buffer.size(); ++i) {
    const DepthKey k = ref.buffer.data()[i];
    ASSERT_TRUE(k == kClearKey || keyFaceId(k) == 0) << "sample " << i;
  }
  for (const std::string alg : {"hierarchical", "octree"}) {
    const test::Rendered r = test::render(scene, alg);
    test::expectSameFrame(ref, r, alg);
    EXPECT_EQ(r.stats.trianglesRasterized, 1u) << alg;
    EXPECT_EQ(r.stats.trianglesHzbCulled, kCopies - 1) << alg;
    EXPECT_EQ(r.stats.pixelsTested * kCopies, ref.stats.pixelsTested) << alg;
  }
}

TEST(CoincidentFaces, AMeshListedTwiceDrawsOnlyItsFirstCopyIdenticallyToTheZBuffer) {
  // Big random triangles (each at least 32 samples across) that cross one another, then the
  // same list again. Every algorithm agrees; the hierarchical ones rasterize exactly the
  // triangles they rasterize for the mesh listed once, since a copy never wins a sample and so
  // never changes what the pyramid holds when an original is tested.
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.5, 1.0), depth(-0.5, 0.5);
  std::vector<Vec3> p;
  std::vector<std::vector<int>> once;
  for (int i = 0; i < 150; ++i) {
    const Vec3 c(1.2 * u(rng), 1.2 * u(rng), 0.0);
    const double r = radius(rng), turn = u(rng) * CV_PI;
    for (int k = 0; k < 3; ++k) {
      const double angle = turn + k * 2.0 * CV_PI / 3.0;
      p.push_back(c + Vec3(r * std::cos(angle), r * std::sin(angle), depth(rng)));
    }
    once.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  std::vector<std::vector<int>> twice = once;
  twice.insert(twice.end(), once.begin(), once.end());
  SceneSettings s = test::tinySettings(256);
  s.cull = false;
  Warnings warnings;
  const Scene single = makeScene(s, test::makeMesh(p, once));
  const Scene doubled = makeScene(s, test::makeMesh(p, twice));
  const test::Rendered ref = test::render(doubled, "zbuffer");
  EXPECT_EQ(test::countDifferences(ref.buffer, test::render(single, "zbuffer").buffer), 0u);
  for (const std::string alg : {"scanline", "interval", "hierarchical", "octree"}) {
    const test::Rendered r = test::render(doubled, alg);
    test::expectSameFrame(ref, r, alg);
    if (alg == "hierarchical" || alg == "octree") {
      EXPECT_EQ(r.stats.trianglesRasterized, test::render(single, alg).stats.trianglesRasterized)
          << alg;
      EXPECT_GE(r.stats.trianglesHzbCulled, once.size()) << alg;
    }
  }
}

TEST(CoincidentFaces, OctreeNodesKnowTheirSmallestFaceId) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  for (int i = 0; i < 3000; ++i) {
    for (int k = 0; k < 3; ++k) p.push_back(Vec3(u(rng), u(rng), u(rng)));
    f.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  SceneSettings s = test::tinySettings(64);
  s.grid = Grid{{2, 1, 2}, {3.0, 0.0, 3.0}};
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  Octree tree;
  tree.build(scene, 64);
  ASSERT_GT(tree.nodes().size(), 20u);
  for (const OctreeNode& node : tree.nodes()) {
    uint32_t smallest = UINT32_MAX;
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i)
      smallest = std::min(smallest, tree.faces()[i]);
    EXPECT_EQ(node.minFace, smallest);
  }
}

TEST(CoincidentFaces, TheOctreeNodeTestBreaksADepthTieByTheNodesSmallestId) {
  // A wall at z = 0 (faces 0 and 1) fills a 64 x 64 pyramid at one window depth, keys of ids 0
  // and 1. A flat box just behind it, moved back a step at a time: where the box's lowered
  // nearest depth equals the wall's, a node whose faces all have ids above 1 is hidden and one
  // holding face 0 is not; nowhere is the second hidden without the first.
  SceneSettings s = test::tinySettings(64);
  Warnings warnings;
  const Scene scene = makeScene(
      s, test::makeMesh({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, {{0, 1, 2}, {0, 2, 3}}));
  const Camera camera = makeCamera(scene);
  const test::WallPyramid wall(scene, camera);
  const OctreeNodeTest test(camera, wall.fb.width(), wall.fb.height());
  int tiesBrokenById = 0;
  for (int step = 0; step < 4000; ++step) {
    OctreeNode node{};
    for (int a = 0; a < 2; ++a) node.lo[a] = -0.5f, node.hi[a] = 0.5f;
    node.lo[2] = node.hi[2] = -float(step) * 1e-7f;  // window depth: about 1/24 ulp a step
    node.minFace = 2;
    const bool hiddenWithLargerIds = test.hidden(node, wall.r.pyramid());
    node.minFace = 0;
    const bool hiddenWithFaceZero = test.hidden(node, wall.r.pyramid());
    EXPECT_TRUE(hiddenWithLargerIds || !hiddenWithFaceZero) << step;
    tiesBrokenById += hiddenWithLargerIds && !hiddenWithFaceZero;
  }
  EXPECT_GT(tiesBrokenById, 0);
}

}  // namespace
}  // namespace zrender
