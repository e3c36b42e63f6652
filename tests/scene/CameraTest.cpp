// The camera of a scene (makeCamera, turntableCamera; docs/design.md, Camera and transforms): a
// model behind it, fit framing the bounding sphere in the smaller field of view, and the
// turntable's turn.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {
namespace {

TEST(Camera, ModelBehindTheCameraDrawsNothing) {
  // A square at z = 0 seen from z = 2 looking away from it (toward -... +Z).
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(16);
  s.target = Vec3(0, 0, 5);
  s.cull = false;
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  for (size_t i = 0; i < r.buffer.size(); ++i) ASSERT_EQ(r.buffer.data()[i], kClearKey);
  EXPECT_EQ(r.stats.trianglesClippedAway, 2u);
  EXPECT_EQ(r.stats.trianglesRasterized, 0u);
}

TEST(Camera, FitFramesTheBoundingSphere) {
  // A unit-radius model centred at (5, 0, 0): fit moves the target there and backs the eye
  // off along the original direction until radius * 1.05 fills the smaller half-angle.
  auto mesh = test::makeMesh({{4, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, -1, 0}}, {{0, 1, 2}, {0, 3, 1}});
  SceneSettings s = test::tinySettings(16);
  s.fit = true;
  s.fovy = 60.0;
  Warnings w;
  const Scene scene = makeScene(s, mesh);
  EXPECT_NEAR(scene.boundsRadius, 1.0, 1e-12);
  const Camera cam = makeCamera(scene);
  EXPECT_NEAR(cam.target[0], 5.0, 1e-12);
  const double distance = 1.05 / std::sin(30.0 * CV_PI / 180.0);
  EXPECT_NEAR(cv::norm(cam.eye - cam.target), distance, 1e-9);
  EXPECT_NEAR(cam.eye[2], distance, 1e-9);  // still looking down -Z
  EXPECT_NEAR(cam.near, distance - 1.05, 1e-9);
  EXPECT_NEAR(cam.far, distance + 1.05, 1e-9);
}

TEST(Camera, FitUsesTheSmallerFieldOfViewOfAWideOrTallImage) {
  // The same unit sphere at fovy 60: the horizontal half-angle is atan(tan 30 * aspect), so a
  // wide image (32 x 16) is bound by its vertical 30 degrees and a tall one (16 x 32) by its
  // horizontal atan(tan 30 / 2) = 16.1 degrees, which needs the eye farther away.
  auto mesh = test::makeMesh({{4, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, -1, 0}}, {{0, 1, 2}, {0, 3, 1}});
  SceneSettings s = test::tinySettings(16);
  s.fit = true;
  s.fovy = 60.0;
  const double half = 30.0 * CV_PI / 180.0;
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{32, 16}, {16, 32}}) {
    s.width = width, s.height = height;
    Warnings w;
    const Camera cam = makeCamera(makeScene(s, mesh));
    const double horizontal = std::atan(std::tan(half) * width / height);
    const double distance = 1.05 / std::sin(std::min(half, horizontal));
    EXPECT_NEAR(cv::norm(cam.eye - cam.target), distance, 1e-9) << width << " x " << height;
  }
  EXPECT_NEAR(1.05 / std::sin(std::atan(std::tan(half) / 2)), 3.7858,
              1e-4);  // tall: 1.05 / 0.27735
}

TEST(Camera, TurntableTurnsTheModelByTheRightHandRuleAboutUp) {
  // Up +Y, eye on +Z: a quarter turn takes the model's +X side to -Z, away from the eye (seen
  // from above, counter-clockwise), so the turned view shows at (1, 0, 0) what the first view
  // shows at (0, 0, -1), and the other way round for a three-quarter turn.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  Warnings w;
  const Camera cam = makeCamera(makeScene(test::tinySettings(16), mesh));
  const auto seen = [](const Mat4& view, const Vec3& p) { return transformPoint(view, p); };
  const Vec3 quarter = seen(turntableCamera(cam, 90.0).view, Vec3(1, 0, 0));
  const Vec3 expected = seen(cam.view, Vec3(0, 0, -1));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(quarter[a], expected[a], 1e-12) << a;
  const Vec3 threeQuarters = seen(turntableCamera(cam, 270.0).view, Vec3(1, 0, 0));
  const Vec3 front = seen(cam.view, Vec3(0, 0, 1));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(threeQuarters[a], front[a], 1e-12) << a;
}

}  // namespace
}  // namespace zrender
