#pragma once

// The comparison of a rendered image with a reference image (`zrender SCENE --reference REF`,
// docs/design.md, Reference images): which pixels differ, by how much, and a picture of where.

#include <cstddef>
#include <string>

#include <opencv2/core/mat.hpp>

namespace zrender {

struct ImageDifference {
  // Same size, channel count and channel type: only then is the rest set.
  bool comparable = false;
  size_t pixels = 0;           // width x height
  size_t differingPixels = 0;  // pixels with at least one channel unequal
  // The largest absolute difference of one channel, in the images' own units: a whole number
  // for 8- and 16-bit images; for float ones, a NaN against a number counts as infinite.
  double largest = 0.0;
  // 8-bit BGR, the images' size: `context` at a quarter of its brightness where the pixels are
  // equal, pure red (0, 0, 255) where they differ. Empty when no pixel differs.
  cv::Mat marked;
};

// Compares `image` with `reference` channel by channel, exactly: 8-bit, 16-bit or 32-bit float
// channels (a NaN equals a NaN). `context` (8-bit BGR, the size of `image`) is what `marked`
// shows around the differing pixels. std::invalid_argument for another channel type or a
// context of another size or type.
ImageDifference compareImages(const cv::Mat& image, const cv::Mat& reference,
                              const cv::Mat& context);

// An image's size and type in words, for messages: "32x24 8-bit, 3 channels",
// "32x24 32-bit float, 1 channel".
std::string describeImage(const cv::Mat& image);

}  // namespace zrender
