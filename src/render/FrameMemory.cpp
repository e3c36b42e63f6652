#include "zrender/render/FrameMemory.hpp"

#include <algorithm>

namespace zrender {

bool ColorImage::resize(int width, int height) {
  if (image_.cols == width && image_.rows == height && !image_.empty()) return false;
  // New bytes rather than grown ones: nothing to copy.
  decltype(bytes_) fresh(size_t(std::max(width, 0)) * size_t(std::max(height, 0)) * 3);
  bytes_.swap(fresh);
  image_ = cv::Mat(height, width, CV_8UC3, bytes_.data(), size_t(std::max(width, 0)) * 3);
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
  // One write per page: the fault, where the kernel zeroes the page, is the cost to move out of
  // the first frame; clearing the keys here too would be done again by that frame.
  unsigned char* first;
  unsigned char* end;
  if (part < keyParts_) {
    auto* keys = reinterpret_cast<unsigned char*>(buffer.data());
    const size_t bytes = buffer.size() * sizeof(DepthKey);
    first = keys + bytes * part / keyParts_;
    end = keys + bytes * (part + 1) / keyParts_;
  } else {
    part -= keyParts_;
    const cv::Mat& image = color.image();
    const size_t bytes = size_t(image.rows) * image.step;
    first = image.data + bytes * part / colorParts_;
    end = image.data + bytes * (part + 1) / colorParts_;
  }
  constexpr size_t kPage = 4096;  // bytes; huge pages are faulted by their first write
  for (unsigned char* p = first; p < end; p += kPage) *static_cast<volatile unsigned char*>(p) = 0;
}

}  // namespace zrender
