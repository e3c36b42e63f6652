// What the z-pyramid rejects in `hierarchical` (and, where said, `octree`) never changes the
// frame: occluders, slivers behind them, interleaved clusters, coplanar ties and instances
// nearest first, each checked against the z-buffer bit for bit, and the rejections counted so
// that the test is known to reach them.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "support/AlgorithmAgreement.hpp"
#include "support/TestMeshes.hpp"
#include "support/TestSupport.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {
namespace {

using test::addTessellatedSquare;
using test::Compared;
using test::expectSameAsZBuffer;

TEST(HierarchicalAlgorithm, BigOccluderIsRejectedByThePyramid) {
  // A near quad (faces 0, 1: first in id order) hides a far grid of small quads.
  std::vector<Vec3> p = {{-1.9, -1.9, 0.5}, {1.9, -1.9, 0.5}, {1.9, 1.9, 0.5}, {-1.9, 1.9, 0.5}};
  std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
  const int n = 20;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(-1.5 + 3.0 * i / n, -1.5 + 3.0 * j / n, -1.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = 4 + j * (n + 1) + i;
      f.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  SceneSettings s = test::tinySettings(128);
  const Compared c =
      expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms, "occluder");
  for (size_t k = 0; k < test::kPyramidAlgorithms.size(); ++k) {
    SCOPED_TRACE(test::kPyramidAlgorithms[k]);
    EXPECT_GT(c.stats[k].trianglesHzbCulled + c.stats[k].octreeNodesCulled, 0u);
  }
  EXPECT_GE(c.stats[0].trianglesHzbCulled, 2u * n * n - 40u);  // hierarchical: nearly all
}

TEST(HierarchicalAlgorithm, SliversBehindAnOccluder) {
  // Thousands of thin, randomly tilted slivers (some nearly edge-on, whose depth planes are
  // extrapolated steeply at snapped samples) behind a quad that hides them, from just behind
  // it to far enough that the octree rejects their nodes: neither the pyramid's bounds nor
  // the octree's node margin may lose a sample the z-buffer draws.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  uint64_t nodesCulled = 0, trianglesCulled = 0;
  for (double gap : {1e-4, 1e-2, 1.0, 4.0}) {
    std::vector<Vec3> p = {{-1.6, -1.6, 1.2}, {1.6, -1.6, 1.2}, {1.6, 1.6, 1.2}, {-1.6, 1.6, 1.2}};
    std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
    for (int i = 0; i < 3000; ++i) {
      const double z = 1.2 - gap - 0.01 * (u(rng) + 1.0);
      const double spread = 0.3 * (2.0 - z);  // stay inside the quad's shadow
      const Vec3 c(spread * u(rng), spread * u(rng), z);
      Vec3 along(u(rng), u(rng), u(rng)), across(u(rng), u(rng), u(rng));
      along *= 0.06 / cv::norm(along);
      across = along.cross(across);
      across *= 1e-4 / std::max(cv::norm(across), 1e-12);
      const int b = int(p.size());
      p.insert(p.end(), {c - along, c + along + across, c + along - across});
      f.push_back({b, b + 1, b + 2});
    }
    SceneSettings s = test::tinySettings(300);
    s.cull = false;
    s.near = 0.5;
    s.msaa = gap < 1e-3 ? 4 : 1;
    const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms,
                                           "gap " + std::to_string(gap));
    trianglesCulled += c.stats[0].trianglesHzbCulled;
    nodesCulled += c.stats[1].octreeNodesCulled;
  }
  EXPECT_GT(trianglesCulled, 5000u);
  EXPECT_GT(nodesCulled, 0u);
}

TEST(HierarchicalAlgorithm, DenseInterleavedClusters) {
  // Hundreds of small clusters of triangles at nearby depths, partly in front of each other:
  // octree nodes are tested against a pyramid built from geometry just in front of them, so
  // a node test that is not conservative by even a small depth loses visible faces here.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  for (int cluster = 0; cluster < 500; ++cluster) {
    const Vec3 c(1.4 * u(rng), 1.4 * u(rng), 0.4 * u(rng));
    for (int i = 0; i < 24; ++i) {
      const int b = int(p.size());
      for (int k = 0; k < 3; ++k)
        p.push_back(c + Vec3(0.12 * u(rng), 0.12 * u(rng), 0.02 * u(rng)));
      f.push_back({b, b + 1, b + 2});
    }
  }
  SceneSettings s = test::tinySettings(320);
  s.cull = false;
  const Compared c =
      expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms, "clusters");
  EXPECT_GT(c.stats[0].trianglesHzbCulled, 30u);
}

TEST(HierarchicalAlgorithm, CoplanarTiesWithSmallerIdBehind) {
  // Two identical coplanar quads; the one drawn first has the larger id, so at equal depth
  // the later, smaller id must still be drawn (and win every sample).
  std::vector<Vec3> p = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  // Face 0 and 1 are the same quad; faces 2.. repeat it so many ids tie.
  std::vector<std::vector<int>> f = {{0, 1, 2, 3}, {0, 1, 2, 3}, {1, 2, 3, 0}, {2, 3, 0, 1}};
  SceneSettings s = test::tinySettings(64);
  const Compared c =
      expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms, "coplanar");
  EXPECT_GT(c.covered, 500u);
  const test::Rendered r = test::render(test::makeMesh(p, f), s, "hierarchical");
  EXPECT_EQ(keyFaceId(r.buffer.row(32)[32]), 0u);
}

TEST(HierarchicalAlgorithm, NearestInstanceFirstHidesTheOthersBeforeTheirSetUp) {
  // A tessellated square (200 triangles) in a row of four instances along z, numbered far to
  // near as the eye sees them: the nearest is drawn first, and every triangle of the three
  // behind it is proved hidden (most already in the transform, without set-up).
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(10, false, 0.0, p, f);
  SceneSettings s = test::tinySettings(128);
  s.grid = Grid{{1, 1, 4}, {0.0, 0.0, 0.5}};  // z = -0.75, -0.25, 0.25, 0.75
  // The last instance is the nearest and covers two thirds of the image, all of the tiles the
  // others reach.
  s.eye = Vec3(0.0, 0.0, 1.5);
  s.target = Vec3(0.0, 0.0, 0.0);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  const Compared c = expectSameAsZBuffer(scene, test::kPyramidAlgorithms, "row of squares");
  const RenderStats& h = c.stats[0];
  EXPECT_GT(c.covered, 4000u);
  EXPECT_EQ(h.trianglesRasterized, 200u);
  EXPECT_EQ(h.trianglesHzbCulled, 600u);
  // Those of the instances behind never reached the frame's geometry.
  Renderer renderer(scene, "hierarchical");
  renderer.renderFrame(makeCamera(scene));
  EXPECT_EQ(renderer.geometry().triangles.size(), 200u);
}

}  // namespace
}  // namespace zrender
