#include "zrender/render/FrameMemory.hpp"

#include <algorithm>

namespace zrender {

bool ColorImage::resize(int width, int height) {
  if (mat_.cols == width && mat_.rows == height && !mat_.empty()) return false;
  // New bytes rather than grown ones: nothing to copy.
  decltype(bytes_) fresh(size_t(std::max(width, 0)) * size_t(std::max(height, 0)) * 3);
  bytes_.swap(fresh);
  mat_ = cv::Mat(height, width, CV_8UC3, bytes_.data());
  return true;
}

namespace {

constexpr size_t kPartBytes = size_t(2) << 20;

size_t partsOf(size_t bytes) {
  return (bytes + kPartBytes - 1) / kPartBytes;
}

}  // namespace

FrameMemory::FrameMemory(int width, int height, int msaa) {
  const int scale = sampleScaleOf(msaa);
  buffer.resize(width * scale, height * scale);
  color.resize(width, height);
  keyParts_ = partsOf(buffer.size() * sizeof(DepthKey));
  colorParts_ = std::min(partsOf(size_t(width) * size_t(height) * 3), size_t(std::max(height, 0)));
}

size_t FrameMemory::parts() const {
  return keyParts_ + colorParts_;
}

void FrameMemory::touchPart(size_t part) {
  if (part < keyParts_) {
    buffer.clearPart(part, keyParts_);
    return;
  }
  part -= keyParts_;
  const int rows = color.mat().rows;
  color.mat()
      .rowRange(int(rows * part / colorParts_), int(rows * (part + 1) / colorParts_))
      .setTo(cv::Scalar::all(0));
}

}  // namespace zrender
