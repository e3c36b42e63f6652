// The overlay (view/Overlay.hpp): drawn on a copy, only inside its box in the top-left corner,
// white text that fits the frame.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "zrender/view/Overlay.hpp"

namespace zrender {
namespace {

const std::vector<std::string> kLines = {
    "hierarchical  phong  msaa 4  cull on", "frame 12.34 ms (median of 30)  61.0 fps",
    "culled: 34990 back-facing, 0 clipped, 893 by the z-pyramid",
    "drawn: 30211 triangles; octree nodes: 108 of 701 culled"};

TEST(Overlay, DrawsOnACopyInsideItsBoxOnly) {
  for (const cv::Size size : {cv::Size(640, 480), cv::Size(200, 150), cv::Size(1800, 1800)}) {
    cv::Mat frame(size, CV_8UC3, cv::Scalar(40, 200, 90));
    const cv::Mat before = frame.clone();
    const cv::Mat shown = withOverlay(frame, kLines);
    EXPECT_EQ(cv::norm(frame, before, cv::NORM_INF), 0.0) << "the frame itself changed";
    const cv::Rect box = overlayBox(size, kLines);
    EXPECT_EQ(box.x, 3);
    EXPECT_EQ(box.y, 3);
    EXPECT_LE(box.br().x, size.width) << size;  // the text was scaled to fit
    EXPECT_LT(box.height, size.height / 2) << size;
    cv::Mat outside = shown.clone();
    outside(box).setTo(cv::Scalar(40, 200, 90));
    EXPECT_EQ(cv::norm(outside, before, cv::NORM_INF), 0.0) << "drawn outside the box " << size;
    // Inside: the background darkened, and white text.
    int white = 0, dark = 0;
    for (int y = box.y; y < box.br().y; ++y) {
      for (int x = box.x; x < box.br().x; ++x) {
        const cv::Vec3b p = shown.at<cv::Vec3b>(y, x);
        white += p[0] > 200 && p[1] > 200 && p[2] > 200;
        dark += p == cv::Vec3b(14, 70, 32);  // 0.35 of the colour, rounded
      }
    }
    EXPECT_GT(white, 50) << size;
    EXPECT_GT(dark, box.area() / 2) << size;
  }
}

}  // namespace
}  // namespace zrender
