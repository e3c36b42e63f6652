#pragma once

#include <vector>

#include "zrender/RasterRules.hpp"

namespace zrender {

// The visibility result of a frame: one DepthKey (depth and face id) per sample. Color is
// computed afterwards from it (deferred shading), so all algorithms only have to agree here.
class FrameBuffer {
 public:
  void resize(int width, int height) {
    width_ = width;
    height_ = height;
    keys_.resize(size_t(width) * size_t(height));
  }
  void clear() { std::fill(keys_.begin(), keys_.end(), kClearKey); }

  int width() const { return width_; }    // samples
  int height() const { return height_; }  // samples
  DepthKey* row(int y) { return keys_.data() + size_t(y) * size_t(width_); }
  const DepthKey* row(int y) const { return keys_.data() + size_t(y) * size_t(width_); }
  DepthKey* data() { return keys_.data(); }
  const DepthKey* data() const { return keys_.data(); }
  size_t size() const { return keys_.size(); }

  bool operator==(const FrameBuffer& o) const {
    return width_ == o.width_ && height_ == o.height_ && keys_ == o.keys_;
  }

 private:
  int width_ = 0, height_ = 0;
  std::vector<DepthKey> keys_;
};

}  // namespace zrender
