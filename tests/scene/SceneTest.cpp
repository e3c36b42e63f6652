// A scene's instances (Scene::modelMatrix): a grid is centred on the origin.

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace zrender
