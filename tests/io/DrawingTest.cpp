// The images drawn with imgproc (io/Drawing.hpp): the overlay drawn on a copy, only inside its box
// in the top-left corner, white text that fits the frame; a contact sheet's cells the frames scaled
// down; a chart.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/mat.hpp>
#include <opencv2/imgproc.hpp>

#include "zrender/io/images/Drawing.hpp"

namespace zrender {
namespace {

const std::vector<std::string> kLines = {
    "hierarchical  phong  msaa 4  cull on", "frame 12.34 ms (median of 30)  61.0 fps",
    "culled: 34990 back-facing, 0 clipped, 893 by the z-pyramid",
    "drawn: 30211 triangles; octree nodes: 108 of 701 culled"};

TEST(Drawing, AnOverlayIsDrawnOnACopyInsideItsBoxOnly) {
  for (const cv::Size size : {cv::Size(640, 480), cv::Size(200, 150), cv::Size(1800, 1800)}) {
    cv::Mat frame(size, CV_8UC3, cv::Scalar(40, 200, 90));
    const cv::Mat before = frame.clone();
    const cv::Mat shown = withOverlay(frame, kLines).clone();
    EXPECT_EQ(cv::norm(frame, before, cv::NORM_INF), 0.0) << "the frame itself changed";
    const PixelBox b = overlayBox(size.width, size.height, kLines);
    const cv::Rect box(b.x, b.y, b.width, b.height);
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

// Each cell is its frame scaled down by OpenCV's area average: frames of one color give cells
// of that color, in order, left to right and top to bottom.
TEST(Drawing, AContactSheetTilesItsFramesScaledDown) {
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 5; ++i) {
    cv::Mat frame(900, 1200, CV_8UC3);
    frame.setTo(cv::Scalar(10 * i, 20 + i, 200 - 30 * i));
    frames.push_back(frame);
  }
  const cv::Mat sheet = contactSheet(frames);
  // 3 columns of 600 pixels (1800 / 3), cells 450 high, 2 rows.
  ASSERT_EQ(sheet.cols, 1800);
  ASSERT_EQ(sheet.rows, 900);
  const cv::Mat m = sheet;
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(m.at<cv::Vec3b>((i / 3) * 450 + 200, (i % 3) * 600 + 300),
              cv::Vec3b(uchar(10 * i), uchar(20 + i), uchar(200 - 30 * i)))
        << i;
  EXPECT_EQ(m.at<cv::Vec3b>(700, 1500), cv::Vec3b(0, 0, 0));  // no sixth frame: black
}

}  // namespace
}  // namespace zrender
