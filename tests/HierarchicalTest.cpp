// `hierarchical` and `octree` against the z-buffer: bit-identical keys (depth + id) and colors
// on reference models, quads, concave polygons, random soups, off-screen and near-plane
// geometry, the crowd scene, every shading mode, culling off and MSAA 4. Plus the pieces on
// their own: the nearest-key bound, the pyramid's rejection and tie-break, the octree's
// structure and its counters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "FaceByFace.hpp"
#include "TestSupport.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/transform/FaceTransformer.hpp"
#include "zrender/visibility/HierarchicalAlgorithm.hpp"
#include "zrender/visibility/Octree.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

const std::vector<std::string> kAlgorithms = {"hierarchical", "octree"};

using test::coveredSamples;

struct Compared {
  size_t covered = 0;              // samples zbuffer covered
  std::vector<RenderStats> stats;  // per entry of kAlgorithms
};

// Renders `scene` with zbuffer and both pyramid algorithms; keys and colors must be equal.
Compared expectSameAsZBuffer(const Scene& scene, const std::string& what) {
  Compared out;
  const test::Rendered ref = test::render(scene, "zbuffer");
  out.covered = coveredSamples(ref.buffer);
  for (const std::string& alg : kAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    test::expectSameFrame(ref, r, alg + ", " + what);
    out.stats.push_back(r.stats);
  }
  return out;
}

Compared expectSameAsZBuffer(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                             const std::string& what) {
  Warnings warnings;
  const Scene scene = makeScene(settings, std::move(mesh));
  return expectSameAsZBuffer(scene, what);
}

// A reference scene of settings.json at a reduced size, or null (and the test skipped).
std::shared_ptr<const Mesh> referenceScene(const std::string& name, int size,
                                           SceneSettings& settings) {
  auto mesh = test::referenceModel(name);
  if (!mesh) return nullptr;
  settings = test::projectScene(name);
  settings.width = settings.height = size;
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// The pieces.

TEST(NearestKeyTest, IsABoundOfEverySampleKeyInTheRectangle) {
  // Random planes, including steep and nearly flat ones and ones that leave [0, 1], over
  // random rectangles: the bound never exceeds a sample's key, and is not far below it.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tight = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    DepthPlane p;
    const double scale = std::pow(10.0, -7.0 + 8.0 * unit(rng));
    p.a = (unit(rng) - 0.5) * scale;
    p.b = (unit(rng) - 0.5) * scale;
    p.c = unit(rng) * 1.2 - 0.1;
    const int x0 = int(unit(rng) * 1000), y0 = int(unit(rng) * 1000);
    const int x1 = x0 + int(unit(rng) * 40), y1 = y0 + int(unit(rng) * 40);
    const uint32_t id = uint32_t(unit(rng) * 1e6);
    const DepthKey bound = nearestKeyOver(p, id, x0, y0, x1, y1);
    DepthKey smallest = ~DepthKey(0);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        smallest = std::min(smallest, makeDepthKey(p.at(x, p.rowBase(y)), id));
    ASSERT_LE(bound, smallest) << "trial " << trial;
    tight += keyDepth(smallest) - keyDepth(bound) < 1e-6f;
  }
  EXPECT_GT(tight, 2900);  // the margin is a few ulps, not a loose bound
}

TEST(NearestKeyTest, NanPlaneBoundStaysBelowItsSamples) {
  // A NaN plane gives the face's farthest corner depth at every sample (DepthPlane's clamp);
  // the bound must not exceed that.
  DepthPlane p;
  p.a = std::nan("");
  p.loBits = int32_t(floatBits(0.25f));
  p.hiBits = int32_t(floatBits(0.75f));
  EXPECT_EQ(p.at(2, p.rowBase(1)), 0.75f);
  EXPECT_LE(nearestKeyOver(p, 5, 0, 0, 3, 3), makeDepthKey(0.75f, 5));
  EXPECT_GE(nearestKeyOver(p, 5, 0, 0, 3, 3), makeDepthKey(0.25f, 5));
}

// Draws one triangle (sample coordinates, positively oriented) through an HzbRasterizer.
ScreenTriangle makeTriangle(double x0, double y0, double x1, double y1, double x2, double y2,
                            uint32_t id, double depth) {
  ScreenTriangle t{};
  t.v[0] = FixedPoint{snapToSubpixel(x0), snapToSubpixel(y0)};
  t.v[1] = FixedPoint{snapToSubpixel(x1), snapToSubpixel(y1)};
  t.v[2] = FixedPoint{snapToSubpixel(x2), snapToSubpixel(y2)};
  t.id = id;
  t.plane.a = 0.0;
  t.plane.b = 0.0;
  t.plane.c = depth;
  return t;
}

// A 64 x 48 buffer behind a big occluder at depth 0.5 with id 7 (two triangles).
struct WalledBuffer {
  FrameBuffer fb;
  HzbRasterizer r;
  RenderStats stats;
  WalledBuffer() {
    fb.resize(64, 48);
    r.begin(fb);
    r.drawTriangle(makeTriangle(0, 0, 64, 0, 64, 48, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(0, 0, 64, 48, 0, 48, 7, 0.5), stats);
  }
};

TEST(HzbRasterizerTest, RejectsWhatIsBehindAndKeepsTies) {
  WalledBuffer w;
  FrameBuffer& fb = w.fb;
  HzbRasterizer& r = w.r;
  RenderStats& stats = w.stats;
  EXPECT_EQ(stats.trianglesRasterized, 2u);
  // Behind: rejected without pixel work.
  const uint64_t tested = stats.pixelsTested;
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 3, 0.75), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  EXPECT_EQ(stats.pixelsTested, tested);
  // Same depth, larger id: loses every tie (rejecting it is allowed, drawing it harmless).
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 9, 0.5), stats);
  const uint64_t culled = stats.trianglesHzbCulled;
  // Same depth, smaller id: wins every tie, so it must be drawn.
  r.drawTriangle(makeTriangle(5, 5, 30, 5, 30, 30, 2, 0.5), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, culled);
  // In front: drawn.
  r.drawTriangle(makeTriangle(40, 10, 60, 10, 60, 40, 11, 0.25), stats);
  EXPECT_EQ(stats.trianglesHzbCulled, culled);
  r.finish();
  EXPECT_EQ(keyFaceId(fb.row(6)[28]), 2u);
  EXPECT_EQ(keyFaceId(fb.row(30)[55]), 11u);
  EXPECT_EQ(keyFaceId(fb.row(40)[10]), 7u);
  // The farthest key left is (0.5, 7): a key at that depth with a larger id is hidden
  // everywhere, one with a smaller id nowhere.
  EXPECT_TRUE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.5f, 8)));
  EXPECT_FALSE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.5f, 6)));
  EXPECT_FALSE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.4f, 99)));
  EXPECT_TRUE(r.pyramid().occludes(0, 0, 63, 47, makeDepthKey(0.6f, 0)));
}

