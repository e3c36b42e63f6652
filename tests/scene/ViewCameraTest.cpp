// The cameras of a run's views (viewCamera; docs/design.md, Views): azimuth turns the eye about
// the up axis through the target (right-hand rule), elevation raises it toward up (past the
// pole too), zoom magnifies through the focal length, and a view's own eye, target or up frame
// it as the scene's would. A turntable's frames are views, bit for bit.

#include <gtest/gtest.h>

#include <cmath>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A square at the origin seen from (0, 0, 10), up +Y.
Scene squareScene(bool fit = false) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(16);
  s.eye = Vec3(0, 0, 10);
  s.target = Vec3(0, 0, 0);
  s.near = 1.0;
  s.far = 20.0;
  s.fit = fit;
  return makeScene(s, mesh);
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << i;
}

// The point a view matrix maps to `p`'s camera-space position, through the inverse view.
Vec3 viewPoint(const Camera& c, const Vec3& p) {
  return transformPoint(c.view, p);
}

TEST(ViewCamera, AzimuthTurnsTheEyeAboutUpByTheRightHandRule) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.azimuth = 90.0;
  const Camera c = viewCamera(scene, base, view, "test");
  expectNear(c.eye, Vec3(10, 0, 0));  // +Z turned 90 degrees about +Y is +X
  expectNear(c.up, Vec3(0, 1, 0));
  // The same camera as lookAt from there.
  const Mat4 expected = lookAt(Vec3(10, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0));
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(c.view.val[i], expected.val[i], 1e-12) << i;
  EXPECT_EQ(c.projection, base.projection);
}

TEST(ViewCamera, ElevationRaisesTheEyeTowardUpEvenOverThePole) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.elevation = 30.0;
  expectNear(viewCamera(scene, base, view, "test").eye,
             Vec3(0, 10 * std::sin(kPi / 6), 10 * std::cos(kPi / 6)));
  view.elevation = 90.0;
  const Camera top = viewCamera(scene, base, view, "test");
  expectNear(top.eye, Vec3(0, 10, 0));
  // Looking straight down, the image's up is the old viewing direction, -Z: a point beyond the
  // target along -Z is above the image's centre, and the target is 10 ahead.
  expectNear(viewPoint(top, Vec3(0, 0, 0)), Vec3(0, 0, -10));
  expectNear(viewPoint(top, Vec3(0, 0, -1)), Vec3(0, 1, -10));
  expectNear(top.up, Vec3(0, 0, -1));
  // Past the pole: the eye goes on over the top, and the picture is upside down.
  view.elevation = 120.0;
  expectNear(viewCamera(scene, base, view, "test").eye,
             Vec3(0, 10 * std::sin(kPi * 2 / 3), 10 * std::cos(kPi * 2 / 3)));
}

TEST(ViewCamera, ElevationThenAzimuth) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.elevation = 45.0;
  view.azimuth = 90.0;
  const double h = 10 * std::sqrt(0.5);
  expectNear(viewCamera(scene, base, view, "test").eye, Vec3(h, h, 0), 1e-9);
}

TEST(ViewCamera, ZoomMultipliesTheFocalLength) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.zoom = 2.0;
  const Camera c = viewCamera(scene, base, view, "test");
  // projection(1, 1) is the focal length over the half height: cot(fovy / 2).
  EXPECT_NEAR(c.projection(1, 1), 2.0 * base.projection(1, 1), 1e-12);
  EXPECT_NEAR(c.projection(0, 0), 2.0 * base.projection(0, 0), 1e-12);
  EXPECT_EQ(c.view, base.view);
  EXPECT_EQ(c.near, base.near);
  EXPECT_EQ(c.far, base.far);
}

TEST(ViewCamera, ATurntableFrameIsTheViewTurnedTheOtherWayBitForBit) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  for (int k = 0; k < 7; ++k) {
    ViewSpec view;
    view.azimuth = -(360.0 * k / 7);
    const Camera c = viewCamera(scene, base, view, "test");
    const Camera t = turntableCamera(base, 360.0 * k / 7);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(c.view.val[i], t.view.val[i]) << k << " " << i;
  }
}

TEST(ViewCamera, AViewsOwnEyeIsFramedAsTheScenesWouldBe) {
  const Scene scene = squareScene(true);
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.eye = Vec3(3, 4, 0);
  const Camera c = viewCamera(scene, base, view, "test");
  SceneSettings s = scene.settings;
  s.eye = Vec3(3, 4, 0);
  s.fitKeeps.eye = true;
  const Camera expected = makeCamera(scene, s);
  EXPECT_EQ(c.view, expected.view);
  EXPECT_EQ(c.projection, expected.projection);
  expectNear(c.eye, Vec3(3, 4, 0));
}

TEST(ViewCamera, AViewWhoseEyeIsItsTargetIsAnErrorNamingIt) {
  const Scene scene = squareScene();
  const Camera base = makeCamera(scene);
  ViewSpec view;
  view.eye = Vec3(0, 0, 0);
  try {
    viewCamera(scene, base, view, "settings.json: scene 's': key 'views[3]'");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "settings.json: scene 's': key 'views[3]': the eye [0, 0, 0] is the target");
  }
  view.eye = Vec3(0, 5, 0);  // straight above: up is the viewing direction
  EXPECT_THROW(viewCamera(scene, base, view, "v"), InputError);
}

}  // namespace
}  // namespace zrender
