// The z-pyramid (DepthPyramid): the AVX2 tile maximum against the scalar one, and every node a
// bound of the buffer below it (exact after every triangle) as an HzbRasterizer draws.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/ScreenGeometry.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"

namespace zrender {
namespace {

using test::makeTriangle;

TEST(DepthPyramid, VectorTileMaximumMatchesTheScalarOne) {
  // Random tiles of few distinct keys (many ties, so the row and column picked matter), some
  // with the top bit set (unsigned order), with 1 to 16 rows, inside a wider buffer.
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  std::mt19937_64 rng(11);
  const size_t stride = 40;
  std::vector<DepthKey> buffer(stride * 16);
  int lastRowPicked = 0, notLastColumn = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int distinct = 1 + int(rng() % 6);
    std::vector<DepthKey> pool(static_cast<size_t>(distinct));
    for (DepthKey& k : pool) {
      k = rng();
      if (rng() % 2) k &= ~(DepthKey(1) << 63);
      if (rng() % 4 == 0) k = kClearKey;
    }
    for (DepthKey& k : buffer) k = pool[rng() % pool.size()];
    const int rows = 1 + int(rng() % 16);
    const DepthKey* first = buffer.data() + 3;
    const TileMax expected = tileMax(first, stride, rows, DepthPyramid::kTileSize);
    const TileMax actual = tileMaxAvx2(first, stride, rows);
    ASSERT_EQ(expected.key, actual.key) << trial;
    ASSERT_EQ(expected.row, actual.row) << trial;
    ASSERT_EQ(expected.column, actual.column) << trial;
    // The scalar one, by definition: the largest key, at the last row and column holding it.
    DepthKey largest = 0;
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < 16; ++x) largest = std::max(largest, first[size_t(y) * stride + x]);
    ASSERT_EQ(expected.key, largest);
    ASSERT_EQ(first[size_t(expected.row) * stride + size_t(expected.column)], largest);
    for (int y = expected.row + 1; y < rows; ++y)
      for (int x = 0; x < 16; ++x) ASSERT_NE(first[size_t(y) * stride + x], largest);
    for (int x = expected.column + 1; x < 16; ++x)
      ASSERT_NE(first[size_t(expected.row) * stride + x], largest);
    lastRowPicked += expected.row == rows - 1;
    notLastColumn += expected.column != 15;
  }
  EXPECT_GT(lastRowPicked, 1000);
  EXPECT_GT(notLastColumn, 1000);
}

TEST(DepthPyramid, NodesBoundTheBufferAfterRandomWrites) {
  // Random triangles at random depths on buffers of awkward sizes (partial tiles, a single
  // tile, one row of tiles), then pyramid queries over random rectangles against a
  // brute-force maximum of the buffer: never occluded when key <= that maximum. The buffer
  // must also end fully written (cleared where nothing was drawn).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int rejected = 0;
  uint64_t culled = 0;
  for (const auto& size :
       std::vector<std::pair<int, int>>{{100, 70}, {1, 1}, {5, 3}, {9, 17}, {64, 8}, {33, 130}}) {
    const int w = size.first, h = size.second;
    SCOPED_TRACE(std::to_string(w) + " x " + std::to_string(h));
    FrameBuffer fb;
    fb.resize(w, h);
    std::fill(fb.data(), fb.data() + fb.size(), DepthKey(12345));  // last frame's garbage
    HzbRasterizer r;
    r.begin(fb);
    RenderStats stats;
    for (uint32_t i = 0; i < 300; ++i) {
      double p[6];
      for (int k = 0; k < 6; k += 2) p[k] = unit(rng) * w, p[k + 1] = unit(rng) * h;
      ScreenTriangle t = makeTriangle(p[0], p[1], p[2], p[3], p[4], p[5], i, unit(rng));
      if (orient2d(t.v[0], t.v[1], t.v[2]) < 0) std::swap(t.v[1], t.v[2]);
      t.plane.a = (unit(rng) - 0.5) * 0.01;
      if (orient2d(t.v[0], t.v[1], t.v[2]) > 0) r.drawTriangle(t, stats);
    }
    for (int q = 0; q < 500; ++q) {
      int x0 = int(unit(rng) * w), x1 = int(unit(rng) * w);
      int y0 = int(unit(rng) * h), y1 = int(unit(rng) * h);
      if (x0 > x1) std::swap(x0, x1);
      if (y0 > y1) std::swap(y0, y1);
      DepthKey m = 0;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) m = std::max(m, fb.row(y)[x]);
      const DepthKey key = makeDepthKey(float(unit(rng)), 0);
      const bool occluded = r.pyramid().occludes(x0, y0, x1, y1, key, 64);
      if (key <= m) {
        ASSERT_FALSE(occluded) << q;
      }
      rejected += occluded;
    }
    r.finish();
    for (size_t i = 0; i < fb.size(); ++i) ASSERT_NE(fb.data()[i], DepthKey(12345)) << i;
    culled += stats.trianglesHzbCulled;
  }
  EXPECT_GT(culled, 0u);
  EXPECT_GT(rejected, 0);
}