TEST(HzbRasterizerTest, BigTriangleWhoseNearCornerIsOffScreenIsRejectedByItsPlane) {
  // A wall at depth 0.5 over the whole image, then a triangle reaching far to the right of it
  // whose depth falls from 0.98 at x = 10 to 0.2 at x = 400: its nearest corner (0.2) is in
  // front of the wall, but in the image (x < 64) it is behind (depth > 0.87), which only its
  // plane over its sample bounds in the image shows.
  WalledBuffer w;
  FrameBuffer& fb = w.fb;
  HzbRasterizer& r = w.r;
  RenderStats& stats = w.stats;
  ScreenTriangle t = makeTriangle(10, 5, 400, 5, 10, 40, 3, 0.0);
  t.plane.a = -0.002;
  t.plane.c = 1.0;
  t.plane.loBits = int32_t(floatBits(0.19f));
  t.plane.hiBits = int32_t(floatBits(0.99f));
  const uint64_t tested = stats.pixelsTested;
  r.drawTriangle(t, stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  EXPECT_EQ(stats.pixelsTested, tested);
  // Nearer than the wall in the image (0.3 at its left end): drawn.
  t.plane.c = 0.3;
  t.plane.loBits = int32_t(floatBits(0.0f));
  r.drawTriangle(t, stats);
  EXPECT_EQ(stats.trianglesHzbCulled, 1u);
  r.finish();
  EXPECT_EQ(keyFaceId(fb.row(10)[20]), 3u);
}

TEST(DepthPyramidTest, VectorTileMaximumMatchesTheScalarOne) {
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

TEST(DepthPyramidTest, NodesBoundTheBufferAfterRandomWrites) {
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

TEST(DepthPyramidTest, EveryNodeIsExactAfterEveryTriangle) {
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

// A floor of n x n cells rising 0.05 per row, from z = -6 (far) to z = 4 (behind a tiny
// scene's eye), x in [-6, 6] (past the image's sides): quads, or with `mixed` two triangles in
// two cells of three.
void addTiltedFloor(int n, bool mixed, std::vector<Vec3>& p, std::vector<std::vector<int>>& f) {
  const int b = int(p.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      p.emplace_back(-6.0 + 12.0 * i / n, -0.6 + 0.05 * j, -6.0 + 10.0 * j / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = b + j * (n + 1) + i;
      if (mixed && (i + j) % 3 != 0) {
        f.push_back({a, a + 1, a + n + 2});
        f.push_back({a, a + n + 2, a + n + 1});
      } else {
        f.push_back({a, a + 1, a + n + 2, a + n + 1});
      }
    }
}

// Geometry as bytes-comparable fields: faces, vertices, triangles (corners, face, id, plane)
// and the counters.
void expectSameGeometry(const FrameGeometry& a, const FrameGeometry& b, const std::string& what) {
  ASSERT_EQ(a.faces.size(), b.faces.size()) << what;
  ASSERT_EQ(a.triangles.size(), b.triangles.size()) << what;
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
  for (size_t i = 0; i < a.faces.size(); ++i) {
    const ScreenFace &x = a.faces[i], &y = b.faces[i];
    EXPECT_TRUE(x.id == y.id && x.firstVertex == y.firstVertex && x.vertexCount == y.vertexCount &&
                x.firstTriangle == y.firstTriangle && x.triangleCount == y.triangleCount &&
                x.frontFacing == y.frontFacing)
        << what << ", face " << i;
  }
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]) << what;
  for (size_t i = 0; i < a.triangles.size(); ++i) {
    const ScreenTriangle &x = a.triangles[i], &y = b.triangles[i];
    EXPECT_TRUE(x.v[0] == y.v[0] && x.v[1] == y.v[1] && x.v[2] == y.v[2] && x.face == y.face &&
                x.id == y.id && x.plane.a == y.plane.a && x.plane.b == y.plane.b &&
                x.plane.c == y.plane.c && x.plane.loBits == y.plane.loBits &&
                x.plane.hiBits == y.plane.hiBits)
        << what << ", triangle " << i;
  }
  EXPECT_EQ(a.counters.backfaceCulled, b.counters.backfaceCulled) << what;
  EXPECT_EQ(a.counters.clippedAway, b.counters.clippedAway) << what;
  EXPECT_EQ(a.counters.degenerate, b.counters.degenerate) << what;
}

// A unit square in the z = 0 plane (raised by wave * sin(i + 2 j) at grid point (i, j)), cut
// into n x n cells facing +z: quads, or two triangles each.
void addTessellatedSquare(int n, bool quads, double wave, std::vector<Vec3>& p,
                          std::vector<std::vector<int>>& f) {
  const int b = int(p.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      p.emplace_back(-0.5 + double(i) / n, -0.5 + double(j) / n, wave * std::sin(i + 2.0 * j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = b + j * (n + 1) + i;
      if (quads) {
        f.push_back({a, a + 1, a + n + 2, a + n + 1});
      } else {
        f.push_back({a, a + 1, a + n + 2});
        f.push_back({a, a + n + 2, a + n + 1});
      }
    }
}

// The scene of the transform tests: quads, mixed triangles and a concave polygon on a floor
// that crosses the near plane and leaves the image, plus a face that snaps to fewer than three
// corners, in a grid of 3 x 1 x 2 instances.
Scene floorGridScene(SceneSettings& s) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTiltedFloor(12, true, p, f);
  const int b = int(p.size());
  p.insert(p.end(), {{-1.8, -1.0, 0.0},
                     {0.0, -1.6, 0.0},
                     {1.6, -1.0, 0.0},
                     {0.5, -0.8, -0.9},
                     {1.4, 0.8, 0.0},
                     {0.0, 0.1, 0.9},
                     {-1.4, 0.8, -0.4}});
  f.push_back({b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6});
  f.push_back({b + 6, b + 5, b + 4, b + 3, b + 2, b + 1, b});
  f.push_back({b, b, b + 1});  // snaps to fewer than three corners
  s = test::tinySettings(90);
  s.grid = Grid{{3, 1, 2}, {4.0, 0.0, 5.0}};
  Warnings warnings;
  return makeScene(s, test::makeMesh(p, f));
}

// The camera of floorGridScene()'s settings `s`, seen from `eye`.
Camera floorGridCamera(const SceneSettings& s, const Scene& scene, const Vec3& eye) {
  SceneSettings view = s;
  view.eye = eye;
  Warnings warnings;
  return makeCamera(makeScene(view, scene.mesh));
}

TEST(FaceTransformerTest, BatchesGiveWhatFaceByFaceGives) {
  // Quads and a concave polygon, on a floor that crosses the near plane and leaves the image,
  // in a grid of 3 x 1 x 2 instances; faces in a shuffled order cut into batches of random
  // sizes, two frames from different eyes. Each batch computes its own vertices, so a vertex
  // shared by batches is computed several times: every face must still come out as when it is
  // transformed on its own with the whole model's vertices.
  SceneSettings s;
  const Scene scene = floorGridScene(s);

  std::mt19937 rng(7);
  std::vector<uint32_t> order(scene.faceCount());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<uint32_t> batches = {0};
  while (batches.back() < order.size())
    batches.push_back(std::min(uint32_t(order.size()), batches.back() + 1 + uint32_t(rng() % 40)));

  for (bool cull : {true, false}) {
    test::FaceByFace byFace(scene, 1, cull);
    FaceTransformer byBatch(scene, 1, cull, FaceBatches{&order, &batches});
    for (const Vec3& eye : {Vec3(0.3, 0.2, 1.0), Vec3(-0.5, -0.3, 2.5)}) {
      const Camera camera = floorGridCamera(s, scene, eye);
      byFace.beginFrame(camera);
      byBatch.beginFrame(camera);
      FrameGeometry expected, actual;
      for (uint32_t id : order) byFace.transformFace(id, expected);
      for (uint32_t batch = 0; batch + 1 < batches.size(); ++batch)
        byBatch.pullBatch(batch, actual);
      // Not vacuous: many faces went through the whole path, some were clipped or dropped.
      EXPECT_GT(expected.triangles.size() + expected.counters.backfaceCulled, 300u);
      EXPECT_GT(expected.triangles.size(), 0u);
      EXPECT_GT(expected.counters.clippedAway + expected.counters.degenerate, 0u);
      expectSameGeometry(expected, actual, cull ? "culling" : "no culling");
    }
  }
}

TEST(FaceTransformerTest, InstancesGiveWhatFaceByFaceGives) {
  // Instances in a shuffled order, each with its vertices in arrays reused from one to the
  // next: a face of instance k (clipped ones included, which recompute clip coordinates from
  // the instance) must come out as when transformed on its own.
  SceneSettings s;
  const Scene scene = floorGridScene(s);
  const uint32_t nf = uint32_t(scene.mesh->faceCount());
  const std::vector<uint32_t> instances = {3, 0, 5, 1, 4, 2};
  for (bool cull : {true, false}) {
    test::FaceByFace byFace(scene, 1, cull);
    FaceTransformer byInstance(scene, 1, cull);
    for (const Vec3& eye : {Vec3(0.3, 0.2, 1.0), Vec3(-0.5, -0.3, 2.5)}) {
      const Camera camera = floorGridCamera(s, scene, eye);
      byFace.beginFrame(camera);
      byInstance.beginFrame(camera);
      FrameGeometry expected, actual;
      for (uint32_t k : instances) {
        for (uint32_t f = 0; f < nf; ++f) byFace.transformFace(k * nf + f, expected);
        byInstance.pullInstance(k, actual);
      }
      // Not vacuous: many faces went through the whole path, some were clipped or dropped.
      EXPECT_GT(expected.triangles.size() + expected.counters.backfaceCulled, 300u);
      EXPECT_GT(expected.triangles.size(), 0u);
      EXPECT_GT(expected.counters.clippedAway, 0u);
      expectSameGeometry(expected, actual, cull ? "culling" : "no culling");
    }
  }
}

TEST(FaceTransformerTest, InstancesWhollyOutsideTheViewAreOnlyCounted) {
  // A tessellated unit square facing the eye (plus a face of two corners), repeated in a row
  // across the view and in a column along it: instances beyond a side, behind the eye or
  // beyond the far plane are skipped whole, one straddling the right side is not, and every
  // face and counter comes out as when transformed face by face.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(4, true, 0.0, p, f);
  f.push_back({0, 1});
  const auto mesh = test::makeMesh(p, f);
  // Eye at z = 2 looking down -z, 90 degrees: at z = 0 the view spans x, y in [-2, 2].
  struct Case {
    Grid grid;
    std::vector<bool> outside;  // per instance
  };
  const std::vector<Case> cases = {
      // x = -9, -6, -3, 0, 3, 6, 9: all but the middle one beyond a side.
      {Grid{{7, 1, 1}, {3.0, 0.0, 0.0}}, {true, true, true, false, true, true, true}},
      // y = -3, 0, 3: below and above.
      {Grid{{1, 3, 1}, {0.0, 3.0, 0.0}}, {true, false, true}},
      // z = -10 (beyond the far plane at distance 10), -5, 0, 5 and 10 (behind the eye).
      {Grid{{1, 1, 5}, {0.0, 0.0, 5.0}}, {true, false, false, true, true}},
      // x = -2, 0, 2: the outer two straddle the sides.
      {Grid{{3, 1, 1}, {2.0, 0.0, 0.0}}, {false, false, false}},
  };
  Warnings warnings;
  for (const Case& c : cases) {
    SceneSettings s = test::tinySettings(64);
    s.grid = c.grid;
    const Scene scene = makeScene(s, mesh);
    const Camera camera = makeCamera(scene);
    const uint32_t nf = uint32_t(scene.mesh->faceCount());
    test::FaceByFace byFace(scene, camera, 1, true);
    FaceTransformer byInstance(scene, camera, 1, true);
    FrameGeometry expected, actual;
    ASSERT_EQ(scene.instanceCount(), c.outside.size());
    for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
      EXPECT_EQ(byInstance.viewOfInstance(k).outside, bool(c.outside[k])) << "instance " << k;
      for (uint32_t face = 0; face < nf; ++face) byFace.transformFace(k * nf + face, expected);
      byInstance.pullInstance(k, actual);
    }
    EXPECT_GT(expected.triangles.size(), 0u);
    EXPECT_GT(expected.counters.clippedAway, 0u);
    expectSameGeometry(expected, actual, "instances");
  }
}

TEST(FaceTransformerTest, InstanceNearestDepthBoundsEveryFaceTightly) {
  // Tessellated squares at several depths and tilts, seen from several eyes: no face of an
  // instance is nearer than viewOfInstance().nearest (its plane's least depth included), which
  // is within a millionth of the nearest corner of the instance's box; an instance reaching
  // past the near plane gets 0.
  // Flat and square-on too, where the box's nearest corners are vertices.
  Warnings warnings;
  int bounded = 0, zero = 0;
  for (double wave : {0.3, 0.0}) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> f;
    addTessellatedSquare(6, false, wave, p, f);
    const auto mesh = test::makeMesh(p, f);
    for (const Vec3& eye : {Vec3(0.0, 0.0, 3.0), Vec3(1.0, 0.7, 4.0), Vec3(-0.4, 0.2, 1.2)}) {
      SceneSettings s = test::tinySettings(96);
      s.grid = Grid{{2, 1, 4}, {0.7, 0.0, 0.9}};
      s.angle = wave > 0.0 ? 35.0 : 0.0;
      s.axis = Vec3(1.0, 1.0, 0.0);
      s.eye = eye;
      s.far = 50.0;
      const Scene scene = makeScene(s, mesh);
      const Camera camera = makeCamera(scene);
      const uint32_t nf = uint32_t(scene.mesh->faceCount());
      FaceTransformer t(scene, camera, 1, false);
      test::FaceByFace byFace(scene, camera, 1, false);
      for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
        const InstanceView view = t.viewOfInstance(k);
        const float nearest = view.nearest;
        const SampleRect& area = view.area;
        FrameGeometry g;
        for (uint32_t face = 0; face < nf; ++face) byFace.transformFace(k * nf + face, g);
        if (g.counters.clippedAway > 0) {  // reaches past the near plane or a side
          zero += nearest == 0.0f;
          continue;
        }
        for (const ScreenTriangle& tri : g.triangles) {
          ASSERT_LE(nearest, tri.plane.minDepth()) << "instance " << k;
          // And every sample it covers lies in the area.
          TriangleSetup b;
          if (!b.bounds(tri.v, 96, 96)) continue;
          EXPECT_TRUE(b.minX >= area.minX && b.maxX <= area.maxX && b.minY >= area.minY &&
                      b.maxY <= area.maxY)
              << "instance " << k;
        }
        ASSERT_FALSE(g.triangles.empty());
        double boxNearest = HUGE_VAL;
        for (int c = 0; c < 8; ++c) {
          Vec3 corner;
          for (int a = 0; a < 3; ++a) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (const Vec3& q : p) lo = std::min(lo, q[a]), hi = std::max(hi, q[a]);
            corner[a] = (c >> a & 1) ? hi : lo;
          }
          const Vec4 clip = t.modelViewProjection(k) * Vec4(corner[0], corner[1], corner[2], 1.0);
          boxNearest = std::min(boxNearest, (clip[2] / clip[3] + 1.0) * 0.5);
        }
        EXPECT_GT(nearest, 0.0f) << "instance " << k;
        EXPECT_LE(nearest, boxNearest) << "instance " << k;
        EXPECT_GT(nearest, boxNearest - 1e-6) << "instance " << k;
        ++bounded;
      }
    }
  }
  EXPECT_GT(bounded, 16);
  EXPECT_GT(zero, 0);
}

