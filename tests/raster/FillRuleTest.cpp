// The fill rule (docs/design.md, Rasterization rules), checked against the independent oracle of
// support/CoverageOracle.hpp: the first and last samples of an interval, the sample bounds,
// shared edges, edges through sample centres, fans and the top-left rule covering each sample
// exactly once.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <opencv2/core.hpp>

#include "support/CoverageOracle.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {
namespace {

using test::addCoverage;
using test::kOracleSize;
using test::oracleCovers;
using test::oriented;
using test::Polygon;

FixedPoint randomPoint(std::mt19937& rng) {
  std::uniform_int_distribution<int32_t> d(0, kOracleSize * kSubpixel);
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
    std::vector<int> count(kOracleSize * kOracleSize, 0);
    const auto t1 = oriented(a, b, c), t2 = oriented(b, a, d);
    addCoverage(t1.data(), kOracleSize, count);
    addCoverage(t2.data(), kOracleSize, count);
    const Polygon quad = {a, d, b, c};
    for (int y = 0; y < kOracleSize; ++y)
      for (int x = 0; x < kOracleSize; ++x)
        ASSERT_EQ(count[size_t(y) * kOracleSize + x], oracleCovers(quad, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(FillRule, EdgesThroughSampleCentresStillCoverOnce) {
  // All corners on sample centres or on the grid of half samples: edges run exactly through
  // many centres, where only the top-left rule decides.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int32_t> d(0, 2 * kOracleSize);
  for (int trial = 0; trial < 400; ++trial) {
    auto p = [&] { return FixedPoint{d(rng) * kHalfSubpixel, d(rng) * kHalfSubpixel}; };
    const FixedPoint a = p(), b = p();
    FixedPoint c = p(), e = p();
    const int64_t oc = orient2d(a, b, c), oe = orient2d(a, b, e);
    if (oc == 0 || oe == 0 || (oc > 0) == (oe > 0)) continue;
    if (oc < 0) std::swap(c, e);
    std::vector<int> count(kOracleSize * kOracleSize, 0);
    addCoverage(oriented(a, b, c).data(), kOracleSize, count);
    addCoverage(oriented(b, a, e).data(), kOracleSize, count);
    const Polygon quad = {a, e, b, c};
    for (int y = 0; y < kOracleSize; ++y)
      for (int x = 0; x < kOracleSize; ++x)
        ASSERT_EQ(count[size_t(y) * kOracleSize + x], oracleCovers(quad, x, y) ? 1 : 0)
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
    std::vector<int> count(kOracleSize * kOracleSize, 0);
    for (int i = 0; i < k; ++i)
      addCoverage(oriented(o, ring[i], ring[(i + 1) % k]).data(), kOracleSize, count);
    for (int y = 0; y < kOracleSize; ++y)
      for (int x = 0; x < kOracleSize; ++x)
        ASSERT_EQ(count[size_t(y) * kOracleSize + x], oracleCovers(ring, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
  }
}

TEST(FillRule, TopLeftRuleOnATriangleThroughSampleCentres) {
  // Corners on the centres of samples (0,0), (4,0) and (0,4). The top edge (y = 0.5) and the
  // left edge (x = 0.5) are included, the hypotenuse through (4,0)...(0,4) is not, so the
  // covered samples are exactly those with i + j <= 3: 10 samples.
  const FixedPoint a{kHalfSubpixel, kHalfSubpixel}, b{4 * kSubpixel + kHalfSubpixel, kHalfSubpixel},
      c{kHalfSubpixel, 4 * kSubpixel + kHalfSubpixel};
  std::vector<int> count(kOracleSize * kOracleSize, 0);
  addCoverage(oriented(a, b, c).data(), kOracleSize, count);
  int total = 0;
  for (int j = 0; j < kOracleSize; ++j)
    for (int i = 0; i < kOracleSize; ++i) {
      EXPECT_EQ(count[size_t(j) * kOracleSize + i], (i + j <= 3) ? 1 : 0) << i << "," << j;
      total += count[size_t(j) * kOracleSize + i];
    }
  EXPECT_EQ(total, 10);
  // The mirror image (x flipped about x = 4.5 sample units): its vertical edge is now a right
  // edge and the hypotenuse a left edge, so the covered set is i - j >= 1... worked out:
  // samples (i, j) with 1 <= i <= 4, j <= i - 1.
  const FixedPoint d{9 * kSubpixel - kHalfSubpixel, kHalfSubpixel};  // x = 8.5 -> mirrored a
  const FixedPoint e{4 * kSubpixel + kHalfSubpixel, kHalfSubpixel};  // x = 4.5
  const FixedPoint f{9 * kSubpixel - kHalfSubpixel, 4 * kSubpixel + kHalfSubpixel};
  std::vector<int> mirror(kOracleSize * kOracleSize, 0);
  addCoverage(oriented(d, e, f).data(), kOracleSize, mirror);
  for (int j = 0; j < kOracleSize; ++j)
    for (int i = 0; i < kOracleSize; ++i) {
      // Centres x = i + 0.5 in (4.5, 8.5) strictly left of the right edge, and on or right
      // of the hypotenuse x = 4.5 + (y - 0.5), which is a left edge: i - 4 >= j, i <= 7.
      const bool expected = i <= 7 && i - 4 >= j && j >= 0 && j <= 3;
      EXPECT_EQ(mirror[size_t(j) * kOracleSize + i], expected ? 1 : 0) << i << "," << j;
    }
}

}  // namespace
}  // namespace zrender
