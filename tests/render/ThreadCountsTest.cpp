// Every thread count gives the buffers of one thread (docs/design.md, Threads): color, depth
// and id of every algorithm with 2, 3 and 7 threads equal those with 1, on the reference
// models, polygons, grids, random soups, every shading mode and MSAA 4.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "support/TestSupport.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/ShadingMode.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

test::Rendered renderWith(const Scene& scene, const std::string& algorithm, int threads) {
  Renderer renderer(scene, algorithm, threads);
  renderer.renderFrame(makeCamera(scene));
  // A second frame too: what a renderer keeps from frame to frame must not change it.
  renderer.renderFrame(makeCamera(scene));
  return test::Rendered{renderer.buffer(), renderer.color().clone(), renderer.stats()};
}

// Every algorithm with `threadCounts` threads against itself with one.
void expectSameForEveryThreadCount(const Scene& scene, const std::string& label,
                                   std::initializer_list<int> threadCounts = {2, 3, 7}) {
  for (const std::string& algorithm : algorithmNames()) {
    const test::Rendered one = renderWith(scene, algorithm, 1);
    for (int threads : threadCounts)
      test::expectSameFrame(one, renderWith(scene, algorithm, threads),
                            label + ", " + algorithm + ", " + std::to_string(threads) + " threads");
  }
}

// The project's scene `name` at `size` pixels, or null when its model is not linked.
std::unique_ptr<Scene> projectScene(const std::string& name, int size,
                                    void (*adjust)(SceneSettings&) = nullptr) {
  SceneSettings s = test::projectScene(name);
  if (!std::filesystem::exists(s.modelPath)) return nullptr;
  s.width = s.height = size;
  if (adjust) adjust(s);
  Warnings warnings;
  return std::make_unique<Scene>(loadScene(s, warnings));
}

TEST(ThreadCounts, ReferenceModelsAndShapes) {
  for (const std::string name : {"bunny", "spot", "teapot", "shapes"}) {
    const auto scene = projectScene(name, 200);
    if (!scene) GTEST_SKIP() << name << " is not linked under models/";
    expectSameForEveryThreadCount(*scene, name);
  }
}

TEST(ThreadCounts, TexturedWithMsaaAndBackFaces) {
  const auto spot = projectScene("spot", 160, [](SceneSettings& s) {
    s.shading = ShadingMode::Texture;
    s.msaa = 4;
  });
  if (!spot) GTEST_SKIP() << "spot is not linked under models/";
  expectSameForEveryThreadCount(*spot, "spot, texture, msaa 4", {3});
  const auto teapot = projectScene("teapot", 160, [](SceneSettings& s) {
    s.shading = ShadingMode::Phong;
    s.cull = false;
  });
  expectSameForEveryThreadCount(*teapot, "teapot, phong, no cull", {2});
}

TEST(ThreadCounts, EveryShadingModeWithAndWithoutMsaa) {
  SceneSettings base = test::projectScene("bunny");
  if (!std::filesystem::exists(base.modelPath)) GTEST_SKIP() << "bunny is not linked";
  base.width = base.height = 120;
  Warnings warnings;
  const Scene loaded = loadScene(base, warnings);  // the mesh read once, for every mode
  // Under ThreadSanitizer (tools/tsan.sh) one algorithm: the modes' shading runs on the same
  // threads after each of them, and ReferenceModelsAndShapes runs every algorithm's threads; the
  // three took 58 s there, the longest test of CI's TSan step.
#if defined(__SANITIZE_THREAD__)
  const std::initializer_list<const char*> algorithms = {"octree"};
#else
  const std::initializer_list<const char*> algorithms = {"zbuffer", "interval", "octree"};
#endif
  for (const std::string& mode : shadingModeNames()) {
    for (int msaa : {1, 4}) {
      SceneSettings s = base;
      s.shading = *parseShadingMode(mode);
      s.msaa = msaa;
      const Scene scene = makeScene(s, loaded.mesh);
      for (const std::string algorithm : algorithms) {
        const test::Rendered one = renderWith(scene, algorithm, 1);
        test::expectSameFrame(one, renderWith(scene, algorithm, 3),
                              mode + ", msaa " + std::to_string(msaa) + ", " + algorithm);
      }
    }
  }
}

