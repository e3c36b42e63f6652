// The `octree` algorithm (OctreeAlgorithm) with leaves of any size draws the z-buffer's frame.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "support/TestSupport.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"

namespace zrender {
namespace {

TEST(OctreeAlgorithm, AnyLeafSizeGivesTheZBuffersFrame) {
  // The leaf size only moves where node tests happen; small leaves test far more nodes.
  for (uint32_t leafFaces : {1u, 4u, 32u}) {
    SceneSettings s = test::tinySettings(96);
    s.cull = false;
    Warnings warnings;
    const Scene scene = makeScene(s, test::randomSoup(6, 400, true));
    Renderer ref(scene, "zbuffer");
    Renderer octree(scene, std::make_unique<OctreeAlgorithm>(leafFaces));
    ref.renderFrame(makeCamera(scene));
    octree.renderFrame(makeCamera(scene));
    EXPECT_TRUE(identicalFrames(ref.buffer(), ref.color(), octree.buffer(), octree.color()))
        << "leaves of " << leafFaces;
    EXPECT_GT(test::coveredSamples(ref.buffer()), 1000u);
  }
}

}  // namespace
}  // namespace zrender
