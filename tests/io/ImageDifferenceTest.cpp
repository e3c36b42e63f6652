// The comparison of an image with a reference (io/images/ImageDifference.hpp): counts, the
// largest difference in each channel type, NaNs and infinities, the marked image, and images of
// another size or type, on small images made here.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "zrender/io/images/ImageDifference.hpp"

namespace zrender {
namespace {

const cv::Vec3b kRed(0, 0, 255);

// A 4 x 3 BGR context, each pixel's values its own.
cv::Mat context() {
  cv::Mat c(3, 4, CV_8UC3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) c.at<cv::Vec3b>(y, x) = cv::Vec3b(40 * x + 7, 200 - 9 * y, 255);
  return c;
}

TEST(ImageDifference, EightBitChannels) {
  const cv::Mat image = context();
  const ImageDifference same = compareImages(image, image.clone(), image);
  EXPECT_TRUE(same.comparable);
  EXPECT_EQ(same.pixels, 12u);
  EXPECT_EQ(same.differingPixels, 0u);
  EXPECT_EQ(same.largest, 0.0);
  EXPECT_TRUE(same.marked.empty());

  cv::Mat reference = image.clone();
  reference.at<cv::Vec3b>(1, 2)[0] -= 5;
  reference.at<cv::Vec3b>(2, 3) = cv::Vec3b(0, 0, 0);  // 255 off in red
  const ImageDifference d = compareImages(image, reference, image);
  EXPECT_TRUE(d.comparable);
  EXPECT_EQ(d.differingPixels, 2u);
  EXPECT_EQ(d.largest, 255.0);
  ASSERT_EQ(d.marked.type(), CV_8UC3);
  ASSERT_EQ(d.marked.size(), image.size());
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const cv::Vec3b c = image.at<cv::Vec3b>(y, x);
      const bool differs = (x == 2 && y == 1) || (x == 3 && y == 2);
      EXPECT_EQ(d.marked.at<cv::Vec3b>(y, x),
                differs ? kRed : cv::Vec3b(c[0] / 4, c[1] / 4, c[2] / 4))
          << x << ", " << y;
    }
  }
}

TEST(ImageDifference, SixteenBitChannels) {
  cv::Mat image(2, 2, CV_16UC1, cv::Scalar(65535));
  cv::Mat reference = image.clone();
  reference.at<uint16_t>(0, 1) = 0;
  reference.at<uint16_t>(1, 1) = 65534;
  const cv::Mat gray(2, 2, CV_8UC3, cv::Scalar(100, 100, 100));
  const ImageDifference d = compareImages(image, reference, gray);
  EXPECT_EQ(d.differingPixels, 2u);
  EXPECT_EQ(d.largest, 65535.0);
  EXPECT_EQ(d.marked.at<cv::Vec3b>(0, 0), cv::Vec3b(25, 25, 25));
  EXPECT_EQ(d.marked.at<cv::Vec3b>(1, 1), kRed);
}

TEST(ImageDifference, FloatsExactlyWithNaNs) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const cv::Mat gray(1, 4, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::Mat image = (cv::Mat_<float>(1, 4) << nan, inf, 1.0f, 0.5f);
  // NaN = NaN and inf = inf: equal; 1 against the next float up: 2^-23 apart.
  cv::Mat reference = (cv::Mat_<float>(1, 4) << nan, inf, std::nextafter(1.0f, 2.0f), 0.5f);
  ImageDifference d = compareImages(image, reference, gray);
  EXPECT_EQ(d.differingPixels, 1u);
  EXPECT_EQ(d.largest, std::ldexp(1.0, -23));
  EXPECT_EQ(d.marked.at<cv::Vec3b>(0, 2), kRed);
  EXPECT_EQ(d.marked.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));

  reference.at<float>(0, 3) = nan;  // a NaN against a number: infinitely far
  d = compareImages(image, reference, gray);
  EXPECT_EQ(d.differingPixels, 2u);
  EXPECT_TRUE(std::isinf(d.largest));
}

TEST(ImageDifference, AnotherSizeOrTypeIsNotCompared) {
  const cv::Mat image = context();
  const cv::Mat bigger(4, 4, CV_8UC3, cv::Scalar(0, 0, 0));
  const cv::Mat gray(3, 4, CV_8UC1, cv::Scalar(0));
  const cv::Mat floats(3, 4, CV_32FC3, cv::Scalar(0, 0, 0));
  for (const cv::Mat& other : {bigger, gray, floats}) {
    const ImageDifference d = compareImages(image, other, image);
    EXPECT_FALSE(d.comparable);
    EXPECT_EQ(d.differingPixels, 0u);
    EXPECT_TRUE(d.marked.empty());
  }
  EXPECT_EQ(describeImage(image), "4x3 8-bit, 3 channels");
  EXPECT_EQ(describeImage(cv::Mat(2, 5, CV_16UC1)), "5x2 16-bit, 1 channel");
  EXPECT_EQ(describeImage(cv::Mat(1, 1, CV_32FC1)), "1x1 32-bit float, 1 channel");
}

}  // namespace
}  // namespace zrender