// Every instance of the scene (culling on), into `plain` without a filter and into `filtered`
// with `filter`.
void transformWithAndWithout(const Scene& scene, TriangleFilter& filter, FrameGeometry& plain,
                             FrameGeometry& filtered) {
  const Camera camera = makeCamera(scene);
  FaceTransformer without(scene, camera, 1, true), with(scene, camera, 1, true);
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    without.pullInstance(k, plain);
    with.pullInstance(k, filtered, &filter);
  }
}

// Marks the tiles of the left half of a 128-sample-wide image as hidden, for every instance.
class LeftHalfFilter : public TriangleFilter {
 public:
  std::vector<uint8_t> marked = std::vector<uint8_t>(8 * 8, 0);
  std::vector<float> bounds;  // what beginInstance() was told
  LeftHalfFilter() {
    for (int ty = 0; ty < 8; ++ty)
      for (int tx = 0; tx < 4; ++tx) marked[size_t(ty * 8 + tx)] = 1;
  }
  HiddenTiles beginInstance(float nearestDepth, const SampleRect& /*area*/) override {
    bounds.push_back(nearestDepth);
    return HiddenTiles{marked.data(), 4, 8};
  }
  bool hidden(const FixedPoint*, float, uint32_t) override { return false; }
};

TEST(FaceTransformerTest, FacesInHiddenTilesAreDroppedBeforeTheirDepths) {
  // A grid of tessellated squares in front of the eye, on a 128 x 128 image of 8 x 8 tiles
  // whose left half the filter marks: a face whose sample bounds lie in at most 2 x 2 marked
  // tiles is dropped and counted as filtered, every other face comes out as without the filter.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(7, false, 0.0, p,
                       f);  // odd: faces of the middle square straddle the image centre
  SceneSettings s = test::tinySettings(128);
  s.grid = Grid{{3, 2, 1}, {1.2, 1.2, 0.0}};
  s.eye = Vec3(0.0, 0.0, 2.5);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  LeftHalfFilter filter;
  FrameGeometry expected, actual;
  transformWithAndWithout(scene, filter, expected, actual);
  EXPECT_EQ(filter.bounds.size(), scene.instanceCount());
  for (float b : filter.bounds) EXPECT_GT(b, 0.0f);
  std::map<uint32_t, size_t> kept;
  for (size_t i = 0; i < actual.faces.size(); ++i) kept[actual.faces[i].id] = i;
  uint64_t dropped = 0, straddling = 0;
  for (const ScreenFace& face : expected.faces) {
    const ScreenTriangle& t = expected.triangles[face.firstTriangle];
    TriangleSetup bounds;
    ASSERT_TRUE(bounds.bounds(t.v, 128, 128));
    const bool inLeft = (bounds.maxX >> 4) < 4;
    const bool small = (bounds.maxX >> 4) - (bounds.minX >> 4) <= 1 &&
                       (bounds.maxY >> 4) - (bounds.minY >> 4) <= 1;
    if (inLeft && small) {
      EXPECT_EQ(kept.count(face.id), 0u) << face.id;
      ++dropped;
      continue;
    }
    straddling += (bounds.minX >> 4) < 4;
    ASSERT_EQ(kept.count(face.id), 1u) << face.id;
    const ScreenTriangle& u = actual.triangles[actual.faces[kept[face.id]].firstTriangle];
    EXPECT_TRUE(t.v[0] == u.v[0] && t.v[1] == u.v[1] && t.v[2] == u.v[2] &&
                t.plane.loBits == u.plane.loBits && t.plane.c == u.plane.c);
  }
  EXPECT_GT(dropped, 50u);
  EXPECT_GT(straddling, 5u);
  EXPECT_EQ(actual.counters.filtered, dropped);
  EXPECT_EQ(actual.faces.size(), expected.faces.size() - dropped);
  EXPECT_EQ(expected.counters.filtered, 0u);
}

