// The viewer's camera (view/OrbitCamera.hpp): the starting eye taken apart into azimuth,
// elevation and distance about the target, moved by a ViewState, and near and far hugging the
// model where the scene is framed by fit.

#include <gtest/gtest.h>

#include <cmath>

#include "support/TestSupport.hpp"
#include "zrender/view/OrbitCamera.hpp"

namespace zrender {
namespace {

constexpr double kPi = 3.14159265358979323846;

Scene squareScene(const SceneSettings& s) {
  return makeScene(
      s, test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}}));
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_NEAR(cv::norm(a - b), 0.0, tolerance) << a << " vs " << b;
}

ViewState at(double azimuth, double elevation, int zoomSteps) {
  ViewState s;
  s.azimuth = azimuth;
  s.elevation = elevation;
  s.zoomSteps = zoomSteps;
  return s;
}

TEST(OrbitCamera, TheStartStateGivesTheStartingCamera) {
  SceneSettings s = test::tinySettings(32);
  s.eye = Vec3(1, 2, 3);
  s.target = Vec3(0.5, -1, 0);
  const Scene scene = squareScene(s);
  const Camera start = makeCamera(scene);
  const OrbitCamera orbit(start, scene);
  // eye - target = (0.5, 3, 3): 3 above the target, sqrt(9.25) across.
  EXPECT_NEAR(orbit.startElevation(), std::atan2(3.0, std::sqrt(9.25)) * 180.0 / kPi, 1e-12);
  const Camera cam = orbit.at(at(0.0, orbit.startElevation(), 0));
  expectNear(cam.eye, start.eye, 1e-12);
  EXPECT_EQ(cam.target, start.target);
  EXPECT_EQ(cam.up, start.up);
  EXPECT_EQ(cam.near, start.near);
  EXPECT_EQ(cam.far, start.far);
  EXPECT_EQ(cam.width, 32);
}

TEST(OrbitCamera, AzimuthTurnsTheEyeAboutUpElevationRaisesItZoomScalesTheDistance) {
  const Scene scene = squareScene(test::tinySettings(32));  // eye (0, 0, 2), up +Y
  const OrbitCamera orbit(makeCamera(scene), scene);
  EXPECT_NEAR(orbit.startElevation(), 0.0, 1e-12);
  expectNear(orbit.at(at(90.0, 0.0, 0)).eye, Vec3(2, 0, 0), 1e-12);  // right-hand rule
  expectNear(orbit.at(at(180.0, 0.0, 0)).eye, Vec3(0, 0, -2), 1e-12);
  expectNear(orbit.at(at(0.0, 30.0, 0)).eye, Vec3(0, 1, std::sqrt(3.0)), 1e-12);
  expectNear(orbit.at(at(0.0, 0.0, -1)).eye, Vec3(0, 0, 1.6), 1e-12);
  expectNear(orbit.at(at(0.0, 0.0, 2)).eye, Vec3(0, 0, 3.125), 1e-12);
  // Built as makeCamera builds one, from eye, target and up.
  const Camera cam = orbit.at(at(33.0, -20.0, 1));
  EXPECT_EQ(cam.view, lookAt(cam.eye, cam.target, cam.up));
  EXPECT_EQ(cam.projection, perspective(cam.fovy, cam.aspect, cam.near, cam.far));
}

TEST(OrbitCamera, NearAndFarHugTheModelOnlyWhereFitFramesIt) {
  SceneSettings s = test::tinySettings(32);
  const Scene fixed = squareScene(s);
  const OrbitCamera still(makeCamera(fixed), fixed);
  EXPECT_EQ(still.at(at(0.0, 0.0, 4)).near, 0.1);
  EXPECT_EQ(still.at(at(0.0, 0.0, 4)).far, 10.0);

  s.fit = true;
  const Scene framed = squareScene(s);
  const Camera start = makeCamera(framed);
  const OrbitCamera orbit(start, framed);
  const double distance = cv::norm(start.eye - start.target);
  for (int zoom : {-3, 0, 5}) {
    const Camera cam = orbit.at(at(0.0, orbit.startElevation(), zoom));
    const FitView hug = hugSphere(distance * std::pow(1.25, zoom), framed.boundsRadius);
    EXPECT_NEAR(cam.near, hug.near, 1e-12) << zoom;
    EXPECT_NEAR(cam.far, hug.far, 1e-12) << zoom;
  }
  // A near the user gave stays.
  s.fitKeeps.near = true;
  s.near = 0.25;
  const Scene kept = squareScene(s);
  EXPECT_EQ(OrbitCamera(makeCamera(kept), kept).at(at(0.0, 0.0, 3)).near, 0.25);
}

}  // namespace
}  // namespace zrender
