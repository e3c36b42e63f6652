// The fill rule and depth rules of SPEC §5, checked against an independent oracle: a sample
// is covered when its centre, nudged by (2^-16, 2^-32) of a 1/256 unit, lies inside the polygon
// by the even-odd rule, evaluated exactly in 128-bit integers. For coordinates below 2^12
// units that nudge is small enough to be the infinitesimal (e, e^2) of the top-left rule.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "TestSupport.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/raster/TriangleFill.hpp"
#include "zrender/transform/Triangulation.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

namespace zrender {
namespace {

using Polygon = std::vector<FixedPoint>;

bool oracleCovers(const Polygon& poly, int i, int j) {
  const __int128 s = __int128(1) << 32;
  const __int128 px = __int128(sampleCentre(i)) * s + (__int128(1) << 16);
  const __int128 py = __int128(sampleCentre(j)) * s + 1;
  bool inside = false;
  for (size_t k = 0; k < poly.size(); ++k) {
    const FixedPoint& a = poly[k];
    const FixedPoint& b = poly[(k + 1) % poly.size()];
    const __int128 ax = a.x * s, ay = a.y * s, bx = b.x * s, by = b.y * s;
    if ((ay > py) == (by > py)) continue;
    const __int128 lhs = (px - ax) * (by - ay), rhs = (py - ay) * (bx - ax);
    if (by > ay ? lhs > rhs : lhs < rhs) inside = !inside;  // crossing left of the point
  }
  return inside;
}

// Adds 1 to `count` for every sample the shared TriangleSetup says the triangle covers.
void addCoverage(const FixedPoint v[3], int size, std::vector<int>& count) {
  TriangleSetup s;
  if (!s.setup(v, size, size)) return;
  for (int y = s.minY; y <= s.maxY; ++y) {
    for (int x = s.minX; x <= s.maxX; ++x) {
      bool in = true;
      for (const EdgeFunction& e : s.edge)
        in &= e.covers(e.value + e.stepX * (x - s.minX) + e.stepY * (y - s.minY));
      count[size_t(y) * size + x] += in;
    }
  }
}

// Positively oriented copy of a triangle.
std::array<FixedPoint, 3> oriented(FixedPoint a, FixedPoint b, FixedPoint c) {
  if (orient2d(a, b, c) < 0) std::swap(b, c);
  return {a, b, c};
}

constexpr int kSize = 16;  // samples; coordinates stay below 16 * 256 = 2^12 units

FixedPoint randomPoint(std::mt19937& rng) {
  std::uniform_int_distribution<int32_t> d(0, kSize * kSubpixel);
  return {d(rng), d(rng)};
}

TEST(FillRule, SampleRangeOfAnIntervalIsTheCentresInIt) {
  // The first and last sample whose centre (i + 1/2 pixels, in fixed point) lies in [lo, hi],
  // checked by definition around zero, around sample centres and at the guard band's ends.
  std::vector<int64_t> values;
  for (int64_t v = -3 * kSubpixel; v <= 3 * kSubpixel; ++v) values.push_back(v);
  for (int64_t big : {int64_t(kGuardBand) * kSubpixel, int64_t(1) << 30})
    for (int64_t d = -2; d <= 2; ++d) values.push_back(big + d), values.push_back(-big + d);
  for (int64_t v : values) {
    const int first = firstSampleAtOrAfter(v), last = lastSampleAtOrBefore(v);
    const auto centre = [](int64_t i) { return i * kSubpixel + kHalfSubpixel; };
    ASSERT_GE(centre(first), v) << v;
    ASSERT_LT(centre(first - 1), v) << v;
    ASSERT_LE(centre(last), v) << v;
    ASSERT_GT(centre(last + 1), v) << v;
  }
}

TEST(FillRule, SampleBoundsAreTheSetUpsBounds) {
  // The transform drops a triangle whose sampleBounds() are empty, before its plane: exact
  // only because the pixel loops' own TriangleSetup::bounds() would find no sample either.
  std::mt19937 rng(11);
  const int width = 37, height = 23;
  std::uniform_int_distribution<int32_t> corner(-3 * kSubpixel, (width + 3) * kSubpixel);
  std::uniform_int_distribution<int32_t> offset(-2 * kSubpixel, 2 * kSubpixel);
  int empty = 0, nonEmpty = 0;
  for (int i = 0; i < 20000; ++i) {
    // Mostly tiny triangles (a sample or two across), some big ones.
    const FixedPoint a{corner(rng), corner(rng) * height / width};
    const int scale = i % 10 == 0 ? 8 : 1;
    const FixedPoint b{a.x + offset(rng) * scale, a.y + offset(rng) * scale};
    const FixedPoint c{a.x + offset(rng) * scale, a.y + offset(rng) * scale};
    const FixedPoint v[3] = {a, b, c};
    TriangleSetup setup;
    const bool found = setup.bounds(v, width, height);
    const SampleRect r = sampleBounds(a, b, c, width, height);
    ASSERT_EQ(r.empty(), !found) << i;
    if (found) {
      EXPECT_TRUE(r.minX == setup.minX && r.maxX == setup.maxX && r.minY == setup.minY &&
                  r.maxY == setup.maxY)
          << i;
    }
    (found ? nonEmpty : empty) += 1;
  }
  EXPECT_GT(empty, 2000);
  EXPECT_GT(nonEmpty, 2000);
}

TEST(FillRule, TwoTrianglesSharingAnEdgeCoverTheirUnionExactlyOnce) {
  std::mt19937 rng(1234);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const FixedPoint a = randomPoint(rng), b = randomPoint(rng);
    FixedPoint c = randomPoint(rng), d = randomPoint(rng);
    const int64_t oc = orient2d(a, b, c), od = orient2d(a, b, d);
    if (oc == 0 || od == 0 || (oc > 0) == (od > 0)) continue;  // need c and d on opposite sides
    if (oc < 0) std::swap(c, d);
    std::vector<int> count(kSize * kSize, 0);
    const auto t1 = oriented(a, b, c), t2 = oriented(b, a, d);
    addCoverage(t1.data(), kSize, count);
    addCoverage(t2.data(), kSize, count);
    const Polygon quad = {a, d, b, c};
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        ASSERT_EQ(count[size_t(y) * kSize + x], oracleCovers(quad, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(FillRule, EdgesThroughSampleCentresStillCoverOnce) {
  // All corners on sample centres or on the grid of half samples: edges run exactly through
  // many centres, where only the top-left rule decides.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int32_t> d(0, 2 * kSize);
  for (int trial = 0; trial < 400; ++trial) {
    auto p = [&] { return FixedPoint{d(rng) * kHalfSubpixel, d(rng) * kHalfSubpixel}; };
    const FixedPoint a = p(), b = p();
    FixedPoint c = p(), e = p();
    const int64_t oc = orient2d(a, b, c), oe = orient2d(a, b, e);
    if (oc == 0 || oe == 0 || (oc > 0) == (oe > 0)) continue;
    if (oc < 0) std::swap(c, e);
    std::vector<int> count(kSize * kSize, 0);
    addCoverage(oriented(a, b, c).data(), kSize, count);
    addCoverage(oriented(b, a, e).data(), kSize, count);
    const Polygon quad = {a, e, b, c};
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        ASSERT_EQ(count[size_t(y) * kSize + x], oracleCovers(quad, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
  }
}

TEST(FillRule, FanAroundOneVertexCoversItsPolygonExactlyOnce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2 * CV_PI), radius(1.0, 7.5);
  for (int trial = 0; trial < 200; ++trial) {
    const int k = 3 + trial % 9;
    std::vector<double> angles(static_cast<size_t>(k));
    for (double& t : angles) t = angle(rng);
    std::sort(angles.begin(), angles.end());
    // Centre off the sample grid by a random sub-sample offset.
    const double cx = 8.0 + (rng() % 256) / 256.0, cy = 8.0 + (rng() % 256) / 256.0;
    const FixedPoint o{snapToSubpixel(cx), snapToSubpixel(cy)};
    Polygon ring;
    for (double t : angles) {
      const double r = radius(rng);
      ring.push_back({snapToSubpixel(cx + r * std::cos(t)), snapToSubpixel(cy + r * std::sin(t))});
    }
    // A star-shaped ring around o needs every angle gap below pi for the fan to be a partition.
    bool star = true;
    for (int i = 0; i < k; ++i) star &= orient2d(o, ring[i], ring[(i + 1) % k]) > 0;
    if (!star) continue;
    std::vector<int> count(kSize * kSize, 0);
    for (int i = 0; i < k; ++i)
      addCoverage(oriented(o, ring[i], ring[(i + 1) % k]).data(), kSize, count);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        ASSERT_EQ(count[size_t(y) * kSize + x], oracleCovers(ring, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
  }
}

TEST(FillRule, ConcavePolygonTriangulationCoversExactlyThePolygon) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> radius(0.5, 7.5);
  std::vector<std::array<uint32_t, 3>> pieces;
  std::vector<uint32_t> scratch;
  int concave = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = 4 + trial % 20;
    Polygon poly;
    for (int i = 0; i < k; ++i) {
      const double t = 2 * CV_PI * i / k, r = radius(rng);
      poly.push_back(
          {snapToSubpixel(8.0 + r * std::cos(t)), snapToSubpixel(8.0 + r * std::sin(t))});
    }
    if (trial % 2) std::reverse(poly.begin(), poly.end());  // both windings
    pieces.clear();
    ASSERT_TRUE(triangulatePolygon(poly.data(), uint32_t(poly.size()), pieces, scratch));
    for (int i = 0; i < k; ++i)
      concave += orient2d(poly[i], poly[(i + 1) % k], poly[(i + 2) % k]) * (trial % 2 ? -1 : 1) < 0;
    std::vector<int> count(kSize * kSize, 0);
    for (const auto& t : pieces) {
      const FixedPoint v[3] = {poly[t[0]], poly[t[1]], poly[t[2]]};
      ASSERT_GT(orient2d(v[0], v[1], v[2]), 0);
      addCoverage(v, kSize, count);
    }
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        ASSERT_EQ(count[size_t(y) * kSize + x], oracleCovers(poly, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
  }
  EXPECT_GT(concave, 100);  // the trials really were concave
}

TEST(FillRule, TopLeftRuleOnATriangleThroughSampleCentres) {
  // Corners on the centres of samples (0,0), (4,0) and (0,4). The top edge (y = 0.5) and the
  // left edge (x = 0.5) are included, the hypotenuse through (4,0)...(0,4) is not, so the
  // covered samples are exactly those with i + j <= 3: 10 samples.
  const FixedPoint a{kHalfSubpixel, kHalfSubpixel}, b{4 * kSubpixel + kHalfSubpixel, kHalfSubpixel},
      c{kHalfSubpixel, 4 * kSubpixel + kHalfSubpixel};
  std::vector<int> count(kSize * kSize, 0);
  addCoverage(oriented(a, b, c).data(), kSize, count);
  int total = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      EXPECT_EQ(count[size_t(j) * kSize + i], (i + j <= 3) ? 1 : 0) << i << "," << j;
      total += count[size_t(j) * kSize + i];
    }
  EXPECT_EQ(total, 10);
  // The mirror image (x flipped about x = 4.5 sample units): its vertical edge is now a right
  // edge and the hypotenuse a left edge, so the covered set is i - j >= 1... worked out:
  // samples (i, j) with 1 <= i <= 4, j <= i - 1.
  const FixedPoint d{9 * kSubpixel - kHalfSubpixel, kHalfSubpixel};  // x = 8.5 -> mirrored a
  const FixedPoint e{4 * kSubpixel + kHalfSubpixel, kHalfSubpixel};  // x = 4.5
  const FixedPoint f{9 * kSubpixel - kHalfSubpixel, 4 * kSubpixel + kHalfSubpixel};
  std::vector<int> mirror(kSize * kSize, 0);
  addCoverage(oriented(d, e, f).data(), kSize, mirror);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      // Centres x = i + 0.5 in (4.5, 8.5) strictly left of the right edge, and on or right
      // of the hypotenuse x = 4.5 + (y - 0.5), which is a left edge: i - 4 >= j, i <= 7.
      const bool expected = i <= 7 && i - 4 >= j && j >= 0 && j <= 3;
      EXPECT_EQ(mirror[size_t(j) * kSize + i], expected ? 1 : 0) << i << "," << j;
    }
}

// A FrameGeometry made directly of triangles (no camera), each its own face.
FrameGeometry geometryOf(const std::vector<std::array<FixedPoint, 3>>& tris,
                         const std::vector<DepthPlane>& planes, const std::vector<uint32_t>& ids,
                         int size) {
  FrameGeometry g;
  g.width = g.height = size;
  for (size_t i = 0; i < tris.size(); ++i) {
    const auto t = oriented(tris[i][0], tris[i][1], tris[i][2]);
    ScreenFace f{};
    f.id = ids[i];
    f.firstVertex = uint32_t(g.vertices.size());
    f.vertexCount = 3;
    f.firstTriangle = uint32_t(g.triangles.size());
    f.triangleCount = 1;
    f.frontFacing = true;
    g.vertices.insert(g.vertices.end(), t.begin(), t.end());
    g.triangles.push_back(
        ScreenTriangle{{t[0], t[1], t[2]}, uint32_t(g.faces.size()), ids[i], planes[i]});
    g.faces.push_back(f);
  }
  return g;
}

FrameBuffer runZBuffer(FrameGeometry& g) {
  // The z-buffer reads only the geometry; scene, camera and transformer are not touched.
  auto mesh = test::makeMesh({{0, 0, 0}}, {{0}});
  Warnings w;
  const Scene scene = makeScene(test::tinySettings(g.width), mesh);
  const Camera camera = makeCamera(scene);
  test::GivenGeometry given;
  FrameInput input{scene, camera, given, g};
  FrameBuffer fb;
  fb.resize(g.width, g.height);
  RenderStats stats;
  ZBufferAlgorithm().render(input, fb, stats);
  return fb;
}

TEST(DepthRule, InterpenetratingTrianglesSplitAlongTheirIntersection) {
  // Two triangles covering the same square; depth 0.5 + 0.01 (x - 8) and 0.5 - 0.01 (x - 8):
  // they cross at x = 8, so face 1 is nearer left of it and face 0 right of it.
  const FixedPoint p0{0, 0}, p1{16 * kSubpixel, 0}, p2{0, 16 * kSubpixel};
  const DepthPlane rising{0.01, 0.0, 0.42}, falling{-0.01, 0.0, 0.58};
  FrameGeometry g = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {rising, falling}, {0, 1}, 16);
  const FrameBuffer fb = runZBuffer(g);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const DepthKey k = fb.row(y)[x];
      if (x + y >= 15) {  // outside the triangle (the hypotenuse is not a left edge)
        EXPECT_EQ(k, kClearKey) << x << "," << y;
        continue;
      }
      // Sample centre x + 0.5 < 8 -> falling (id 1) is farther... depth(rising) smaller
      // left of 8: rising = 0.5 + 0.01 (x + 0.5 - 8) < 0.5 there, so id 0 wins on the left.
      const uint32_t expected = x + 0.5 < 8 ? 0u : 1u;
      EXPECT_EQ(keyFaceId(k), expected) << x << "," << y;
    }
  }
}

TEST(DepthRule, CoplanarDuplicatesGoToTheSmallerIdWhateverTheOrder) {
  const FixedPoint p0{100, 50}, p1{3000, 700}, p2{900, 3900};
  const DepthPlane plane{0.001, 0.002, 0.3};
  FrameGeometry forward = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {plane, plane}, {5, 9}, 16);
  FrameGeometry backward = geometryOf({{p0, p1, p2}, {p0, p1, p2}}, {plane, plane}, {9, 5}, 16);
  const FrameBuffer a = runZBuffer(forward), b = runZBuffer(backward);
  EXPECT_EQ(test::countDifferences(a, b), 0u);
  size_t covered = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a.data()[i] == kClearKey) continue;
    ++covered;
    EXPECT_EQ(keyFaceId(a.data()[i]), 5u);
  }
  EXPECT_GT(covered, 50u);
}

