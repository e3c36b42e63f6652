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

FrameMemory firstTouchedFrameMemory(int width, int height, int msaa) {
  FrameMemory memory;
  const int scale = sampleScaleOf(msaa);
  memory.buffer.resize(width * scale, height * scale);
  memory.buffer.clear();
  memory.color.resize(width, height);
  memory.color.mat().setTo(cv::Scalar::all(0));
  return memory;
}

}  // namespace zrender