TEST(FaceTransformerTest, TrianglesCoveringNoSampleCentreAreDroppedBeforeTheirPlane) {
  // 8 x 8 pixels over [-2, 2]^2 at z = 0: pixel column (x + 2) * 2, row (2 - y) * 2, sample
  // centres at half pixels. Face 0 spans columns 4.1-4.4 and rows 3.6-3.9: no centre. Face 1
  // (bigger) covers the centre of pixel (4, 4), at (0.25, -0.25). Both are front-facing and
  // inside the view volume.
  std::vector<Vec3> p = {{0.05, 0.05, 0.0}, {0.2, 0.05, 0.0}, {0.05, 0.2, 0.0},
                         {-0.2, -0.6, 0.0}, {0.8, -0.6, 0.0}, {-0.2, 0.4, 0.0}};
  const std::vector<std::vector<int>> f = {{0, 1, 2}, {3, 4, 5}};
  const SceneSettings s = test::tinySettings(8);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  FaceTransformer transformer(scene, makeCamera(scene), 1, true);
  FrameGeometry g;
  transformer.pullInstance(0, g);
  ASSERT_EQ(g.faces.size(), 1u);  // no plane set up, nothing stored for face 0
  EXPECT_EQ(g.faces[0].id, 1u);
  // Counted nowhere, as the z-buffer's set-up never counted them.
  EXPECT_EQ(g.counters.degenerate + g.counters.backfaceCulled + g.counters.clippedAway, 0u);
  // The same faces one at a time (the general path) agree.
  FrameGeometry one;
  test::FaceByFace byFace(scene, makeCamera(scene), 1, true);
  for (uint32_t id = 0; id < 2; ++id) byFace.transformFace(id, one);
  ASSERT_EQ(one.faces.size(), 1u);
  EXPECT_EQ(one.faces[0].id, 1u);
  // And no algorithm draws face 0, while face 1 owns the sample it covers.
  for (const char* alg : {"zbuffer", "scanline", "interval", "hierarchical", "octree"}) {
    const test::Rendered r = test::render(scene, alg);
    EXPECT_EQ(keyFaceId(r.buffer.row(4)[4]), 1u) << alg;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) EXPECT_NE(keyFaceId(r.buffer.row(y)[x]), 0u) << alg;
  }
}

