// Whole-pipeline scenes small enough to work out by hand: with test::tinySettings(8) the plane
// z = 0 spans x, y in [-2, 2] across the 8 x 8 image, so world x maps to pixel column 2x + 4 and
// world y to row 4 - 2y: one world unit is two pixels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <set>
#include <vector>

#include "TestSupport.hpp"
#include "zrender/base/HugePageAllocator.hpp"
#include "zrender/io/ImageOutput.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/shading/Shader.hpp"
#include "zrender/shading/ShadingModel.hpp"

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

TEST(FrameBuffer, BigBuffersStartOnAHugePageAndCopyLikeVectors) {
  FrameBuffer big;
  big.resize(1800, 1800);
#if defined(__linux__)
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % HugePageAllocator<DepthKey>::kHugePage,
            0u);
#endif
  big.clear();
  big.row(1799)[1799] = makeDepthKey(0.5f, 7);
  FrameBuffer copy = big;
  EXPECT_TRUE(copy == big);
  copy.row(0)[0] = makeDepthKey(0.25f, 3);
  EXPECT_FALSE(copy == big);
  EXPECT_EQ(big.row(1799)[1799], makeDepthKey(0.5f, 7));

  FrameBuffer small;  // below a huge page: operator new
  small.resize(8, 8);
  small.clear();
  FrameBuffer smallCopy = small;
  EXPECT_TRUE(smallCopy == small);
}

TEST(FrameBuffer, HugePageVectorsKeepTheirValuesAcrossBothKindsOfBlock) {
  // Grows from operator new blocks into mapped ones; every value must move along.
  std::vector<uint64_t, HugePageAllocator<uint64_t>> v;
  for (uint64_t i = 0; i < 600000; ++i) v.push_back(i * 2654435761u);
  for (uint64_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i * 2654435761u);
  v.resize(10);
  v.shrink_to_fit();  // back to a small block
  EXPECT_EQ(v[9], uint64_t(9) * 2654435761u);
  HugePageAllocator<uint64_t> allocator;
  EXPECT_THROW(allocator.allocate(std::size_t(-1) / 8), std::bad_alloc);
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

TEST(TinyScene, GridInstancesAreCentredOnTheOrigin) {
  // SPEC §3: instance (i, j, k) moves by ((i - (nx-1)/2) sx, (j - (ny-1)/2) sy, (k - (nz-1)/2)
  // sz), numbered i fastest: with counts 2 x 2 x 2 every offset is half a spacing either way.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  SceneSettings s = test::tinySettings(8);
  s.grid = Grid{{2, 2, 2}, {1.0, 2.0, 3.0}};
  Warnings warnings;
  const Scene scene = makeScene(s, mesh);
  ASSERT_EQ(scene.instanceCount(), 8u);
  for (uint32_t n = 0; n < 8; ++n) {
    const Vec3 moved = transformPoint(scene.modelMatrix(n), Vec3(0, 0, 0));
    const Vec3 expected((n % 2 == 0 ? -0.5 : 0.5), (n / 2 % 2 == 0 ? -1.0 : 1.0),
                        (n / 4 == 0 ? -1.5 : 1.5));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(moved[a], expected[a]) << "instance " << n << ", " << a;
  }
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

TEST(Shading, IdModeEncodesIdPlusOneLowByteInRed) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Id;
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3), cv::Vec3b(0, 0, 1));  // BGR: R = 1 = id 0 + 1
  EXPECT_EQ(r.color.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
}

TEST(Shading, NormalModeOfAFaceTowardTheEyeIsHalfHalfFull) {
  // View-space normal (0, 0, 1) -> color (0.5, 0.5, 1) -> RGB (128, 128, 255).
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3), cv::Vec3b(255, 128, 128));
}

TEST(Shading, FlatModeIsTheLambertTermSeenFromTheCentroid) {
  // Centroid at the origin, eye at (0, 0, 2): the face normal points at the light: gray 255.
  // Tilted 60 degrees about Y: cos 60 = 0.5 -> 128.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Flat;
  EXPECT_EQ(test::render(mesh, s, "zbuffer").color.at<cv::Vec3b>(3, 3), cv::Vec3b(255, 255, 255));
  s.angle = 60.0;
  EXPECT_EQ(test::render(mesh, s, "zbuffer").color.at<cv::Vec3b>(3, 3), cv::Vec3b(128, 128, 128));
}

