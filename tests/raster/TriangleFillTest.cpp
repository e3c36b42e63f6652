// The pixel loops of the z-buffer (TriangleFill): the AVX2 triangle and span fills against their
// scalar twins, bit for bit, on random triangles, spans and planes (NaN and infinities too).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "support/TestSupport.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/raster/TriangleFill.hpp"

namespace zrender {
namespace {

// A plane for the vector-against-scalar tests: slopes up to 0.2 per sample, depths crossing 0
// and 1, a random clamp range, and every 50th a NaN, infinite, huge or -0 x slope.
DepthPlane randomPlane(std::mt19937& rng, int i) {
  const double specials[] = {std::nan(""), HUGE_VAL, -HUGE_VAL, 1e300, -0.0};
  std::uniform_real_distribution<double> slope(-0.2, 0.2), offset(-0.5, 1.5);
  DepthPlane plane{slope(rng), slope(rng), offset(rng)};
  if (i % 50 == 0) plane.a = specials[(i / 50) % 5];
  const float lo = std::uniform_real_distribution<float>(0.0f, 0.6f)(rng);
  plane.loBits = int32_t(floatBits(lo));
  plane.hiBits = int32_t(floatBits(std::min(1.0f, lo + 0.5f)));
  return plane;
}

TEST(TriangleFill, VectorFillMatchesTheScalarFillBitForBit) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar fill runs";
  // Random triangles from a sample wide to wider than the image, reaching past every border,
  // with planes that rise steeply, cross 0 and 1, or give NaN and infinities, on an image
  // whose width is not a multiple of the four-sample block.
  const int width = 37, height = 29;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int32_t> coord(-12 * kSubpixel, 50 * kSubpixel);
  std::uniform_int_distribution<int32_t> near(-6 * kSubpixel, 6 * kSubpixel);
  FrameBuffer scalar, vector;
  scalar.resize(width, height);
  vector.resize(width, height);
  scalar.clear();
  vector.clear();
  RenderStats scalarStats, vectorStats;
  int filled = 0, wide = 0;
  for (int i = 0; i < 4000; ++i) {
    FixedPoint v[3];
    v[0] = {coord(rng), coord(rng)};
    const bool small = i % 2 == 0;
    for (int k = 1; k < 3; ++k)
      v[k] = small ? FixedPoint{v[0].x + near(rng), v[0].y + near(rng)}
                   : FixedPoint{coord(rng), coord(rng)};
    if (orient2d(v[0], v[1], v[2]) < 0) std::swap(v[1], v[2]);
    if (orient2d(v[0], v[1], v[2]) == 0) continue;
    TriangleSetup s;
    if (!s.setup(v, width, height)) continue;
    const DepthPlane plane = randomPlane(rng, i);
    fillTriangleScalar(s, plane, uint32_t(i), scalar, scalarStats);
    fillTriangleAvx2(s, plane, uint32_t(i), vector, vectorStats);
    ++filled;
    wide += s.maxX - s.minX >= 12;
  }
  EXPECT_GT(filled, 1000);
  EXPECT_GT(wide, 200);  // the skipping loop of wide triangles ran too
  EXPECT_EQ(test::countDifferences(scalar, vector), 0u);
  EXPECT_EQ(scalarStats.pixelsTested, vectorStats.pixelsTested);
  EXPECT_EQ(scalarStats.pixelsWritten, vectorStats.pixelsWritten);
  EXPECT_GT(scalarStats.pixelsWritten, 5000u);
}

TEST(TriangleFill, VectorSpanFillMatchesTheScalarSpanFillBitForBit) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar fill runs";
  // Random spans, from one sample to the whole row, reaching its end, with planes that rise
  // steeply, cross 0 and 1, or give NaN and infinities, on rows whose width is not a multiple
  // of the four-sample block.
  const int width = 37, rows = 9;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> column(0, width - 1);
  FrameBuffer scalar, vector;
  scalar.resize(width, rows);
  vector.resize(width, rows);
  scalar.clear();
  vector.clear();
  uint64_t scalarWritten = 0, vectorWritten = 0;
  for (int i = 0; i < 3000; ++i) {
    int left = column(rng), right = column(rng) + 1;
    if (left >= right) std::swap(left, right);
    if (i % 7 == 0) right = width;
    const int y = i % rows;
    const DepthPlane plane = randomPlane(rng, i);
    const double rowBase = plane.rowBase(y);
    scalarWritten += fillSpanScalar(scalar.row(y), left, right, plane, rowBase, uint32_t(i));
    vectorWritten += fillSpanAvx2(vector.row(y), left, right, plane, rowBase, uint32_t(i));
  }
  EXPECT_EQ(test::countDifferences(scalar, vector), 0u);
  EXPECT_EQ(scalarWritten, vectorWritten);
  EXPECT_GT(scalarWritten, 1000u);  // spans overwrite each other: a real mix of winners
}

}  // namespace
}  // namespace zrender
