// One color per face (FaceColors): the instances of a grid get their own colors, whether they
// are looked up in a table of the frame's faces, of the mesh's faces, or found as pixels meet
// them.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "support/TestSupport.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {
namespace {

TEST(FaceColors, GridInstancesGetTheirOwnFaceColors) {
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

}  // namespace
}  // namespace zrender
