// Whole-pipeline scenes small enough to work out by hand: with test::tinySettings(8) the plane
// z = 0 spans x, y in [-2, 2] across the 8 x 8 image, so world x maps to pixel column 2x + 4 and
// world y to row 4 - 2y: one world unit is two pixels.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {
namespace {

// The face id of every pixel, row by row; -1 for background.
std::vector<std::vector<int>> idMap(const FrameBuffer& fb) {
  std::vector<std::vector<int>> m(size_t(fb.height()), std::vector<int>(size_t(fb.width()), -1));
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) {
      const uint32_t id = keyFaceId(fb.row(y)[x]);
      m[size_t(y)][size_t(x)] = id == kBackgroundId ? -1 : int(id);
    }
  return m;
}

// Parses a picture like {"..00..", ...}: '.' background, a digit the face id.
std::vector<std::vector<int>> picture(const std::vector<std::string>& rows) {
  std::vector<std::vector<int>> m;
  for (const auto& r : rows) {
    m.emplace_back();
    for (char c : r) m.back().push_back(c == '.' ? -1 : c - '0');
  }
  return m;
}

TEST(TinyScene, SquareQuadCoversExactlyItsSixteenPixels) {
  // The square [-1, 1]^2 spans columns and rows 2..6 exactly, so the centres 2.5 .. 5.5 are in.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_EQ(idMap(r.buffer), picture({"........",  //
                                      "........",  //
                                      "..0000..",  //
                                      "..0000..",  //
                                      "..0000..",  //
                                      "..0000..",  //
                                      "........",  //
                                      "........"}));
  EXPECT_EQ(r.stats.trianglesRasterized, 2u);  // a quad is drawn as two pieces
}

TEST(TinyScene, AspectFromTheSettingsWidensTheView) {
  // Aspect 2 on a square image: the view spans [-4, 4] across and [-2, 2] down at the
  // square's distance, so the square [-1, 1]^2 spans columns 3..5 (centres 3.5, 4.5) and rows
  // 2..6 (centres 2.5 .. 5.5).
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.aspect = 2.0;
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(idMap(r.buffer), picture({"........",  //
                                      "........",  //
                                      "...00...",  //
                                      "...00...",  //
                                      "...00...",  //
                                      "...00...",  //
                                      "........",  //
                                      "........"}));
}

TEST(TinyScene, ConcaveLShapeCoversExactlyItsArea) {
  // L: [-1, 1] x [-1, 0] plus [-1, 0] x [0, 1], counter-clockwise seen from +Z.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 0}},
                             {{0, 1, 2, 3, 4, 5}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_EQ(idMap(r.buffer), picture({"........",  //
                                      "........",  //
                                      "..00....",  //
                                      "..00....",  //
                                      "..0000..",  //
                                      "..0000..",  //
                                      "........",  //
                                      "........"}));
}

TEST(TinyScene, NearerFaceWinsAndBackFacesAreCulled) {
  // Face 0: the square at z = 0. Face 1: a smaller square [0, 1]^2 at z = 0.5 (nearer the eye
  // at z = 2), which covers... at depth 0.5 its projection is scaled by 2 / 1.5: [0, 4/3]^2 ->
  // columns 4 .. 6.67, rows 1.33 .. 4: centres 4.5, 5.5, 6.5 and rows 1.5, 2.5, 3.5.
  // Face 2: the same as face 1 but clockwise (a back face): culled.
  auto mesh = test::makeMesh({{-1, -1, 0},
                              {1, -1, 0},
                              {1, 1, 0},
                              {-1, 1, 0},  //
                              {0, 0, 0.5},
                              {1, 0, 0.5},
                              {1, 1, 0.5},
                              {0, 1, 0.5}},
                             {{0, 1, 2, 3}, {4, 5, 6, 7}, {7, 6, 5, 4}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_EQ(idMap(r.buffer), picture({"........",  //
                                      "....111.",  //
                                      "..00111.",  //
                                      "..00111.",  //
                                      "..0000..",  //
                                      "..0000..",  //
                                      "........",  //
                                      "........"}));
  EXPECT_EQ(r.stats.trianglesBackfaceCulled, 2u);
}

TEST(TinyScene, NoCullDrawsBackFacesWithTheirOwnIds) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{3, 2, 1, 0}});
  SceneSettings s = test::tinySettings(8);
  EXPECT_EQ(idMap(test::render(mesh, s, "zbuffer").buffer)[3][3], -1);  // culled
  s.cull = false;
  EXPECT_EQ(idMap(test::render(mesh, s, "zbuffer").buffer)[3][3], 0);
}