// Drops every third face it is asked about and remembers what it was told.
class RecordingFilter : public TriangleFilter {
 public:
  struct Asked {
    FixedPoint v[3];
    float nearestDepth;
  };
  std::map<uint32_t, Asked> asked;
  bool hidden(const FixedPoint* v, float nearestDepth, uint32_t faceId) override {
    asked[faceId] = Asked{{v[0], v[1], v[2]}, nearestDepth};
    return faceId % 3 == 0;
  }
};

TEST(FaceTransformerTest, FilterSeesTheFaceAsDrawnAndDropsOnlyWhatItRejects) {
  SceneSettings s;
  const Scene scene = floorGridScene(s);
  RecordingFilter filter;
  FrameGeometry expected, actual;
  transformWithAndWithout(scene, filter, expected, actual);
  std::map<uint32_t, size_t> actualFace;
  for (size_t i = 0; i < actual.faces.size(); ++i) actualFace[actual.faces[i].id] = i;
  size_t dropped = 0, keptAsked = 0, notAsked = 0;
  for (const ScreenFace& face : expected.faces) {
    const auto asked = filter.asked.find(face.id);
    const auto kept = actualFace.find(face.id);
    if (asked != filter.asked.end() && face.id % 3 == 0) {
      EXPECT_TRUE(kept == actualFace.end()) << "face " << face.id << " was rejected";
      ++dropped;
      continue;
    }
    ASSERT_TRUE(kept != actualFace.end()) << "face " << face.id;
    const ScreenFace& other = actual.faces[kept->second];
    ASSERT_EQ(face.triangleCount, other.triangleCount);
    for (uint32_t t = 0; t < face.triangleCount; ++t) {
      const ScreenTriangle& x = expected.triangles[face.firstTriangle + t];
      const ScreenTriangle& y = actual.triangles[other.firstTriangle + t];
      EXPECT_TRUE(x.v[0] == y.v[0] && x.v[1] == y.v[1] && x.v[2] == y.v[2] && x.id == y.id &&
                  x.plane.loBits == y.plane.loBits && x.plane.c == y.plane.c)
          << face.id;
    }
    if (asked == filter.asked.end()) {
      ++notAsked;  // polygons and clipped faces take the general path
      continue;
    }
    ++keptAsked;
    // What the filter was told is what the pixel loops get: the corners, and the nearest
    // corner depth as the plane's clamp holds it, bit for bit.
    const ScreenTriangle& t = expected.triangles[face.firstTriangle];
    EXPECT_EQ(floatBits(asked->second.nearestDepth), uint32_t(t.plane.loBits)) << face.id;
    std::set<std::pair<int32_t, int32_t>> told, drawn;
    for (int i = 0; i < 3; ++i) {
      told.insert({asked->second.v[i].x, asked->second.v[i].y});
      drawn.insert({t.v[i].x, t.v[i].y});
    }
    EXPECT_EQ(told, drawn) << face.id;
  }
  // Faces that cover no sample centre (small ones, between centres) are dropped before the
  // filter is asked: here 17 dropped and 39 kept of those asked.
  EXPECT_GT(dropped, 10u);
  EXPECT_GT(keptAsked, 25u);
  EXPECT_GT(notAsked, 10u);
  EXPECT_EQ(actual.faces.size(), expected.faces.size() - dropped);
  EXPECT_EQ(expected.counters.backfaceCulled, actual.counters.backfaceCulled);
}

TEST(OctreeTest, EveryFaceOnceAndInsideItsNodes) {
  // Three instances of a random soup, rotated: every face id appears once, every node's box
  // holds its faces' corners, and children split their parent's face range.
  SceneSettings s = test::tinySettings(64);
  s.angle = 30.0;
  s.axis = Vec3(1, 2, 3);
  s.grid = Grid{{3, 1, 1}, Vec3(2.5, 0, 0)};
  Warnings warnings;
  const Scene scene = makeScene(s, test::randomSoup(11, 700, false));
  Octree tree;
  tree.build(scene);
  ASSERT_FALSE(tree.empty());
  std::vector<uint32_t> ids = tree.faces();
  std::sort(ids.begin(), ids.end());
  ASSERT_EQ(ids.size(), size_t(scene.faceCount()));
  for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i);

  const Mesh& mesh = *scene.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  size_t leaves = 0;
  for (const OctreeNode& node : tree.nodes()) {
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const uint32_t id = tree.faces()[i];
      const Mat4 m = scene.modelMatrix(id / nf);
      const Corner* c = mesh.faceCorners(id % nf);
      for (uint32_t j = 0; j < mesh.cornerCount(id % nf); ++j) {
        const Vec3 p = transformPoint(m, mesh.positions[size_t(c[j].position)]);
        for (int a = 0; a < 3; ++a) {
          ASSERT_LE(node.lo[a], p[a]);
          ASSERT_GE(node.hi[a], p[a]);
        }
      }
    }
    if (node.childMask == 0) {
      ++leaves;
      continue;
    }
    uint32_t next = node.faceBegin;
    const int children = __builtin_popcount(node.childMask);
    for (int k = 0; k < children; ++k) {
      const OctreeNode& child = tree.nodes()[node.firstChild + uint32_t(k)];
      EXPECT_EQ(child.faceBegin, next);
      EXPECT_LT(child.faceBegin, child.faceEnd);
      next = child.faceEnd;
    }
    EXPECT_EQ(next, node.faceEnd);
  }
  EXPECT_GT(leaves, 8u);
}

