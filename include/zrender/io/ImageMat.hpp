#pragma once

// Image and cv::Mat, one seen as the other: for the plugins (and the tests), which link
// OpenCV's libraries; the program itself does not include this (zrender/base/Image.hpp).

#include <opencv2/core.hpp>

#include "zrender/base/Image.hpp"

namespace zrender {

// Each pixel format and the OpenCV type of the same pixels.
struct FormatType {
  PixelFormat format;
  int cvType;
};
inline constexpr FormatType kFormatTypes[] = {{PixelFormat::kGray8, CV_8UC1},
                                              {PixelFormat::kBgr8, CV_8UC3},
                                              {PixelFormat::kGray16, CV_16UC1},
                                              {PixelFormat::kFloat32, CV_32FC1}};

inline int cvTypeOf(PixelFormat format) {
  for (const FormatType& f : kFormatTypes)
    if (f.format == format) return f.cvType;
  return CV_8UC1;
}

// A cv::Mat header over the image's pixels, no copy: the image must outlive it.
inline cv::Mat asMat(const Image& image) {
  if (image.empty()) return cv::Mat();
  return cv::Mat(image.rows(), image.cols(), cvTypeOf(image.format()), image.data(), image.step());
}

// The format of an Image that can hold `mat`'s type; false for none (kFormatTypes).
inline bool formatOf(const cv::Mat& mat, PixelFormat& format) {
  for (const FormatType& f : kFormatTypes) {
    if (f.cvType == mat.type()) {
      format = f.format;
      return true;
    }
  }
  return false;
}

// An Image over `mat`'s pixels, no copy (empty for a type formatOf does not take): `mat`'s
// pixels must outlive it.
inline Image viewOf(const cv::Mat& mat) {
  PixelFormat format;
  if (mat.empty() || !formatOf(mat, format)) return Image();
  return Image(mat.rows, mat.cols, format, const_cast<uchar*>(mat.data), mat.step);
}

// A copy of `mat` as an Image; false (and `out` left as it was) for a type an Image cannot
// hold (CV_8UC1, CV_8UC3, CV_16UC1 and CV_32FC1 it can).
inline bool copyToImage(const cv::Mat& mat, Image& out) {
  PixelFormat format;
  if (!formatOf(mat, format)) return false;
  Image image(mat.rows, mat.cols, format);
  cv::Mat pixels = asMat(image);
  mat.copyTo(pixels);
  out = image;
  return true;
}

// A copy of `mat` (a type copyToImage takes) as an Image.
inline Image toImage(const cv::Mat& mat) {
  Image image;
  copyToImage(mat, image);
  return image;
}

}  // namespace zrender
