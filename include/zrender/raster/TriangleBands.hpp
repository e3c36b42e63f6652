#pragma once

#include <algorithm>
#include <vector>

#include "zrender/base/Threads.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RowBands.hpp"

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
  const GeometryVector<ScreenTriangle>& sort(const FrameGeometry& g, int width, int height) {
    return sort(g, 0, width, height);
  }
  // The same for the triangles of `g` from index `first` on.
  const GeometryVector<ScreenTriangle>& sort(const FrameGeometry& g, size_t first, int width,
                                             int height);

  // The triangles of `g` that reach the image, each in every band it reaches rather than only
  // its first row's, so that the bands can be drawn apart (by several threads at once, each
  // triangle clipped to the band's rows): the same order within a band. Counted and copied by
  // `threads`; valid until the next call.
  const GeometryVector<ScreenTriangle>& bin(const FrameGeometry& g, int width, int height,
                                            const Threads& threads) {
    return bin(std::vector<const FrameGeometry*>{&g}, width, height, threads);
  }
  // The same for the triangles of geometry in parts (a GeometrySource pull with parts).
  const GeometryVector<ScreenTriangle>& bin(const std::vector<const FrameGeometry*>& parts,
                                            int width, int height, const Threads& threads);

  // After sort() or bin(): the bands, and the triangles of band b (rows b * 32 to b * 32 + 31)
  // at indices [bandStart(b), bandStart(b + 1)) of the sorted triangles.
  int bandCount() const { return int(bandStart_.size()) - 1; }
  uint32_t bandStart(int band) const { return bandStart_[size_t(band)]; }
  // Whether band `band` is the first a triangle reaches (after bin(): one band counts it).
  static bool firstBandOf(const ScreenTriangle& t, int band) {
    return firstRow(t) >> kBandShift == band;
  }
  // The first sample row a triangle reaches, 0 if it starts above the image.
  static int firstRow(const ScreenTriangle& t) {
    const FixedPoint* v = t.v;
    return std::max(firstSampleAtOrAfter(std::min({v[0].y, v[1].y, v[2].y})), 0);
  }

 private:
  // Bands [first, last] that triangle `t` reaches; false when it misses the image.
  static bool bandsOf(const ScreenTriangle& t, int width, int height, int& first, int& last);

  std::vector<uint32_t> band_, bandStart_, cursor_;  // scratch kept from frame to frame
  GeometryVector<ScreenTriangle> sorted_;
  BandPlacer placer_;  // bin()
};

}  // namespace zrender
