// The comparison of two frames that `bench` reports as "identical" (identicalFrames): any
// difference in a key (depth or face id), a color or the size is a disagreement.

#include <gtest/gtest.h>

#include "support/TestSupport.hpp"
#include "zrender/io/ImageMat.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {
namespace {

TEST(IdenticalFrames, AnyDifferenceInKeysOrColorsIsADisagreement) {
  auto mesh = test::makeMesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}});
  const test::Rendered a = test::render(mesh, test::tinySettings(8), "zbuffer");
  EXPECT_TRUE(identicalFrames(a.buffer, viewOf(a.color), a.buffer, viewOf(a.color)));
  FrameBuffer otherKeys = a.buffer;
  otherKeys.row(3)[3] = makeDepthKey(keyDepth(otherKeys.row(3)[3]), 1);  // another face id
  EXPECT_FALSE(identicalFrames(otherKeys, viewOf(a.color), a.buffer, viewOf(a.color)));
  cv::Mat otherColor = a.color.clone();
  otherColor.at<cv::Vec3b>(0, 7)[1] = 1;  // one channel of one pixel
  EXPECT_FALSE(identicalFrames(a.buffer, viewOf(otherColor), a.buffer, viewOf(a.color)));
  const test::Rendered small = test::render(mesh, test::tinySettings(4), "zbuffer");
  EXPECT_FALSE(identicalFrames(small.buffer, viewOf(small.color), a.buffer, viewOf(a.color)));
}

}  // namespace
}  // namespace zrender
