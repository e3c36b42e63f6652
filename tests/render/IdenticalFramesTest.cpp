// The comparison of two frames that `bench` reports as "identical" (identicalFrames): any
// difference in a key (depth or face id), a color or the size is a disagreement.

#include <gtest/gtest.h>

#include <opencv2/core/mat.hpp>

#include "support/TestSupport.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {
namespace {

TEST(IdenticalFrames, AnyDifferenceInKeysOrColorsIsADisagreement) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered a = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_TRUE(identicalFrames(a.buffer, a.color, a.buffer, a.color));
  FrameBuffer otherKeys = a.buffer;
  otherKeys.row(3)[3] = makeDepthKey(keyDepth(otherKeys.row(3)[3]), 1);  // another face id
  EXPECT_FALSE(identicalFrames(otherKeys, a.color, a.buffer, a.color));
  cv::Mat otherColor = a.color.clone();
  otherColor.at<cv::Vec3b>(0, 7)[1] = 1;  // one channel of one pixel
  EXPECT_FALSE(identicalFrames(a.buffer, otherColor, a.buffer, a.color));
  const test::Rendered small = test::render(mesh, test::tinySettings(4), "zbuffer");
  EXPECT_FALSE(identicalFrames(small.buffer, small.color, a.buffer, a.color));
}

}  // namespace
}  // namespace zrender
