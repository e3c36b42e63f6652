// A scene's instances (Scene::modelMatrix): a grid is centred on the origin; the bounding
// sphere holds them all.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "support/TestSupport.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {
namespace {

TEST(Scene, GridInstancesAreCentredOnTheOrigin) {
  // docs/design.md, Settings: instance (i, j, k) moves by ((i - (nx-1)/2) sx, (j - (ny-1)/2) sy, (k
  // - (nz-1)/2) sz), numbered i fastest: with counts 2 x 2 x 2 every offset is half a spacing
  // either way.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  SceneSettings s = test::tinySettings(8);
  s.grid = Grid{{2, 2, 2}, {1.0, 2.0, 3.0}};
  Warnings warnings;
  const Scene scene = makeScene(s, mesh);
  ASSERT_EQ(scene.instanceCount(), 8u);
  for (uint32_t n = 0; n < 8; ++n) {
    const Vec3 moved = transformPoint(scene.modelMatrix(n), Vec3(0, 0, 0));
    const Vec3 expected((n % 2 == 0 ? -0.5 : 0.5), (n / 2 % 2 == 0 ? -1.0 : 1.0),
                        (n / 4 == 0 ? -1.5 : 1.5));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(moved[a], expected[a]) << "instance " << n << ", " << a;
  }
}

// The bounding sphere's radius reaches the farthest vertex of every instance: the largest
// distance from the centre over the vertices of all instances, computed here the long way, is
// the radius to the last bit.
TEST(Scene, TheBoundingSphereReachesTheFarthestVertexOfAnyInstance) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    auto mesh = test::randomSoup(seed, 50, false);
    SceneSettings s = test::tinySettings(8);
    s.grid = Grid{{3, 2, 4}, {0.7, 1.9, 0.4}};
    s.angle = 33.0;
    s.axis = Vec3(1, 2, 3);
    const Scene scene = makeScene(s, mesh);
    double farthest = 0.0;
    for (uint32_t n = 0; n < scene.instanceCount(); ++n) {
      for (const Vec3& p : mesh->positions) {
        const Vec3 rotated = transformPoint(rotation(s.angle, s.axis), p);
        const Vec3 d = rotated + scene.instanceOffsets[n] - scene.boundsCentre;
        farthest = std::max(farthest, d.dot(d));
      }
    }
    EXPECT_EQ(scene.boundsRadius, std::sqrt(farthest)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace zrender
