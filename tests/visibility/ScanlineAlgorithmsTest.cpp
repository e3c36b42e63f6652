// The scan-line algorithms, `scanline` and `interval`: a concave polygon drawn natively and
// worked out by hand, rows crossed by many edges, and their own counters.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "support/AlgorithmAgreement.hpp"
#include "support/TestMeshes.hpp"
#include "support/TestSupport.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/transform/Triangulation.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

using test::combOutline;
using test::expectSameAsZBuffer;
using test::extraCounter;
using test::planarPolygon;
using test::PolygonSoup;

// ---------------------------------------------------------------------------------------------
// Hand-worked coverage: a concave hexagon in an 8 x 8 image, corners at sample centres or
// borders (sample units): A (0.5, 0.5), B (6.5, 0.5), C (6.5, 6.5), D (4.5, 6.5), E (3.5, 2.5),
// F (2.5, 6.5). Worked row by row (centre yc = j + 0.5, crossings c, covered centres in
// [c1, c2) and [c3, c4)):
//   row 0: F-A at 0.5, B-C at 6.5 (A-B is horizontal, never active)     -> columns 0..5
//   row 1: F-A at 0.833, B-C at 6.5                                     -> 1..5
//   row 2: F-A 1.167, E-F 3.5, D-E 3.5 (E is at a centre), B-C 6.5      -> 1..5
//   row 3: F-A 1.5, E-F 3.25, D-E 3.75, B-C 6.5                         -> 1, 2, 4, 5
//   row 4: F-A 1.833, E-F 3.0, D-E 4.0, B-C 6.5                         -> 2, 4, 5
//   row 5: F-A 2.167, E-F 2.75, D-E 4.25, B-C 6.5                       -> 2, 4, 5
//   row 6: yc = 6.5 is the bottom of every edge: none active            -> nothing
const char* const kHexagonMask[8] = {
    "XXXXXX..",  //
    ".XXXXX..",  //
    ".XXXXX..",  //
    ".XX.XX..",  //
    "..X.XX..",  //
    "..X.XX..",  //
    "........",  //
    "........",  //
};

FixedPoint samplePoint(double x, double y) {
  return FixedPoint{int32_t(std::lround(x * kSubpixel)), int32_t(std::lround(y * kSubpixel))};
}

// Renders one hand-made face with `algorithm`; the face's depth is 0.5 everywhere.
FrameBuffer renderHandMadeFace(const std::vector<FixedPoint>& corners,
                               const std::string& algorithm) {
  Warnings warnings;
  const Scene scene = makeScene(test::tinySettings(8),
                                test::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  const Camera camera = makeCamera(scene);
  test::GivenGeometry given;
  FrameGeometry geometry;
  geometry.width = geometry.height = 8;
  geometry.vertices.assign(corners.begin(), corners.end());
  std::vector<std::array<uint32_t, 3>> pieces;
  std::vector<uint32_t> scratch;
  EXPECT_TRUE(triangulatePolygon(corners.data(), uint32_t(corners.size()), pieces, scratch));
  ScreenFace face{};
  face.id = 7;
  face.firstVertex = 0;
  face.vertexCount = uint16_t(corners.size());
  face.firstTriangle = 0;
  face.triangleCount = uint16_t(pieces.size());
  face.frontFacing = true;
  int32_t minY = corners[0].y, maxY = corners[0].y;
  for (const FixedPoint& p : corners) minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
  face.rows = faceRowSpan(minY, maxY, geometry.height);
  geometry.faces.push_back(face);
  for (const auto& t : pieces)
    geometry.triangles.push_back(ScreenTriangle{
        {corners[t[0]], corners[t[1]], corners[t[2]]}, 0, face.id, DepthPlane{0.0, 0.0, 0.5}});

  auto alg = makeAlgorithm(algorithm);
  FrameBuffer fb;
  fb.resize(8, 8);
  RenderStats stats;
  FrameInput input{scene, camera, given, geometry};
  alg->render(input, fb, stats);
  return fb;
}

TEST(ScanlineAlgorithms, HandWorkedConcaveHexagon) {
  std::vector<FixedPoint> hexagon = {samplePoint(0.5, 0.5), samplePoint(6.5, 0.5),
                                     samplePoint(6.5, 6.5), samplePoint(4.5, 6.5),
                                     samplePoint(3.5, 2.5), samplePoint(2.5, 6.5)};
  const DepthKey inside = makeDepthKey(0.5f, 7);
  for (int winding = 0; winding < 2; ++winding) {
    // zbuffer draws the triangulation; it must agree with the hand-worked polygon too.
    for (const std::string alg : {"scanline", "interval", "zbuffer"}) {
      const FrameBuffer fb = renderHandMadeFace(hexagon, alg);
      for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
          EXPECT_EQ(fb.row(y)[x], kHexagonMask[y][x] == 'X' ? inside : kClearKey)
              << alg << " winding " << winding << " sample (" << x << ", " << y << ")";
    }
    std::reverse(hexagon.begin(), hexagon.end());
  }
}

// The comb alone, in the image plane: the scan-line algorithms really see 4+ crossings per row.
TEST(ScanlineAlgorithms, CombCrossesRowsManyTimes) {
  PolygonSoup soup;
  soup.add(planarPolygon(combOutline(4, 1.5, 1.2), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
  SceneSettings s = test::tinySettings(64);
  s.cull = false;  // the outline runs clockwise
  EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                test::kScanlineAlgorithms, "comb")
                .covered,
            500u);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(soup.positions, soup.faces));
  for (const std::string& alg : test::kScanlineAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    EXPECT_GE(extraCounter(r.stats, "max_active_edges"), 8u) << alg;
  }
}

// The counters of these algorithms (docs/design.md, Timings and JSON) are reported.
TEST(ScanlineAlgorithms, Counters) {
  SceneSettings s = test::tinySettings(100);
  s.cull = false;
  Warnings warnings;
  const Scene scene = makeScene(s, test::randomSoup(3, 100, true));
  for (const std::string& alg : test::kScanlineAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    std::map<std::string, uint64_t> extra(r.stats.extra.begin(), r.stats.extra.end());
    EXPECT_GT(extra["spans"], 0u) << alg;
    EXPECT_GT(extra["max_active_edges"], 0u) << alg;
    EXPECT_GT(extra["max_active_polygons"], 0u) << alg;
    EXPECT_GT(r.stats.trianglesRasterized, 0u) << alg;
    EXPECT_GT(r.stats.pixelsWritten, 0u) << alg;
  }
}

}  // namespace
}  // namespace zrender
