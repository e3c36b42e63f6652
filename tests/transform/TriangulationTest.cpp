// The triangulation of polygons (triangulatePolygon: a fan when convex, ear clipping otherwise):
// the pieces of a concave polygon cover exactly the polygon by the fill rule's oracle, and faces
// that are not simple (self-crossing, through a repeated corner, with overlapping edges) are
// skipped by every algorithm, while spikes add nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "support/AlgorithmAgreement.hpp"
#include "support/CoverageOracle.hpp"
#include "support/TestSupport.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/transform/Triangulation.hpp"

namespace zrender {
namespace {

using test::addCoverage;
using test::kOracleSize;
using test::oracleCovers;
using test::oriented;
using test::Polygon;

TEST(Triangulation, ConcavePolygonCoversExactlyThePolygon) {
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
    std::vector<int> count(kOracleSize * kOracleSize, 0);
    for (const auto& t : pieces) {
      const FixedPoint v[3] = {poly[t[0]], poly[t[1]], poly[t[2]]};
      ASSERT_GT(orient2d(v[0], v[1], v[2]), 0);
      addCoverage(v, kOracleSize, count);
    }
    for (int y = 0; y < kOracleSize; ++y)
      for (int x = 0; x < kOracleSize; ++x)
        ASSERT_EQ(count[size_t(y) * kOracleSize + x], oracleCovers(poly, x, y) ? 1 : 0)
            << "trial " << trial << " sample " << x << "," << y;
  }
  EXPECT_GT(concave, 100);  // the trials really were concave
}

// A non-planar hexagon that projects to a self-crossing polygon: ear clipping would draw pieces
// of it that differ from the even-odd interior the scan-line algorithms fill, so polygons whose
// boundary crosses itself are skipped by every algorithm. (Also in the render fuzz corpus:
// regression-self-crossing-polygon.bin.)
TEST(Triangulation, SelfCrossingPolygonIsSkippedByEveryAlgorithm) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // A bowtie (crosses in the middle) and a pentagram (winds twice, every turn the same way).
  std::string obj = "v -1 -1 0\nv 1 1 0\nv 1 -1 0\nv -1 1 0\nf 1 2 3 4\n";
  for (int i = 0; i < 5; ++i) {
    const double a = CV_PI / 2 + i * 4 * CV_PI / 5;
    obj += "v " + std::to_string(1.5 * std::cos(a)) + " " + std::to_string(1.5 * std::sin(a)) +
           " -0.5\n";
  }
  obj += "f 5 6 7 8 9\n";
  const test::Rendered r = test::expectAgreement(obj, s);
  EXPECT_EQ(r.stats.trianglesDegenerate, 2u + 3u);  // counted in triangles
  EXPECT_TRUE(test::allBackground(r.buffer));
}

// A spike (the boundary running out and straight back) has no area and the even-odd rule
// ignores it, but an ear beside it would cover the area next to it. Spikes are removed before
// ear clipping: the face covers exactly the square without the spike.
TEST(Triangulation, SpikesAddNothingToAPolygon) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  const std::string square =
      "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0 0.5\nv 1.8 0 0.5\n"
      "v 0.5 0.5 0.5\nv -0.5 0.5 0.5\nv 1.8 1.5 0.5\nv -1.5 0.2 0.5\n";
  const test::Rendered plain = test::expectAgreement(square + "f 1 2 3 5 6\n", s);
  // Out of the right side and back; diagonally out of a corner; two spikes, one on the seam.
  for (const std::string face :
       {"f 1 2 3 4 3 5 6\n", "f 1 2 3 5 7 5 6\n", "f 8 6 1 2 3 4 3 5 6\n"}) {
    SCOPED_TRACE(face);
    const test::Rendered spiky = test::expectAgreement(square + face, s);
    EXPECT_EQ(test::countDifferences(spiky.buffer, plain.buffer), 0u);
  }
}

// A face naming one vertex twice, where the boundary crosses itself through that corner, or
// only touches itself there (two lobes). Ears can be found in both, and they would cover what
// the even-odd rule leaves empty (between the lobes, for the second): such faces are skipped.
// (Also in the render fuzz corpus: regression-repeated-corner-crossing.bin and ...-touching.bin.)
TEST(Triangulation, PolygonThroughARepeatedCornerIsSkipped) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // Vertex 2 (0, 0) is visited twice. Face 0 crosses there from the lower-left to the upper-
  // right lobe (lobes of unequal area, so the total area is not zero); face 1 only touches.
  const std::string points =
      "v -1 -1 0\nv 0 0 0\nv 1.5 1.5 0\nv 1.5 -1.5 0\nv -1 1 0\nv 1 -1 0\nv 1 1 0\n";
  for (const std::string face : {"f 1 2 3 4 2 5\n", "f 1 2 6 7 2 5\n"}) {
    SCOPED_TRACE(face);
    const test::Rendered r = test::expectAgreement(points + face, s);
    EXPECT_EQ(r.stats.trianglesDegenerate, 4u);
    EXPECT_TRUE(test::allBackground(r.buffer));
  }
}

// A polygon two of whose edges overlap along a line (the boundary touches itself without
// crossing): ear clipping would cover part of what the even-odd rule leaves empty. A concave
// face whose part before the near plane is in two pieces gets such edges from clipping, which
// joins the pieces along the cut: all these are skipped by every algorithm (concave faces are
// rare, and all algorithms must agree). (Also in the render fuzz corpus:
// regression-overlapping-edges.bin.)
TEST(Triangulation, PolygonWhoseEdgesOverlapIsSkipped) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // A U in the floor plane y = -0.5, its base nearer than the near plane.
  SceneSettings cut = s;
  cut.eye = Vec3(0, 0, 0);
  cut.target = Vec3(0, -0.3, -1);
  cut.near = 0.5;
  const std::string u =
      "v -2 -0.5 -0.2\nv 2 -0.5 -0.2\nv 2 -0.5 -5\nv 1 -0.5 -5\nv 1 -0.5 -0.3\n"
      "v -1 -0.5 -0.3\nv -1 -0.5 -5\nv -2 -0.5 -5\nf 1 2 3 4 5 6 7 8\n";
  for (const int msaa : {1, 4}) {
    cut.msaa = msaa;
    const test::Rendered r = test::expectAgreement(u, cut);
    EXPECT_EQ(r.stats.trianglesDegenerate, 6u);
    EXPECT_TRUE(test::allBackground(r.buffer));
  }
  // In the image plane: the edge from (1, 1) to (-1, -1) runs back over the one from
  // (-0.5, -0.5) to (0.5, 0.5); and a corner, (0, 1), lying on the top edge of its own face.
  const std::string overlap =
      "v 1 1 0\nv -1 -1 0\nv -1.5 0 0\nv -0.5 -0.5 0\nv 0.5 0.5 0\nv 1.5 0 0\n"
      "v -1 1 0.5\nv 1 1 0.5\nv 1 -1 0.5\nv 0 1 0.5\nv -1 -1 0.5\n"
      "f 1 2 3 4 5 6\nf 7 8 9 10 11\n";
  const test::Rendered r = test::expectAgreement(overlap, s);
  EXPECT_EQ(r.stats.trianglesDegenerate, 4u + 3u);
  EXPECT_TRUE(test::allBackground(r.buffer));
}

}  // namespace
}  // namespace zrender
