// A scene's instances (Scene::modelMatrix): a grid is centred on the origin; the bounding
// sphere holds them all.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
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
        const Mat4& m = scene.modelMatrix(n);  // its translation: the grid offset
        const Vec3 d = rotated + Vec3(m(0, 3), m(1, 3), m(2, 3)) - scene.boundsCentre;
        farthest = std::max(farthest, d.dot(d));
      }
    }
    EXPECT_EQ(scene.boundsRadius, std::sqrt(farthest)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// A mesh of `faces` triangles (all the same one): its face count is what counts here.
std::shared_ptr<const Mesh> manyFaces(int faces) {
  return test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}},
                        std::vector<std::vector<int>>(size_t(faces), {0, 1, 2}));
}

TEST(Scene, FaceIdsMustFitBelowTheBackgroundsId) {
  // 65537 x 65535 = 2^32 - 1 faces: ids 0 .. 2^32 - 2, the background's 2^32 - 1 left free.
  SceneSettings s = test::tinySettings(8);
  s.grid = Grid{{65535, 1, 1}, {1.0, 1.0, 1.0}};
  const Scene fits = makeScene(s, manyFaces(65537));
  EXPECT_EQ(uint64_t(fits.faceCount()), kMaxSceneFaces);
  try {
    makeScene(s, manyFaces(65538));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "scene '" + s.name +
                  "': 65538 faces x 65535 instances = 4295032830 faces, over the 4294967295 "
                  "face ids a frame can tell apart");
  }
}

}  // namespace
}  // namespace zrender
