#include "zrender/io/images/ImageDifference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace zrender {

namespace {

// The absolute difference of two channel values; 0 when they are equal (a NaN equals a NaN).
template <typename T>
double channelDifference(T a, T b) {
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(a) || std::isnan(b))
      return std::isnan(a) && std::isnan(b) ? 0.0 : std::numeric_limits<double>::infinity();
    if (a == b) return 0.0;  // two equal infinities too
  }
  return std::abs(double(a) - double(b));  // exact: doubles hold every 8/16-bit and float value
}

template <typename T>
void compareRows(const cv::Mat& image, const cv::Mat& reference, const cv::Mat& context,
                 ImageDifference& d) {
  const int channels = image.channels();
  const size_t rowValues = size_t(image.cols) * size_t(channels);
  // The marks are made only once a pixel differs: an equal image costs no third buffer.
  const auto mark = [&](int y, int x) {
    if (d.marked.empty()) {
      // Darkened context: equal pixels stay recognisable but never look pure red.
      d.marked = cv::Mat(context.rows, context.cols, CV_8UC3);
      for (int row = 0; row < context.rows; ++row) {
        const uint8_t* in = context.ptr<uint8_t>(row);
        uint8_t* out = d.marked.ptr<uint8_t>(row);
        for (size_t i = 0; i < size_t(context.cols) * 3; ++i) out[i] = uint8_t(in[i] / 4);
      }
    }
    uint8_t* p = d.marked.ptr<uint8_t>(y) + 3 * size_t(x);
    p[0] = 0;
    p[1] = 0;
    p[2] = 255;
  };
  for (int y = 0; y < image.rows; ++y) {
    const T* a = image.ptr<T>(y);
    const T* b = reference.ptr<T>(y);
    for (size_t i = 0; i < rowValues; i += size_t(channels)) {
      double pixelLargest = 0.0;
      bool differs = false;
      for (int c = 0; c < channels; ++c) {
        const double diff = channelDifference(a[i + c], b[i + c]);
        if (diff != 0.0) differs = true;
        pixelLargest = std::max(pixelLargest, diff);
      }
      if (!differs) continue;
      ++d.differingPixels;
      d.largest = std::max(d.largest, pixelLargest);
      mark(y, int(i / size_t(channels)));
    }
  }
}

}  // namespace

ImageDifference compareImages(const cv::Mat& image, const cv::Mat& reference,
                              const cv::Mat& context) {
  ImageDifference d;
  if (image.size() != reference.size() || image.type() != reference.type()) return d;
  if (context.size() != image.size() || context.type() != CV_8UC3)
    throw std::invalid_argument("compareImages: the context must be 8-bit BGR, the image's size");
  d.comparable = true;
  d.pixels = size_t(image.rows) * size_t(image.cols);
  switch (image.depth()) {
    case CV_8U:
      compareRows<uint8_t>(image, reference, context, d);
      break;
    case CV_16U:
      compareRows<uint16_t>(image, reference, context, d);
      break;
    case CV_32F:
      compareRows<float>(image, reference, context, d);
      break;
    default:
      throw std::invalid_argument("compareImages: channels of 8 or 16 bits or float only");
  }
  return d;
}

std::string describeImage(const cv::Mat& image) {
  const char* depth = "16-bit float";  // CV_16F, the one depth left
  switch (image.depth()) {
    case CV_8U:
      depth = "8-bit";
      break;
    case CV_8S:
      depth = "8-bit signed";
      break;
    case CV_16U:
      depth = "16-bit";
      break;
    case CV_16S:
      depth = "16-bit signed";
      break;
    case CV_32S:
      depth = "32-bit integer";
      break;
    case CV_32F:
      depth = "32-bit float";
      break;
    case CV_64F:
      depth = "64-bit float";
      break;
    default:
      break;
  }
  const int channels = image.channels();
  return std::to_string(image.cols) + "x" + std::to_string(image.rows) + " " + depth + ", " +
         std::to_string(channels) + (channels == 1 ? " channel" : " channels");
}

}  // namespace zrender
