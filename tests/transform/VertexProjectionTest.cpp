// The vertex projection (VertexProjection): four vertices at a time (AVX2) against one at a time,
// bit for bit, for positions of every kind.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/VertexProjection.hpp"

namespace zrender {
namespace {

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