TEST(OctreeTest, LeafSizeBoundsEveryLeaf) {
  // Leaves hold at most the faces asked for; smaller leaves make more of them. 700 random
  // faces have distinct centroids, far from kMaxDepth's cells, so the bound is never waived.
  Warnings warnings;
  const Scene scene = makeScene(test::tinySettings(64), test::randomSoup(12, 700, false));
  auto leafSizes = [&scene](uint32_t leafFaces) {
    Octree tree;
    tree.build(scene, leafFaces);
    std::vector<uint32_t> sizes;
    for (const OctreeNode& node : tree.nodes())
      if (node.childMask == 0) sizes.push_back(node.faceEnd - node.faceBegin);
    return sizes;
  };
  const std::vector<uint32_t> small = leafSizes(8), big = leafSizes(Octree::kLeafFaces);
  EXPECT_LE(*std::max_element(small.begin(), small.end()), 8u);
  EXPECT_GT(*std::max_element(big.begin(), big.end()), 8u);
  EXPECT_GT(small.size(), 4 * big.size());
}

// Faces 0 and 1 of `scene` (a wall) drawn into a fresh buffer and its z-pyramid.
struct WallPyramid {
  FrameBuffer fb;
  HzbRasterizer r;
  WallPyramid(const Scene& scene, const Camera& camera) {
    test::FaceByFace transformer(scene, camera, 1, false);
    FrameGeometry wall;
    transformer.transformFace(0, wall);
    transformer.transformFace(1, wall);
    fb.resize(wall.width, wall.height);
    r.begin(fb);
    RenderStats stats;
    for (const ScreenTriangle& t : wall.triangles) r.drawTriangle(t, stats);
  }
  WallPyramid(const WallPyramid&) = delete;  // r points into fb
  WallPyramid& operator=(const WallPyramid&) = delete;
};

TEST(OctreeTest, HiddenNodesHoldNoVisibleFace) {
  // A wall (faces 0, 1) with clusters of small triangles just in front of and just behind it,
  // and more far behind. Against a pyramid of the wall alone, every node the test calls
  // hidden must hold only faces that the z-buffer of the whole scene does not show.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p = {{-2.2, -2.2, 0.0}, {2.2, -2.2, 0.0}, {2.2, 2.2, 0.0}, {-2.2, 2.2, 0.0}};
  std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
  for (int cluster = 0; cluster < 300; ++cluster) {
    const bool far = cluster % 2 == 1;
    const Vec3 c(1.8 * u(rng), 1.8 * u(rng), far ? -4.0 + u(rng) : 0.05 * u(rng));
    for (int i = 0; i < 20; ++i) {
      const int b = int(p.size());
      for (int k = 0; k < 3; ++k) p.push_back(c + Vec3(0.1 * u(rng), 0.1 * u(rng), 0.01 * u(rng)));
      f.push_back({b, b + 1, b + 2});
    }
  }
  SceneSettings s = test::tinySettings(512);
  s.cull = false;
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  const test::Rendered ref = test::render(scene, "zbuffer");
  std::vector<bool> shown(scene.faceCount(), false);
  for (size_t i = 0; i < ref.buffer.size(); ++i)
    if (keyFaceId(ref.buffer.data()[i]) != kBackgroundId)
      shown[keyFaceId(ref.buffer.data()[i])] = true;

  const Camera camera = makeCamera(scene);
  const WallPyramid wall(scene, camera);

  Octree tree;
  tree.build(scene);
  const OctreeNodeTest test(camera, wall.fb.width(), wall.fb.height());
  int hiddenNodes = 0, hiddenFaces = 0;
  for (const OctreeNode& node : tree.nodes()) {
    if (!test.hidden(node, wall.r.pyramid())) continue;
    ++hiddenNodes;
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      ASSERT_FALSE(shown[tree.faces()[i]]) << "face " << tree.faces()[i] << " is visible";
      ++hiddenFaces;
    }
  }
  EXPECT_GT(hiddenNodes, 0);
  EXPECT_GT(hiddenFaces, 1000);
}