TEST(ThreadCounts, SmallCrowd) {
  // Under the sanitizers (tools/tsan.sh, tools/sanitize.sh) a 4 x 1 x 4 crowd: the same threaded
  // paths (instances in chunks, bands, the octree's leaves) at a sixth of the 10 x 1 x 10 crowd's
  // cost, which the plain suite runs.
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  const auto crowd = projectScene("crowd", 150, [](SceneSettings& s) {
    s.grid->count = {4, 1, 4};
  });
#else
  const auto crowd = projectScene("crowd", 150);
#endif
  if (!crowd) GTEST_SKIP() << "bunny is not linked under models/";
  expectSameForEveryThreadCount(*crowd, "crowd", {2, 7});
}

TEST(ThreadCounts, EveryFrameCountsItsOwnWork) {
  // The same camera twice gives the same counters: nothing a band keeps from the frame before
  // (its geometry, its pyramid) is counted again. A grid of random soups: back faces, faces
  // clipped away and octree leaves in several bands.
  SceneSettings s = test::tinySettings(97);
  s.grid = Grid{{4, 3, 1}, {1.0, 1.0, 0.0}};
  const Scene scene = makeScene(s, test::randomSoup(5, 120, true));
  for (const std::string& algorithm : algorithmNames()) {
    for (int threads : {1, 2, 3}) {
      Renderer renderer(scene, algorithm, threads);
      renderer.renderFrame(makeCamera(scene));
      const RenderStats first = renderer.stats();
      renderer.renderFrame(makeCamera(scene));
      const RenderStats& second = renderer.stats();
      const std::string label = algorithm + ", " + std::to_string(threads) + " threads";
      EXPECT_GT(first.trianglesBackfaceCulled, 0u) << label;
      EXPECT_EQ(second.trianglesBackfaceCulled, first.trianglesBackfaceCulled) << label;
      EXPECT_EQ(second.trianglesClippedAway, first.trianglesClippedAway) << label;
      EXPECT_EQ(second.trianglesDegenerate, first.trianglesDegenerate) << label;
      EXPECT_EQ(second.trianglesRasterized, first.trianglesRasterized) << label;
      EXPECT_EQ(second.trianglesHzbCulled, first.trianglesHzbCulled) << label;
      EXPECT_EQ(second.octreeNodesVisited, first.octreeNodesVisited) << label;
      EXPECT_EQ(second.pixelsTested, first.pixelsTested) << label;
      EXPECT_EQ(second.pixelsWritten, first.pixelsWritten) << label;
      EXPECT_EQ(second.extra, first.extra) << label;
    }
  }
}

TEST(ThreadCounts, GridWhoseEveryInstanceIsSeen) {
  // Random soups side by side, each overlapping its neighbours: every instance, from the
  // hierarchical z-buffer's first (nearest) to its last (farthest), has samples of its own in
  // the image, so an instance drawn wrongly or not at all on several threads shows.
  SceneSettings s = test::tinySettings(97);
  s.grid = Grid{{4, 3, 1}, {1.0, 1.0, 0.0}};
  const Scene scene = makeScene(s, test::randomSoup(5, 120, true));
  const test::Rendered one = renderWith(scene, "zbuffer", 1);
  std::set<uint32_t> seen;
  const uint32_t nf = uint32_t(scene.mesh->faceCount());
  for (int y = 0; y < one.buffer.height(); ++y)
    for (int x = 0; x < one.buffer.width(); ++x)
      if (keyFaceId(one.buffer.row(y)[x]) != kBackgroundId)
        seen.insert(keyFaceId(one.buffer.row(y)[x]) / nf);
  EXPECT_EQ(seen.size(), size_t(scene.instanceCount()));
  expectSameForEveryThreadCount(scene, "grid of soups");
}

TEST(ThreadCounts, RandomSoups) {
  for (unsigned seed : {3u, 4u}) {
    SceneSettings s = test::tinySettings(97);  // rows not a multiple of any band height
    s.cull = seed == 4;
    const Scene scene = makeScene(s, test::randomSoup(seed, 300, true));
    expectSameForEveryThreadCount(scene, "soup " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace zrender