TEST(DepthRule, ReversedSubmissionGivesTheSameBuffers) {
  // A random soup through the whole pipeline, then the same triangles submitted backwards.
  auto mesh = test::randomSoup(42, 300, true);
  SceneSettings s = test::tinySettings(96);
  s.cull = false;
  Warnings w;
  const Scene scene = makeScene(s, mesh);
  const Camera camera = makeCamera(scene);
  FaceTransformer transformer(scene, camera, 1, false);
  FrameGeometry g;
  transformer.pullAll(g);
  FrameGeometry reversed = g;
  std::reverse(reversed.triangles.begin(), reversed.triangles.end());
  const FrameBuffer a = runZBuffer(g), b = runZBuffer(reversed);
  EXPECT_EQ(test::countDifferences(a, b), 0u);
  size_t faces = 0;
  std::vector<bool> seen(300, false);
  for (size_t i = 0; i < a.size(); ++i)
    if (keyFaceId(a.data()[i]) != kBackgroundId && !seen[keyFaceId(a.data()[i])])
      seen[keyFaceId(a.data()[i])] = true, ++faces;
  EXPECT_GT(faces, 50u);  // a real mix of visible faces
}

TEST(DepthRule, FloatStepsMatchNextafter) {
  // Every sign, zeros, denormals, 1, infinities and random bit patterns of finite floats.
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,
                               -0.0f,
                               1.0f,
                               -1.0f,
                               inf,
                               -inf,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               -std::numeric_limits<float>::max(),
                               std::nextafter(1.0f, 0.0f),
                               0.5f,
                               1e-30f,
                               -1e-30f};
  std::mt19937 rng(3);
  for (int i = 0; i < 100000; ++i) {
    const float f = bitsToFloat(uint32_t(rng()));
    if (!std::isnan(f)) values.push_back(f);
  }
  for (float f : values) {
    if (f >= 0.0f) {
      EXPECT_EQ(floatBits(nextFloatTowardZero(f)), floatBits(std::nextafter(f, 0.0f))) << f;
    }
    if (f <= 1.0f) {
      EXPECT_EQ(floatBits(nextFloatTowardOne(f)), floatBits(std::nextafter(f, 1.0f))) << f;
    }
  }
}