TEST(OctreeTest, NodeOnTheOccluderIsNotHidden) {
  // The node test allows for rounding by lowering the box's nearest depth; lowering it, not
  // raising it, is what keeps it exact. A wall at z = 0 (faces 0, 1, 4 x 4 units) fills a
  // 64 x 64 pyramid; flat boxes 1 x 1 at z = 0 (on the wall: a face there ties with it, so must
  // be kept), at z = 1e-5 (in front) and at z = -0.01 (behind) are tested.
  SceneSettings s = test::tinySettings(64);
  Warnings warnings;
  const Scene scene = makeScene(
      s, test::makeMesh({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, {{0, 1, 2}, {0, 2, 3}}));
  const Camera camera = makeCamera(scene);
  const WallPyramid wall(scene, camera);
  const OctreeNodeTest test(camera, wall.fb.width(), wall.fb.height());
  const auto flatNode = [](float z) {
    OctreeNode node{};
    for (int a = 0; a < 2; ++a) node.lo[a] = -0.5f, node.hi[a] = 0.5f;
    node.lo[2] = node.hi[2] = z;
    return node;
  };
  EXPECT_FALSE(test.hidden(flatNode(0.0f), wall.r.pyramid()));
  EXPECT_FALSE(test.hidden(flatNode(1e-5f), wall.r.pyramid()));
  EXPECT_TRUE(test.hidden(flatNode(-0.01f), wall.r.pyramid()));
}

TEST(OctreeTest, NodeWhoseEdgeSnapsOntoAClearSampleIsNotHidden) {
  // A flat box at z = -0.5 (2.5 units from the eye of a 64 x 64 tiny scene, window x =
  // (X / 2.5 + 1) * 32) whose left side projects to window x = 15.5 + 1.3e-6: a face with a
  // corner there snaps to x = 15.5 (1/256 sample grid) and, as a left edge, covers the centre
  // of sample column 15, the last of the first column of 16 x 16 pyramid tiles. An occluder
  // at depth 0.5 covers every sample but that column, so the node must be kept; with the
  // column covered too, it is hidden.
  SceneSettings s = test::tinySettings(64);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  const Camera camera = makeCamera(scene);
  OctreeNode node{};
  node.lo[0] = float((15.5 / 32.0 - 1.0) * 2.5 + 1e-7);
  node.hi[0] = 0.5f;
  node.lo[1] = -0.5f, node.hi[1] = 0.5f;
  node.lo[2] = node.hi[2] = -0.5f;
  const auto hiddenBehind = [&](bool coverColumn15) {
    FrameBuffer fb;
    fb.resize(64, 64);
    HzbRasterizer r;
    r.begin(fb);
    RenderStats stats;
    // Samples 0..14 (centres up to 14.5 < 15), and 16..63 (centres from 16.5 > 16) or 15..63.
    const double right = coverColumn15 ? 15 : 16;
    r.drawTriangle(makeTriangle(0, 0, 15, 0, 15, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(0, 0, 15, 64, 0, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(right, 0, 64, 0, 64, 64, 7, 0.5), stats);
    r.drawTriangle(makeTriangle(right, 0, 64, 64, right, 64, 7, 0.5), stats);
    EXPECT_EQ(keyFaceId(fb.row(30)[15]) == 7, coverColumn15);
    EXPECT_EQ(keyFaceId(fb.row(30)[14]), 7u);
    EXPECT_EQ(keyFaceId(fb.row(30)[16]), 7u);
    return OctreeNodeTest(camera, 64, 64).hidden(node, r.pyramid());
  };
  EXPECT_FALSE(hiddenBehind(false));
  EXPECT_TRUE(hiddenBehind(true));
}

// ---------------------------------------------------------------------------------------------
// Whole frames against the z-buffer.

TEST(HierarchicalExactTest, ReferenceModels) {
  for (const std::string name : {"bunny", "spot", "teapot"}) {
    SceneSettings s;
    auto mesh = referenceScene(name, 360, s);
    if (!mesh) GTEST_SKIP() << name << " not linked under models/";
    const Compared c = expectSameAsZBuffer(mesh, s, name);
    EXPECT_GT(c.covered, 1000u) << name;
  }
}

TEST(HierarchicalExactTest, BunnyMsaaAndNoCull) {
  SceneSettings s;
  auto mesh = referenceScene("bunny", 240, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.msaa = 4;
  expectSameAsZBuffer(mesh, s, "msaa 4");
  s.cull = false;
  expectSameAsZBuffer(mesh, s, "msaa 4, no cull");
  s.msaa = 1;
  expectSameAsZBuffer(mesh, s, "no cull");
}

TEST(HierarchicalExactTest, EveryShadingMode) {
  SceneSettings s;
  auto mesh = referenceScene("spot", 200, s);
  if (!mesh) GTEST_SKIP() << "spot not linked under models/";
  for (const std::string& mode : shadingModeNames()) {
    s.shading = *parseShadingMode(mode);
    expectSameAsZBuffer(mesh, s, "shading " + mode);
  }
}

TEST(HierarchicalExactTest, QuadsAndConcavePolygon) {
  // Overlapping quads at different depths and tilts, and a concave (arrow-shaped) polygon that
  // pierces them.
  std::vector<Vec3> p = {{-1.5, -1.5, -0.5}, {1.0, -1.5, -0.3}, {1.0, 1.0, -0.1}, {-1.5, 1.0, -0.3},
                         {-0.5, -0.5, 0.2},  {1.8, -0.5, -0.6}, {1.8, 1.8, -0.6}, {-0.5, 1.8, 0.2},
                         {-1.8, -1.0, 0.0},  {0.0, -1.6, 0.0},  {1.6, -1.0, 0.0}, {0.5, -0.8, -0.9},
                         {1.4, 0.8, 0.0},    {0.0, 0.1, 0.9},   {-1.4, 0.8, -0.4}};
  std::vector<std::vector<int>> f = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11, 12, 13, 14}};
  for (bool cull : {true, false}) {
    SceneSettings s = test::tinySettings(97);
    s.cull = cull;
    const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "quads");
    EXPECT_GT(c.covered, 2000u);
  }
}

TEST(HierarchicalExactTest, RandomSoupsWithCoplanarDuplicates) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    SceneSettings s = test::tinySettings(80 + int(seed) * 7);
    s.cull = false;
    s.msaa = seed % 2 ? 1 : 4;
    const Compared c =
        expectSameAsZBuffer(test::randomSoup(seed, 400, true), s, "soup " + std::to_string(seed));
    EXPECT_GT(c.covered, 1000u);
  }
}

TEST(HierarchicalExactTest, OctreeOfAnyLeafSize) {
  // The leaf size only moves where node tests happen; small leaves test far more nodes.
  for (uint32_t leafFaces : {1u, 4u, 32u}) {
    SceneSettings s = test::tinySettings(96);
    s.cull = false;
    Warnings warnings;
    const Scene scene = makeScene(s, test::randomSoup(6, 400, true));
    Renderer ref(scene, "zbuffer");
    Renderer octree(scene, std::make_unique<OctreeAlgorithm>(leafFaces));
    ref.renderFrame(makeCamera(scene));
    octree.renderFrame(makeCamera(scene));
    EXPECT_TRUE(identicalFrames(ref.buffer(), ref.color(), octree.buffer(), octree.color()))
        << "leaves of " << leafFaces;
    EXPECT_GT(test::coveredSamples(ref.buffer()), 1000u);
  }
}

TEST(HierarchicalExactTest, NearPlaneAndOffScreen) {
  // A tilted floor that runs from far away to behind the eye and past the image's sides, with
  // posts standing on it; and the bunny seen from inside itself.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTiltedFloor(24, false, p, f);
  for (int k = 0; k < 6; ++k) {
    const int b = int(p.size());
    const double x = -2.5 + k, z = -3.0 + 0.8 * k;
    p.insert(p.end(), {{x, -0.7, z}, {x + 0.4, -0.7, z}, {x + 0.4, 1.5, z}, {x, 1.5, z}});
    f.push_back({b, b + 1, b + 2, b + 3});
  }
  for (bool cull : {true, false}) {
    SceneSettings s = test::tinySettings(90);
    s.cull = cull;
    s.eye = Vec3(0.3, 0.2, 1.0);
    const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "floor");
    EXPECT_GT(c.covered, 1000u);
  }

  SceneSettings s;
  auto mesh = referenceScene("bunny", 200, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.eye = Vec3(-0.02, 0.11, 0.02);
  s.target = Vec3(0.1, 0.12, -0.1);
  s.fovy = 80.0;
  s.near = 0.005;
  s.cull = false;
  const Compared c = expectSameAsZBuffer(mesh, s, "inside the bunny");
  EXPECT_GT(c.covered, 1000u);
}

TEST(HierarchicalExactTest, BigOccluderIsRejectedByThePyramid) {
  // A near quad (faces 0, 1: first in id order) hides a far grid of small quads.
  std::vector<Vec3> p = {{-1.9, -1.9, 0.5}, {1.9, -1.9, 0.5}, {1.9, 1.9, 0.5}, {-1.9, 1.9, 0.5}};
  std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
  const int n = 20;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(-1.5 + 3.0 * i / n, -1.5 + 3.0 * j / n, -1.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = 4 + j * (n + 1) + i;
      f.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  SceneSettings s = test::tinySettings(128);
  const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "occluder");
  for (size_t k = 0; k < kAlgorithms.size(); ++k) {
    SCOPED_TRACE(kAlgorithms[k]);
    EXPECT_GT(c.stats[k].trianglesHzbCulled + c.stats[k].octreeNodesCulled, 0u);
  }
  EXPECT_GE(c.stats[0].trianglesHzbCulled, 2u * n * n - 40u);  // hierarchical: nearly all
}

