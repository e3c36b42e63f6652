// Clipping at the near and far planes (clipNearFar) against values worked out by hand (OpenGL
// conventions, docs/design.md, Camera and transforms), and a concave face cut many times by the
// near plane and the guard band.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/AlgorithmAgreement.hpp"
#include "support/TestSupport.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/Clipping.hpp"

namespace zrender {
namespace {

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

// A concave face cut by the near plane many times: its clipped polygon reaches 3/2 count
// corners per plane, more than the count + 2 of a convex one, and the clipping buffers must hold
// them (a heap overflow under ASan otherwise). (Also in the render fuzz corpus:
// regression-concave-near-clip-overflow.bin.)
TEST(Clipping, ConcavePolygonCutManyTimesByTheNearPlane) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  s.eye = Vec3(0, 0, 0);
  s.target = Vec3(0, 0, -1);
  s.near = 0.5;
  // A zig-zag in the floor plane y = -0.5: corners alternately before (z = -0.1) and behind
  // (z = -3) the near plane, then the base. Same in a vertical plane, for the guard band.
  std::string obj;
  const int teeth = 40;
  for (int i = 0; i <= 2 * teeth; ++i) {
    obj += "v " + std::to_string(-2.0 + 4.0 * i / (2 * teeth)) + " -0.5 " +
           (i % 2 ? "-0.1" : "-3") + "\n";
  }
  obj += "v 2 -0.5 -4\nv -2 -0.5 -4\nf";
  for (int i = 1; i <= 2 * teeth + 3; ++i) obj += " " + std::to_string(i);
  obj += "\n";
  test::expectAgreement(obj, s);
  s.msaa = 4;
  test::expectAgreement(obj, s);
  // Far beyond the image sideways (the guard band cuts it many times too).
  std::string wide;
  for (int i = 0; i <= 2 * teeth; ++i) {
    wide += "v " + std::to_string(-1e7 + 2e7 * i / (2 * teeth)) + " " + (i % 2 ? "1e7" : "-0.2") +
            " -1\n";
  }
  wide += "v 1e7 -1e7 -1\nv -1e7 -1e7 -1\nf";
  for (int i = 1; i <= 2 * teeth + 3; ++i) wide += " " + std::to_string(i);
  test::expectAgreement(wide + "\n", s);
}

}  // namespace
}  // namespace zrender
