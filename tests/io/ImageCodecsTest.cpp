// Images read as textures (decodeColorImage): 8-bit BGR whatever the file holds. A PNG is read
// by libpng, as it is kept when it has no alpha, else with its alpha dropped (not blended, as
// cv::imread drops it); other formats by OpenCV in the codec plugin.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/io/images/ImageCodecs.hpp"

namespace zrender {
namespace {

// 5 x 3 pixels, each channel a different function of the position.
cv::Mat pattern(int type) {
  cv::Mat m(3, 5, type);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      for (int c = 0; c < m.channels(); ++c)
        m.ptr<uchar>(y)[x * m.channels() + c] = uchar(40 * x + 70 * y + 11 * c + 3);
  return m;
}

cv::Mat decoded(const std::string& path) {
  std::string error;
  const cv::Mat image = decodeColorImage(path, error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(image.type(), CV_8UC3);
  return image;
}

TEST(ImageCodecs, AColorPngIsReadAsItIsKept) {
  test::TempDir dir;
  const cv::Mat bgr = pattern(CV_8UC3);
  ASSERT_TRUE(test::imwrite(dir.file("c.png"), bgr));
  EXPECT_EQ(cv::norm(decoded(dir.file("c.png")), bgr, cv::NORM_INF), 0.0);
}

TEST(ImageCodecs, APngsAlphaIsDroppedNotBlended) {
  test::TempDir dir;
  cv::Mat bgra = pattern(CV_8UC4);
  bgra.col(1).setTo(cv::Scalar(200, 100, 50, 0));  // fully transparent: the colour stays
  ASSERT_TRUE(test::imwrite(dir.file("a.png"), bgra));
  cv::Mat expected;
  std::vector<cv::Mat> channels;
  cv::split(bgra, channels);
  channels.pop_back();
  cv::merge(channels, expected);
  EXPECT_EQ(cv::norm(decoded(dir.file("a.png")), expected, cv::NORM_INF), 0.0);
}

TEST(ImageCodecs, AGrayPngGivesEqualChannels) {
  test::TempDir dir;
  const cv::Mat gray = pattern(CV_8UC1);
  ASSERT_TRUE(test::imwrite(dir.file("g.png"), gray));
  const cv::Mat image = decoded(dir.file("g.png"));
  const cv::Mat m = image;
  for (int y = 0; y < gray.rows; ++y)
    for (int x = 0; x < gray.cols; ++x) {
      const uchar v = gray.at<uchar>(y, x);
      EXPECT_EQ(m.at<cv::Vec3b>(y, x), cv::Vec3b(v, v, v)) << x << "," << y;
    }
}

// Not a PNG: through the codec plugin.
TEST(ImageCodecs, ABmpIsReadByThePlugin) {
  test::TempDir dir;
  const cv::Mat bgr = pattern(CV_8UC3);
  ASSERT_TRUE(test::imwrite(dir.file("c.bmp"), bgr));
  EXPECT_EQ(cv::norm(decoded(dir.file("c.bmp")), bgr, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace zrender
