#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "zrender/base/HugePageAllocator.hpp"
#include "zrender/raster/KeyFill.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// The visibility result of a frame: one DepthKey (depth and face id) per sample. Color is
// computed afterwards from it (deferred shading), so all algorithms only have to agree here.
class FrameBuffer {
 public:
  // Keys after the last sample, never part of the image: room for a vector loop's last block.
  // The pixel loops do not reach past a row's end (another thread may draw the next row).
  static constexpr size_t kPadding = 4;

  // The samples' keys are left as they are (new ones indeterminate) until the algorithm clears
  // its rows; the padding is cleared here. True when the keys are in new memory, which the
  // kernel zeroes page by page at its first write.
  bool resize(int width, int height) {
    width_ = width;
    height_ = height;
    const size_t n = size_t(width) * size_t(height) + kPadding;
    const bool fresh = n > keys_.capacity();
    keys_.resize(n);
    std::fill(keys_.end() - kPadding, keys_.end(), kClearKey);
    return fresh;
  }
  void clear() { std::fill(keys_.begin(), keys_.end(), kClearKey); }
  // Rows [first, end), cleared.
  void clearRows(int first, int end) {
    fillKeys(row(first), size_t(end - first) * size_t(width_), kClearKey);
  }
  // Part `part` of `parts` equal, contiguous parts of the samples, cleared.
  void clearPart(size_t part, size_t parts) {
    const size_t n = size();
    std::fill(keys_.begin() + std::ptrdiff_t(n * part / parts),
              keys_.begin() + std::ptrdiff_t(n * (part + 1) / parts), kClearKey);
  }

  int width() const { return width_; }    // samples
  int height() const { return height_; }  // samples
  DepthKey* row(int y) { return keys_.data() + size_t(y) * size_t(width_); }
  const DepthKey* row(int y) const { return keys_.data() + size_t(y) * size_t(width_); }
  DepthKey* data() { return keys_.data(); }
  const DepthKey* data() const { return keys_.data(); }
  size_t size() const { return size_t(width_) * size_t(height_); }  // samples

  bool operator==(const FrameBuffer& o) const {
    return width_ == o.width_ && height_ == o.height_ &&
           std::equal(keys_.begin(), keys_.begin() + std::ptrdiff_t(size()), o.keys_.begin());
  }

 private:
  int width_ = 0, height_ = 0;
  std::vector<DepthKey, HugePageAllocator<DepthKey>> keys_;
};

// The sample a pixel's images show (depth, ids, normals): with MSAA (`scale` 2) its nearest,
// the smallest key, the first in row order among equal ones.
struct PixelSample {
  DepthKey key;
  int x, y;  // samples
};
inline PixelSample nearestSample(const FrameBuffer& fb, int scale, int x, int y) {
  PixelSample best{fb.row(y * scale)[x * scale], x * scale, y * scale};
  for (int j = 0; j < scale; ++j) {
    const DepthKey* row = fb.row(y * scale + j);
    for (int i = 0; i < scale; ++i) {
      if (row[x * scale + i] < best.key) best = {row[x * scale + i], x * scale + i, y * scale + j};
    }
  }
  return best;
}

}  // namespace zrender
