// Deferred shading (Shader): rows shaded band by band while an algorithm renders equal the frame
// shaded in one pass afterwards, and with MSAA 4 a pixel is the rounded mean of its samples'
// colors (background included), except in id mode, where it holds its nearest sample's id.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "support/TestSupport.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/shading/Shader.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {
namespace {

TEST(Shader, RowsShadedAsTheyBecomeFinalEqualOneShadingAfterTheFrame) {
  // The row-ordered algorithms have rows shaded band by band while they render (RowSink::rowsDone),
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
        EXPECT_TRUE(samePixels(whole, renderer.color()))
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

TEST(Shader, MsaaHalfCoveredPixelIsTheExactMeanOfItsSamples) {
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

TEST(Shader, MsaaAdjacentFacesBlendWithoutBackgroundBetweenThem) {
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

TEST(Shader, MsaaIdShadingHoldsTheNearestSampleLikeTheIdImage) {
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
    EXPECT_TRUE(samePixels(ids, t.color)) << algorithm;
  }
}

}  // namespace
}  // namespace zrender
