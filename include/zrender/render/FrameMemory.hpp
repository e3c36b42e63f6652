#pragma once

#include <cstddef>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/base/HugePageAllocator.hpp"
#include "zrender/raster/FrameBuffer.hpp"

namespace zrender {

// A frame's color image, 8-bit BGR, in memory of its own in huge pages, as the key buffer:
// its first write then faults a 2 MiB page at a time instead of 4 KiB.
class ColorImage {
 public:
  ColorImage() = default;
  // Moved, the pixels stay where they are, and so does the view of them; a copy would point
  // at the original's.
  ColorImage(ColorImage&&) = default;
  ColorImage& operator=(ColorImage&&) = default;
  ColorImage(const ColorImage&) = delete;
  ColorImage& operator=(const ColorImage&) = delete;

  // Sizes it to `width` x `height` pixels: new memory, its pixels indeterminate, when the
  // size changes; true then.
  bool resize(int width, int height);
  cv::Mat& image() { return image_; }
  const cv::Mat& image() const { return image_; }

 private:
  std::vector<unsigned char, HugePageAllocator<unsigned char>> bytes_;
  cv::Mat image_;  // 8-bit BGR, a view of bytes_
};

// The buffers a Renderer draws frames into: the key buffer and the color image.
struct FrameMemory {
  FrameBuffer buffer;
  ColorImage color;

  FrameMemory() = default;
  // Buffers for frames of `width` x `height` pixels with `msaa` samples per pixel, not yet
  // written. Their pages faulted in part by part (touchPart), beside the renderer's prepare,
  // and given to the renderer (Renderer::adoptMemory), they spare its first frame the kernel's
  // zeroing of new pages (the key buffer of a 1800 x 1800 frame is 26 MB; what a MB costs:
  // docs/performance.md, The machine's two processors).
  FrameMemory(int width, int height, int msaa);

  // The parts it is written in, about a huge page (2 MiB) each: jobs of their own, which
  // whichever thread is free takes.
  size_t parts() const;
  // Faults in the pages of part `part` < parts() by a write to each; what they then hold is
  // unspecified (every frame clears its keys and shades every pixel).
  void touchPart(size_t part);

 private:
  size_t keyParts_ = 0, colorParts_ = 0;
};

// Samples per pixel side for `msaa` samples per pixel (1 or 4).
inline int sampleScaleOf(int msaa) {
  return msaa == 4 ? 2 : 1;
}

}  // namespace zrender
