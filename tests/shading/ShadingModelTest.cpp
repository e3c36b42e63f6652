// The color of each shading mode (docs/design.md, Faces, ids and shading), worked out by hand on
// a square of a tiny scene: id, normal, flat, phong (Blinn-Phong with the light at the eye),
// texture (bilinear, wrapped, v up), random and depth.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <set>

#include "support/TestSupport.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {
namespace {

TEST(ShadingModel, IdModeEncodesIdPlusOneLowByteInRed) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  SceneSettings s = test::tinySettings(8);
  s.shading = ShadingMode::Id;
  const test::Rendered r = test::render(mesh, s, "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3), cv::Vec3b(0, 0, 1));  // BGR: R = 1 = id 0 + 1
  EXPECT_EQ(r.color.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
}

TEST(ShadingModel, NormalModeOfAFaceTowardTheEyeIsHalfHalfFull) {
  // View-space normal (0, 0, 1) -> color (0.5, 0.5, 1) -> RGB (128, 128, 255).
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered r = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(3, 3), cv::Vec3b(255, 128, 128));
}

TEST(ShadingModel, FlatModeIsTheLambertTermSeenFromTheCentroid) {
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

TEST(ShadingModel, PhongIsBlinnPhongWithTheLightAtTheEye) {
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

TEST(ShadingModel, TextureIsBilinearWrappedWithVUp) {
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

TEST(ShadingModel, RandomColorsAreFixedPerIdAndDiffer) {
  EXPECT_EQ(randomFaceColor(17), randomFaceColor(17));
  std::set<uint32_t> colors;
  for (uint32_t id = 0; id < 1000; ++id) colors.insert(randomFaceColor(id));
  EXPECT_GT(colors.size(), 990u);
}

TEST(ShadingModel, DepthModeIsWhiteNearBlackFar) {
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

}  // namespace
}  // namespace zrender
