// Matrices and the viewport against values worked out by hand (OpenGL conventions, SPEC §4).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "TestSupport.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/Clipping.hpp"
#include "zrender/transform/VertexProjection.hpp"

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

TEST(Clipping, TriangleCrossingTheNearPlaneBecomesAQuad) {
  // Near plane z = -w. Vertex 0 is in front of it (z < -w), the others inside: the clip cuts
  // edges 0-1 and 2-0 at their midpoints in this setup (distances -1 and +1).
  const Vec4 in[3] = {Vec4(0, 0, -2, 1), Vec4(1, 0, 0, 1), Vec4(0, 1, 0, 1)};
  Vec4 out[5], scratch[5];
  const size_t n = clipNearFar(in, 3, out, scratch);
  ASSERT_EQ(n, 4u);
  // In cyclic order: vertex 1, vertex 2, the cut on 2-0, the cut on 0-1.
  size_t start = 0;
  while (start < n && out[start] != in[1]) ++start;
  ASSERT_LT(start, n);
  EXPECT_EQ(out[(start + 1) % n], in[2]);
  EXPECT_EQ(out[(start + 2) % n], Vec4(0, 0.5, -1, 1));
  EXPECT_EQ(out[(start + 3) % n], Vec4(0.5, 0, -1, 1));
  for (size_t i = 0; i < n; ++i) EXPECT_GE(out[i][2] + out[i][3], 0.0);
}

TEST(Clipping, SharedEdgeIsCutAtTheSamePointFromBothSides) {
  const Vec4 a(0.3, 0.1, -3, 1.1), b(0.7, -0.2, 0.5, 2.3), c(-0.4, 0.6, 0.2, 1.7),
      d(0.9, 0.9, 0.1, 1.9);
  const Vec4 left[3] = {a, b, c}, right[3] = {b, a, d};  // edge a-b walked both ways
  Vec4 outL[5], outR[5], scratch[5];
  const size_t nl = clipNearFar(left, 3, outL, scratch);
  const size_t nr = clipNearFar(right, 3, outR, scratch);
  ASSERT_EQ(nl, 4u);
  ASSERT_EQ(nr, 4u);
  // Both polygons contain the cut on a-b: the point on the near plane (z = -w) on that edge.
  auto cutOnAB = [&](const Vec4* pts, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      const Vec4 p = pts[i];
      const Vec4 ab = b - a, ap = p - a;
      const bool onEdge = std::abs(ap[0] * ab[1] - ap[1] * ab[0]) < 1e-9;
      if (std::abs(p[2] + p[3]) < 1e-12 && onEdge) return p;
    }
    return Vec4(NAN, NAN, NAN, NAN);
  };
  const Vec4 cutL = cutOnAB(outL, nl), cutR = cutOnAB(outR, nr);
  ASSERT_FALSE(std::isnan(cutL[0]));
  EXPECT_EQ(cutL, cutR);  // bit for bit
}

TEST(Clipping, TriangleWhollyBehindTheCameraIsGone) {
  const Vec4 in[3] = {Vec4(0, 0, -3, 1), Vec4(1, 0, -2, 1), Vec4(0, 1, -5, 1)};
  Vec4 out[5], scratch[5];
  EXPECT_EQ(clipNearFar(in, 3, out, scratch), 0u);
}

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

TEST(VertexProjection, FourAtATimeMatchesOneAtATimeBitForBit) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar projection runs";
  // Random cameras and sizes (MSAA too), and positions of every kind: in view, behind the eye,
  // on the eye plane, far outside the image (guard band), exactly on a clip plane, huge (clip
  // coordinates overflow), NaN and infinite. Every field the scalar version sets must match.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = HUGE_VAL;
  int compared = 0, inView = 0, guarded = 0, clipped = 0, notFinite = 0;
  for (int round = 0; round < 400; ++round) {
    const Vec3 eye(3 * u(rng), 3 * u(rng), 3 + 2 * u(rng));
    // One camera in four with a field of view so narrow that most points land beyond the
    // guard band.
    const double fovy = round % 4 == 0 ? 0.001 : 30 + 60 * (u(rng) + 1);
    const Mat4 mvp = perspective(fovy, 0.5 + (u(rng) + 1), 0.1, 50.0) *
                     lookAt(eye, Vec3(u(rng), u(rng), u(rng)), Vec3(0, 1, 0)) *
                     rotation(180 * u(rng), Vec3(u(rng), 1, u(rng)));
    const VertexViewport viewport{1 + int(rng() % 2000), 1 + int(rng() % 2000), 1 + int(rng() % 2)};
    Vec3 p[4];
    for (Vec3& q : p) {
      switch (rng() % 8) {
        case 0:  // far out to the sides: beyond the guard band
          q = Vec3(1e6 * u(rng), 1e6 * u(rng), u(rng));
          break;
        case 1:  // on the eye's plane or behind it
          q = eye + Vec3(u(rng), u(rng), u(rng) * 0.01);
          break;
        case 2:  // huge
          q = Vec3(1e300 * u(rng), 1e300, u(rng));
          break;
        case 3:  // NaN or infinite
          q = Vec3(rng() % 2 ? nan : inf, u(rng), u(rng));
          break;
        case 4:  // the eye itself (w = 0)
          q = eye;
          break;
        default:
          q = Vec3(u(rng), u(rng), u(rng));
      }
    }
    const Vec3* const positions[4] = {&p[0], &p[1], &p[2], &p[3]};
    VertexState vector[4], scalar[4];
    Vec3 vectorWindow[4], scalarWindow[4];
    projectVertices4Avx2(mvp, positions, viewport, 5, vector, vectorWindow);
    for (int k = 0; k < 4; ++k) {
      projectVertex(mvp, p[k], viewport, 5, scalar[k], scalarWindow[k]);
      ASSERT_EQ(vector[k].code, scalar[k].code) << "round " << round << ", lane " << k;
      EXPECT_EQ(vector[k].frame, 5u);
      const uint32_t code = scalar[k].code;
      if (!(code & (kNear | kFar | kNotFinite))) {
        EXPECT_EQ(std::memcmp(&vectorWindow[k], &scalarWindow[k], sizeof(Vec3)), 0)
            << "round " << round << ", lane " << k;
      }
      if (!(code & kNeedsClip)) {
        EXPECT_EQ(vector[k].snapped, scalar[k].snapped) << "round " << round << ", lane " << k;
      }
      ++compared;
      inView += (code & 0xFF) == 0;
      guarded += (code & kGuard) != 0;
      clipped += (code & (kNear | kFar)) != 0;
      notFinite += (code & kNotFinite) != 0;
    }
  }
  // Every kind was met.
  EXPECT_EQ(compared, 1600);
  EXPECT_GT(inView, 100);
  EXPECT_GT(guarded, 10);
  EXPECT_GT(clipped, 10);
  EXPECT_GT(notFinite, 10);
}

}  // namespace
}  // namespace zrender
