#pragma once

#include <vector>

#include "zrender/raster/FrameGeometry.hpp"

namespace zrender {

// The triangles of a frame in bands of 32 sample rows, top to bottom, in submission (face id)
// order within a band, and copied so that a pixel loop reads them sequentially: the rows a
// triangle touches are then still in cache from its neighbours. Used by the triangle-based
// algorithms; the order never changes their result (DepthKey ordering is order-independent).
class TriangleBands {
 public:
  static constexpr int kBandShift = 5;  // 32 rows

  // The triangles of `g` that reach the width x height sample image, sorted by the band of
  // their first row (a counting sort: linear, stable). Valid until the next call.
  const std::vector<ScreenTriangle>& sort(const FrameGeometry& g, int width, int height) {
    return sort(g, 0, width, height);
  }
  // The same for the triangles of `g` from index `first` on.
  const std::vector<ScreenTriangle>& sort(const FrameGeometry& g, size_t first, int width,
                                          int height);

  // After sort(): the bands, and the triangles of band b (first rows b * 32 to b * 32 + 31)
  // at indices [bandStart(b), bandStart(b + 1)) of the sorted triangles.
  int bandCount() const { return int(bandStart_.size()) - 1; }
  uint32_t bandStart(int band) const { return bandStart_[size_t(band)]; }

 private:
  std::vector<uint32_t> band_, bandStart_, cursor_;  // scratch kept from frame to frame
  std::vector<ScreenTriangle> sorted_;
};

}  // namespace zrender