TEST(DepthRule, KeyOrdersByDepthThenId) {
  EXPECT_LT(makeDepthKey(0.25f, 900), makeDepthKey(0.5f, 1));
  EXPECT_LT(makeDepthKey(0.5f, 1), makeDepthKey(0.5f, 2));
  EXPECT_LT(makeDepthKey(0.0f, 7), makeDepthKey(std::nextafter(0.0f, 1.0f), 0));
  EXPECT_LT(makeDepthKey(1.0f, 3), kClearKey);  // a face on the far plane beats the background
  EXPECT_EQ(keyDepth(makeDepthKey(0.375f, 12)), 0.375f);
  EXPECT_EQ(keyFaceId(makeDepthKey(0.375f, 12)), 12u);
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

TEST(DepthRule, DepthIsClampedToTheFaceCornerRange) {
  DepthPlane p{0.1, 0.0, 0.0};
  p.loBits = int32_t(floatBits(0.25f));
  p.hiBits = int32_t(floatBits(0.5f));
  EXPECT_EQ(p.at(0, p.rowBase(0)), 0.25f);  // 0.05 raised to the nearest corner
  EXPECT_EQ(p.at(3, p.rowBase(0)), 0.35f);  // inside the range: the plane itself
  EXPECT_EQ(p.at(9, p.rowBase(0)), 0.5f);   // 0.95 lowered to the farthest corner
  DepthPlane negativeZero{0.0, 0.0, -0.0};
  EXPECT_EQ(floatBits(negativeZero.at(0, -0.0)), 0u);  // -0.0 becomes +0.0
}

TEST(DepthRule, TransformSetsTheRangeFromTheCornerDepths) {
  // A triangle from z = 0 to z = 1 seen from z = 2: corner depths at view distances 2 and 1.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 1}}, {{0, 1, 2}});
  Warnings w;
  const Scene scene = makeScene(test::tinySettings(16), mesh);
  const Camera camera = makeCamera(scene);
  FaceTransformer transformer(scene, camera, 1, true);
  FrameGeometry g;
  transformer.pullAll(g);
  ASSERT_EQ(g.faces.size(), 1u);
  const double n = 0.1, f = 10.0;
  auto windowDepth = [&](double d) {
    return 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)) + 0.5;
  };
  const DepthPlane& p = g.triangles[g.faces[0].firstTriangle].plane;
  EXPECT_LE(double(p.minDepth()), windowDepth(1.0));
  EXPECT_NEAR(p.minDepth(), windowDepth(1.0), 1e-7);
  EXPECT_GE(double(p.maxDepth()), windowDepth(2.0));
  EXPECT_NEAR(p.maxDepth(), windowDepth(2.0), 1e-7);
}

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

TEST(FillLoop, VectorFillMatchesTheScalarFillBitForBit) {
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

TEST(FillLoop, VectorSpanFillMatchesTheScalarSpanFillBitForBit) {
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