TEST(HierarchicalExactTest, SliversBehindAnOccluder) {
  // Thousands of thin, randomly tilted slivers (some nearly edge-on, whose depth planes are
  // extrapolated steeply at snapped samples) behind a quad that hides them, from just behind
  // it to far enough that the octree rejects their nodes: neither the pyramid's bounds nor
  // the octree's node margin may lose a sample the z-buffer draws.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  uint64_t nodesCulled = 0, trianglesCulled = 0;
  for (double gap : {1e-4, 1e-2, 1.0, 4.0}) {
    std::vector<Vec3> p = {{-1.6, -1.6, 1.2}, {1.6, -1.6, 1.2}, {1.6, 1.6, 1.2}, {-1.6, 1.6, 1.2}};
    std::vector<std::vector<int>> f = {{0, 1, 2}, {0, 2, 3}};
    for (int i = 0; i < 3000; ++i) {
      const double z = 1.2 - gap - 0.01 * (u(rng) + 1.0);
      const double spread = 0.3 * (2.0 - z);  // stay inside the quad's shadow
      const Vec3 c(spread * u(rng), spread * u(rng), z);
      Vec3 along(u(rng), u(rng), u(rng)), across(u(rng), u(rng), u(rng));
      along *= 0.06 / cv::norm(along);
      across = along.cross(across);
      across *= 1e-4 / std::max(cv::norm(across), 1e-12);
      const int b = int(p.size());
      p.insert(p.end(), {c - along, c + along + across, c + along - across});
      f.push_back({b, b + 1, b + 2});
    }
    SceneSettings s = test::tinySettings(300);
    s.cull = false;
    s.near = 0.5;
    s.msaa = gap < 1e-3 ? 4 : 1;
    const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "gap " + std::to_string(gap));
    trianglesCulled += c.stats[0].trianglesHzbCulled;
    nodesCulled += c.stats[1].octreeNodesCulled;
  }
  EXPECT_GT(trianglesCulled, 5000u);
  EXPECT_GT(nodesCulled, 0u);
}

TEST(HierarchicalExactTest, DenseInterleavedClusters) {
  // Hundreds of small clusters of triangles at nearby depths, partly in front of each other:
  // octree nodes are tested against a pyramid built from geometry just in front of them, so
  // a node test that is not conservative by even a small depth loses visible faces here.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  for (int cluster = 0; cluster < 500; ++cluster) {
    const Vec3 c(1.4 * u(rng), 1.4 * u(rng), 0.4 * u(rng));
    for (int i = 0; i < 24; ++i) {
      const int b = int(p.size());
      for (int k = 0; k < 3; ++k)
        p.push_back(c + Vec3(0.12 * u(rng), 0.12 * u(rng), 0.02 * u(rng)));
      f.push_back({b, b + 1, b + 2});
    }
  }
  SceneSettings s = test::tinySettings(320);
  s.cull = false;
  const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "clusters");
  EXPECT_GT(c.stats[0].trianglesHzbCulled, 30u);
}

TEST(HierarchicalExactTest, CoplanarTiesWithSmallerIdBehind) {
  // Two identical coplanar quads; the one drawn first has the larger id, so at equal depth
  // the later, smaller id must still be drawn (and win every sample).
  std::vector<Vec3> p = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  // Face 0 and 1 are the same quad; faces 2.. repeat it so many ids tie.
  std::vector<std::vector<int>> f = {{0, 1, 2, 3}, {0, 1, 2, 3}, {1, 2, 3, 0}, {2, 3, 0, 1}};
  SceneSettings s = test::tinySettings(64);
  const Compared c = expectSameAsZBuffer(test::makeMesh(p, f), s, "coplanar");
  EXPECT_GT(c.covered, 500u);
  const test::Rendered r = test::render(test::makeMesh(p, f), s, "hierarchical");
  EXPECT_EQ(keyFaceId(r.buffer.row(32)[32]), 0u);
}

TEST(HierarchicalExactTest, NearestInstanceFirstHidesTheOthersBeforeTheirSetUp) {
  // A tessellated square (200 triangles) in a row of four instances along z, numbered far to
  // near as the eye sees them: the nearest is drawn first, and every triangle of the three
  // behind it is proved hidden (most already in the transform, without set-up).
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(10, false, 0.0, p, f);
  SceneSettings s = test::tinySettings(128);
  s.grid = Grid{{1, 1, 4}, {0.0, 0.0, 0.5}};  // z = -0.75, -0.25, 0.25, 0.75
  // The last instance is the nearest and covers two thirds of the image, all of the tiles the
  // others reach.
  s.eye = Vec3(0.0, 0.0, 1.5);
  s.target = Vec3(0.0, 0.0, 0.0);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  const Compared c = expectSameAsZBuffer(scene, "row of squares");
  const RenderStats& h = c.stats[0];
  EXPECT_GT(c.covered, 4000u);
  EXPECT_EQ(h.trianglesRasterized, 200u);
  EXPECT_EQ(h.trianglesHzbCulled, 600u);
  // Those of the instances behind never reached the frame's geometry.
  Renderer renderer(scene, "hierarchical");
  renderer.renderFrame(makeCamera(scene));
  EXPECT_EQ(renderer.geometry().triangles.size(), 200u);
}

TEST(HierarchicalExactTest, CrowdSmall) {
  SceneSettings s;
  auto mesh = referenceScene("crowd", 200, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  const Compared c = expectSameAsZBuffer(mesh, s, "crowd 200");
  EXPECT_GT(c.covered, 5000u);
  const RenderStats& octree = c.stats[1];
  EXPECT_GT(octree.octreeNodesVisited, 0u);
  EXPECT_GT(octree.octreeNodesCulled, 0u);
  EXPECT_GT(octree.trianglesHzbCulled, 0u);
  EXPECT_GT(c.stats[0].trianglesHzbCulled, 0u);
  // The octree transforms only what its visible nodes hold.
  EXPECT_LT(octree.trianglesRasterized + octree.trianglesHzbCulled,
            c.stats[0].trianglesRasterized + c.stats[0].trianglesHzbCulled);
}

TEST(HierarchicalExactTest, CrowdVariants) {
  // A smaller grid for the option variants: MSAA 4, no culling, another view from the side.
  SceneSettings s;
  auto mesh = referenceScene("crowd", 150, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.grid->count = {4, 1, 4};
  s.msaa = 4;
  expectSameAsZBuffer(mesh, s, "crowd 4x4 msaa 4");
  s.msaa = 1;
  s.cull = false;
  expectSameAsZBuffer(mesh, s, "crowd 4x4 no cull");
  s.cull = true;
  s.eye = Vec3(1.2, 0.5, 0.3);
  s.target = Vec3(0.0, 0.1, 0.0);
  expectSameAsZBuffer(mesh, s, "crowd 4x4 side");
}

}  // namespace
}  // namespace zrender