TEST(TinyScene, DepthIsTheWindowDepthOfThePlane) {
  // A square at z = 0 seen from distance 2 with near 0.1, far 10: window depth of a point at
  // view distance d is (f + n)/(f - n)/2 - f n / (f - n) / d + 1/2 with n = 0.1, f = 10.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  const double n = 0.1, f = 10.0, d = 2.0;
  const double expected = 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)) + 0.5;
  EXPECT_NEAR(keyDepth(r.buffer.row(3)[3]), expected, 1e-6);
  EXPECT_EQ(keyDepth(r.buffer.row(0)[0]), 1.0f);  // background is the far plane
}

TEST(TinyScene, HugeCoordinatesFarOutsideTheImageAreSafe) {
  // A triangle reaching 1e7 units to the right and up: it covers the quadrant x >= -1 (columns
  // from 2 on), y >= -1 (rows up to 5) of the image and nothing else.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1e7, -1, 0}, {-1, 1e7, 0}}, {{0, 1, 2}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(keyFaceId(r.buffer.row(y)[x]), (x >= 2 && y <= 5) ? 0u : kBackgroundId)
          << x << "," << y;
}

TEST(TinyScene, AFaceOfHugeCoordinatesAroundTheViewCoversItAll) {
  // A triangle at z = 0 reaching e units every way around the view: every pixel is on it, at
  // the window depth of the plane (as in DepthIsTheWindowDepthOfThePlane), up to 1e300 units,
  // where the products of window coordinates overflow a double.
  const double n = 0.1, f = 10.0, d = 2.0;
  const double expected = 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d)) + 0.5;
  for (double e : {1e7, 1e100, 1e155, 1e200, 1e300}) {
    auto mesh = test::makeMesh({{-e, -e, 0}, {e, -e, 0}, {0, e, 0}}, {{0, 1, 2}});
    for (const std::string algorithm :
         {"zbuffer", "scanline", "interval", "hierarchical", "octree"}) {
      const test::Rendered r = test::render(mesh, test::tinySettings(8), algorithm);
      for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
          ASSERT_EQ(keyFaceId(r.buffer.row(y)[x]), 0u)
              << e << " " << algorithm << " " << x << "," << y;
          EXPECT_NEAR(keyDepth(r.buffer.row(y)[x]), expected, 1e-6) << e << " " << algorithm;
        }
      }
    }
  }
}

TEST(TinyScene, TriangleThroughTheEyePlaneMatchesItsPartBeforeTheNearPlane) {
  // The triangle reaches z = 5, behind the eye at z = 2. Clipping at the near plane (view
  // distance 0.1, world z = 1.9) must draw exactly what the part in front of that plane draws
  // when given as its own polygon: the edges cut at z = 1.9, worked out by hand (y = -1 + z/5
  // along the slanted edges, x shrinking linearly to 0 at z = 5).
  auto whole = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 0, 5}}, {{0, 1, 2}});
  const double t = 1.9 / 5.0;  // fraction of the way to (0, 0, 5) at z = 1.9
  auto part = test::makeMesh(
      {{-1, -1, 0}, {1, -1, 0}, {1 - t, -1 + t, 1.9}, {-(1 - t), -1 + t, 1.9}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.cull = false;
  const test::Rendered a = test::render(whole, s, "zbuffer"), b = test::render(part, s, "zbuffer");
  EXPECT_EQ(idMap(a.buffer), idMap(b.buffer));
  EXPECT_EQ(a.stats.trianglesClippedAway, 0u);
  EXPECT_GT(a.stats.pixelsWritten, 8u);
  // The part close to the eye swings below the image centre, filling the bottom rows.
  EXPECT_EQ(idMap(a.buffer)[7][4], 0);
}

}  // namespace
}  // namespace zrender