// Blinn–Phong with the light at the eye, as the README states it, for one channel in 0..1:
// base (ambient 0.1 + 0.9 d) + white specular 0.3 d^64, d = n . toEye; then 8 bits.
int litChannel(double base, double d) {
  const double c = base * (0.1 + 0.9 * d) + 0.3 * std::pow(d, 64.0);
  return int(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

// d for the pixel (column, row) of a size x size tiny scene (eye (0, 0, 2), 90 degrees) on a
// plane through the origin with unit normal (sin a, 0, cos a): the ray from the eye through the
// pixel centre's point (X, Y, 0) has direction D = (X, Y, -2), and d = n . (-D) / |D|.
double lambertAt(int size, int column, int row, double degrees) {
  const double x = (column + 0.5) * 4.0 / size - 2.0, y = 2.0 - (row + 0.5) * 4.0 / size;
  const double a = degrees * M_PI / 180.0;
  return (2.0 * std::cos(a) - x * std::sin(a)) / std::sqrt(x * x + y * y + 4.0);
}

TEST(Shading, PhongIsBlinnPhongWithTheLightAtTheEye) {
  // A square without material (base gray 0.8), facing the eye and then turned 60 degrees
  // about Y (normal (sin 60, 0, cos 60)): every covered pixel as the formula gives it.
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(16);
  s.shading = ShadingMode::Phong;
  for (double degrees : {0.0, 60.0}) {
    s.angle = degrees;
    const test::Rendered r = test::render(mesh, s, "zbuffer");
    int covered = 0;
    for (int row = 0; row < 16; ++row) {
      for (int column = 0; column < 16; ++column) {
        if (keyFaceId(r.buffer.row(row)[column]) == kBackgroundId) continue;
        ++covered;
        const int g = litChannel(0.8, lambertAt(16, column, row, degrees));
        EXPECT_EQ(r.color.at<cv::Vec3b>(row, column), cv::Vec3b(g, g, g))
            << degrees << " degrees, pixel " << column << ", " << row;
      }
    }
    EXPECT_GE(covered, degrees == 0.0 ? 64 : 24) << degrees;
  }
}

TEST(Shading, TextureIsBilinearWrappedWithVUp) {
  // The square with UVs (0, 0) at (-1, -1) to (1, 1) at (1, 1) and a 2 x 2 texture whose red
  // is 0 in column 0 and 255 in column 1, and whose blue is 255 in the top row (row 0 of the
  // image, v near 1) and 0 in the bottom one. Texel centres are at u, v = 0.25 and 0.75, so
  // between them bilinear filtering gives red 2u - 0.5 and blue 2v - 0.5; outside, wrapping
  // blends with the texel on the other side: 0.5 - 2t below 0.25, 2.5 - 2t above 0.75.
  // Green stays 0; the result is lit as phong. The square covers pixels 4..11 of 16.
  auto base = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  auto mesh = std::make_shared<Mesh>(*base);
  mesh->texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (Corner& c : mesh->corners) c.texcoord = c.position;
  SceneSettings s = test::tinySettings(16);
  s.shading = ShadingMode::Texture;
  Warnings warnings;
  Scene scene = makeScene(s, mesh);
  scene.texture = cv::Mat(2, 2, CV_8UC3);
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 2; ++column)
      scene.texture.at<cv::Vec3b>(row, column) = cv::Vec3b(row == 0 ? 255 : 0, 0, column * 255);
  const test::Rendered r = test::render(scene, "zbuffer");
  const auto weight = [](double t) {
    return t < 0.25 ? 0.5 - 2 * t : t > 0.75 ? 2.5 - 2 * t : 2 * t - 0.5;
  };
  for (int row = 4; row <= 11; ++row) {
    for (int column = 4; column <= 11; ++column) {
      const double u = ((column + 0.5) / 4.0 - 2.0 + 1.0) / 2.0;
      const double v = (2.0 - (row + 0.5) / 4.0 + 1.0) / 2.0;
      const double d = lambertAt(16, column, row, 0.0);
      const cv::Vec3b bgr(litChannel(weight(v), d), litChannel(0.0, d), litChannel(weight(u), d));
      EXPECT_EQ(r.color.at<cv::Vec3b>(row, column), bgr) << "pixel " << column << ", " << row;
    }
  }
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3), cv::Vec3b(0, 0, 0));  // background
}