TEST(DepthPyramid, EveryNodeIsExactAfterEveryTriangle) {
  // Not only a bound (above): after each triangle, every node at every level holds the largest
  // key below it, so a key one above that maximum is occluded over the node's samples. A node
  // left too large (a rescan not propagated, a parent not lowered) still gives exact pictures,
  // but culls less; this catches it. Two triangles first cover the whole buffer, so that no
  // sample stays clear.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto& size : std::vector<std::pair<int, int>>{{100, 70}, {200, 130}, {33, 130}}) {
    const int w = size.first, h = size.second;
    SCOPED_TRACE(std::to_string(w) + " x " + std::to_string(h));
    FrameBuffer fb;
    fb.resize(w, h);
    HzbRasterizer r;
    r.begin(fb);
    RenderStats stats;
    r.drawTriangle(makeTriangle(0, 0, w, 0, w, h, 1, 0.95), stats);
    r.drawTriangle(makeTriangle(0, 0, w, h, 0, h, 1, 0.95), stats);
    const int tiles = DepthPyramid::kTileSize;
    for (uint32_t i = 0; i < 120; ++i) {
      double p[6];
      for (int k = 0; k < 6; k += 2) p[k] = unit(rng) * w, p[k + 1] = unit(rng) * h;
      ScreenTriangle t = makeTriangle(p[0], p[1], p[2], p[3], p[4], p[5], 2 + i, 0.9 * unit(rng));
      if (orient2d(t.v[0], t.v[1], t.v[2]) < 0) std::swap(t.v[1], t.v[2]);
      t.plane.a = (unit(rng) - 0.5) * 0.002;
      if (orient2d(t.v[0], t.v[1], t.v[2]) <= 0) continue;
      r.drawTriangle(t, stats);
      for (int level = 0; level < r.pyramid().levelCount(); ++level) {
        const int span = tiles << level;  // samples per node side at this level
        for (int y0 = 0; y0 < h; y0 += span) {
          for (int x0 = 0; x0 < w; x0 += span) {
            const int x1 = std::min(x0 + span, w) - 1, y1 = std::min(y0 + span, h) - 1;
            DepthKey m = 0;
            for (int y = y0; y <= y1; ++y)
              for (int x = x0; x <= x1; ++x) m = std::max(m, fb.row(y)[x]);
            ASSERT_LT(m, kClearKey);
            ASSERT_TRUE(r.pyramid().occludes(x0, y0, x1, y1, m + 1, 1))
                << "triangle " << i << ", level " << level << ", node at " << x0 << ", " << y0;
            ASSERT_FALSE(r.pyramid().occludes(x0, y0, x1, y1, m, 1));
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace zrender
