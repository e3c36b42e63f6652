// Matrices and the viewport against values worked out by hand (OpenGL conventions,
// docs/design.md, Camera and transforms).

#include <gtest/gtest.h>

#include "zrender/scene/Transforms.hpp"

namespace zrender {
namespace {

void expectMatNear(const Mat4& a, const Mat4& b, double tol = 1e-12) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(a(r, c), b(r, c), tol) << "at (" << r << "," << c << ")";
}

TEST(Transforms, LookAtFromPlusZIsATranslation) {
  // Eye at (0, 0, 5) looking at the origin: view = translate(0, 0, -5).
  expectMatNear(lookAt(Vec3(0, 0, 5), Vec3(0, 0, 0), Vec3(0, 1, 0)),
                Mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -5, 0, 0, 0, 1));
}

TEST(Transforms, LookAtFromPlusXRotatesTheWorld) {
  // Eye at (3, 0, 0) looking at the origin: the camera's -Z is world -X, its +X is world -Z.
  const Mat4 v = lookAt(Vec3(3, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0));
  expectMatNear(v, Mat4(0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1));
  // The target lands 3 units in front of the camera, on its axis.
  const Vec3 t = transformPoint(v, Vec3(0, 0, 0));
  EXPECT_NEAR(t[0], 0.0, 1e-12);
  EXPECT_NEAR(t[2], -3.0, 1e-12);
}

TEST(Transforms, PerspectiveMatchesGluPerspective) {
  // fovy 90: f = 1; aspect 2; near 1, far 3: A = (3 + 1) / (1 - 3) = -2, B = 2*3*1/(1-3) = -3.
  expectMatNear(perspective(90.0, 2.0, 1.0, 3.0),
                Mat4(0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0));
}

TEST(Transforms, NearAndFarMapToWindowDepthZeroAndOne) {
  const Mat4 p = perspective(60.0, 1.0, 0.5, 20.0);
  const Vec4 nearPoint = p * Vec4(0, 0, -0.5, 1), farPoint = p * Vec4(0, 0, -20, 1);
  EXPECT_NEAR(clipToWindow(nearPoint, 100, 100)[2], 0.0, 1e-12);
  EXPECT_NEAR(clipToWindow(farPoint, 100, 100)[2], 1.0, 1e-12);
}

TEST(Transforms, ViewportPutsRowZeroAtTheTop) {
  // NDC (-1, 1) is the top-left corner, (1, -1) the bottom-right, (0, 0) the centre.
  const Vec3 topLeft = clipToWindow(Vec4(-2, 2, 0, 2), 640, 480);
  EXPECT_DOUBLE_EQ(topLeft[0], 0.0);
  EXPECT_DOUBLE_EQ(topLeft[1], 0.0);
  const Vec3 bottomRight = clipToWindow(Vec4(1, -1, 0, 1), 640, 480);
  EXPECT_DOUBLE_EQ(bottomRight[0], 640.0);
  EXPECT_DOUBLE_EQ(bottomRight[1], 480.0);
  const Vec3 centre = clipToWindow(Vec4(0, 0, 0, 1), 640, 480);
  EXPECT_DOUBLE_EQ(centre[0], 320.0);
  EXPECT_DOUBLE_EQ(centre[1], 240.0);
  EXPECT_DOUBLE_EQ(centre[2], 0.5);
}

TEST(Transforms, RotationFollowsTheRightHandRule) {
  // 90 degrees about +Y takes +X to -Z, and about +Z takes +X to +Y.
  const Vec3 a = transformPoint(rotation(90, Vec3(0, 2, 0)), Vec3(1, 0, 0));
  EXPECT_NEAR(a[0], 0, 1e-12);
  EXPECT_NEAR(a[2], -1, 1e-12);
  const Vec3 b = transformPoint(rotation(90, Vec3(0, 0, 1)), Vec3(1, 0, 0));
  EXPECT_NEAR(b[1], 1, 1e-12);
}

}  // namespace
}  // namespace zrender