TEST(Shading, GridInstancesGetTheirOwnFaceColors) {
  // A 2 x 2 pixel square repeated 5 x 5 (spacing 0.75, three pixels) in a 16 x 16 image, where
  // world x maps to pixel column 4x + 8 and y to row 8 - 4y. 25 faces for 256 pixels are too
  // many for a table of the frame's faces: flat colors are found as pixels meet them, normal
  // ones come from a table of the mesh's faces. Flat shading differs per instance (the light
  // is at the eye, seen from each centroid); normal shading is the same for all (one
  // rotation); id and random follow the instance's face id.
  auto mesh = test::makeMesh(
      {{-0.25, -0.25, 0}, {0.25, -0.25, 0}, {0.25, 0.25, 0}, {-0.25, 0.25, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(16);
  s.grid = Grid{{5, 5, 1}, {0.75, 0.75, 0.0}};
  for (const char* alg : {"zbuffer", "octree"}) {
    for (ShadingMode mode :
         {ShadingMode::Flat, ShadingMode::Normal, ShadingMode::Id, ShadingMode::Random}) {
      s.shading = mode;
      const test::Rendered r = test::render(mesh, s, alg);
      for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 5; ++i) {
          const uint32_t id = uint32_t(j * 5 + i);
          const double ox = (i - 2) * 0.75, oy = (j - 2) * 0.75;
          uint32_t rgb = 0;  // 0x00RRGGBB
          if (mode == ShadingMode::Flat) {
            // Normal (0, 0, 1), centroid (ox, oy, 0), eye (0, 0, 2).
            const uint32_t g = uint32_t(2.0 / std::sqrt(ox * ox + oy * oy + 4.0) * 255.0 + 0.5);
            rgb = g << 16 | g << 8 | g;
          } else if (mode == ShadingMode::Normal) {
            rgb = 128u << 16 | 128u << 8 | 255u;
          } else if (mode == ShadingMode::Id) {
            rgb = (id + 1) << 16;  // ids below 255: red only
          } else {
            rgb = randomFaceColor(id);
          }
          const cv::Vec3b bgr(uchar(rgb), uchar(rgb >> 8), uchar(rgb >> 16));
          const int row = int(8 - 4 * oy), column = int(4 * ox + 8);
          EXPECT_EQ(r.color.at<cv::Vec3b>(row, column), bgr)
              << alg << ", mode " << int(mode) << ", instance " << id;
        }
      }
    }
  }
}

TEST(Shading, RandomColorsAreFixedPerIdAndDiffer) {
  EXPECT_EQ(randomFaceColor(17), randomFaceColor(17));
  std::set<uint32_t> colors;
  for (uint32_t id = 0; id < 1000; ++id) colors.insert(randomFaceColor(id));
  EXPECT_GT(colors.size(), 990u);
}

TEST(Shading, DepthModeIsWhiteNearBlackFar) {
  // Two squares at different depths: the nearer one white, the farther black, background as set.
  auto mesh = test::makeMesh({{-2, -2, -1},
                              {0, -2, -1},
                              {0, 0, -1},
                              {-2, 0, -1},  //
                              {0, 0, 0.5},
                              {1, 0, 0.5},
                              {1, 1, 0.5},
                              {0, 1, 0.5}},
                             {{0, 1, 2, 3}, {4, 5, 6, 7}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Depth;
  s.background = {10, 20, 30};
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(2, 5), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(r.color.at<cv::Vec3b>(5, 3), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(r.color.at<cv::Vec3b>(7, 7), cv::Vec3b(30, 20, 10));  // BGR of (10, 20, 30)
}

TEST(Shading, RowsShadedAsTheyBecomeFinalEqualOneShadingAfterTheFrame) {
  // The row-ordered algorithms have rows shaded band by band while they render (rowsFinal),
  // and the renderer computes colors only for the faces of the frame's geometry (the octree's
  // grows as it goes); the result must be the frame shaded in one pass afterwards, for every
  // mode, with and without MSAA, on a scene tall enough for many bands (100 rows: 3 bands + a
  // rest; 200 sample rows with MSAA).
  auto mesh = test::randomSoup(11, 400, false);
  for (ShadingMode mode : {ShadingMode::Normal, ShadingMode::Flat, ShadingMode::Phong,
                           ShadingMode::Random, ShadingMode::Id, ShadingMode::Depth}) {
    for (int msaa : {1, 4}) {
      for (const std::string algorithm :
           {"zbuffer", "hierarchical", "scanline", "interval", "octree"}) {
        SceneSettings s = test::tinySettings(100);
        s.shading = mode;
        s.msaa = msaa;
        s.cull = false;
        Warnings w;
        const Scene scene = makeScene(s, mesh);
        const Camera camera = makeCamera(scene);
        Renderer renderer(scene, algorithm);
        renderer.renderFrame(camera);
        cv::Mat whole;
        Shader(scene, mode).shade(renderer.buffer(), camera, renderer.sampleScale(), whole);
        ASSERT_EQ(whole.size(), renderer.color().size());
        EXPECT_EQ(cv::countNonZero(cv::Mat(whole != renderer.color()).reshape(1)), 0)
            << algorithm << " msaa " << msaa << " mode " << int(mode);
        EXPECT_GT(test::coveredSamples(renderer.buffer()), 2000u);
      }
    }
  }
}

// Channel c (0 = blue, 1 = green, 2 = red, as in cv::Vec3b) of a packed 0x00RRGGBB color.
int channel(uint32_t rgb, int c) {
  return int((rgb >> (8 * c)) & 0xFF);
}

TEST(Msaa, HalfCoveredPixelIsTheExactMeanOfItsSamples) {
  // A square whose left edge is at world x = -0.75 -> pixel column 2.5: in pixel 2 only the
  // right column of samples (x = 2.75) is covered, two samples of the face's random color and
  // two of the white background.
  auto mesh =
      test::makeMesh({{-0.75, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-0.75, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Random;
  s.msaa = 4;
  s.background = {255, 255, 255};
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(r.buffer.width(), 16);  // samples
  const uint32_t face = randomFaceColor(0);
  for (int c = 0; c < 3; ++c) {
    // The rounded mean, integer (sum + 2) / 4.
    EXPECT_EQ(r.color.at<cv::Vec3b>(3, 2)[c], (2 * channel(face, c) + 2 * 255 + 2) / 4) << c;
    EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3)[c], channel(face, c)) << c;  // fully covered
    EXPECT_EQ(r.color.at<cv::Vec3b>(3, 1)[c], 255) << c;               // not covered
  }
}

TEST(Msaa, AdjacentFacesBlendWithoutBackgroundBetweenThem) {
  // Two faces sharing the edge x = 0.25 (pixel column 4.5): pixel 4 has two samples of each.
  auto mesh =
      test::makeMesh({{-1, -1, 0}, {0.25, -1, 0}, {0.25, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}},
                     {{0, 1, 2, 3}, {1, 4, 5, 2}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Random;
  s.msaa = 4;
  s.background = {255, 255, 255};
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  // The mean of the two faces' colors: no background leaked in.
  const uint32_t face0 = randomFaceColor(0), face1 = randomFaceColor(1);
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(r.color.at<cv::Vec3b>(3, 4)[c],
              (2 * channel(face0, c) + 2 * channel(face1, c) + 2) / 4)
        << c;
}

TEST(Msaa, IdShadingHoldsTheNearestSampleLikeTheIdImage) {
  // A mean of ids names no face: with MSAA, id shading gives each pixel its nearest sample's
  // id + 1 and 0 for background whatever the background color, exactly the --ids image.
  auto mesh =
      test::makeMesh({{-0.75, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-0.75, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Id;
  s.msaa = 4;
  s.background = {255, 255, 255};
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 2), cv::Vec3b(0, 0, 1));  // half covered: face 0
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 1), cv::Vec3b(0, 0, 0));  // background
  // A soup with many ids (G bytes too) and many shared pixels, by every algorithm.
  auto soup = test::randomSoup(5, 600, false);
  s = test::tinySettings(64);
  s.shading = ShadingMode::Id;
  s.msaa = 4;
  s.cull = false;
  s.background = {10, 20, 30};
  for (const std::string algorithm :
       {"zbuffer", "scanline", "interval", "hierarchical", "octree"}) {
    const test::Rendered t = test::render(soup, s, algorithm);
    const cv::Mat ids = idImage(t.buffer, 2);
    EXPECT_EQ(cv::countNonZero(cv::Mat(ids != t.color).reshape(1)), 0) << algorithm;
  }
}

}  // namespace
}  // namespace zrender
