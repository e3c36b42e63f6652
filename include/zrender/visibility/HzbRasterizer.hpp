#pragma once

#include <algorithm>
#include <cstdint>

#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/raster/TriangleFill.hpp"
#include "zrender/visibility/CoincidentTriangles.hpp"
#include "zrender/visibility/NearestKey.hpp"

namespace zrender {

// The triangle stage shared by `hierarchical` and `octree`: a triangle whose nearest key is
// behind the z-pyramid over its sample bounds is rejected before any pixel work; the others
// are filled exactly as by the z-buffer and the pyramid is brought up to date.
class HzbRasterizer {
 public:
  // Whether a triangle is proved hidden from its snapped corners `v` and the least depth of
  // its corners alone (the first test of drawTriangle); counts it in `stats` if so.
  bool rejects(const FixedPoint* v, float nearestDepth, uint32_t faceId, RenderStats& stats) const {
    SampleRect r = sampleBounds(v[0], v[1], v[2], fb_->width(), fb_->height());
    r.minY = std::max(r.minY, rowBegin_);
    r.maxY = std::min(r.maxY, rowEnd_ - 1);
    if (r.empty()) return true;  // no sample centre in the image (or the band)
    if (!pyramid_.occludes(r.minX, r.minY, r.maxX, r.maxY, makeDepthKey(nearestDepth, faceId)))
      return false;
    ++stats.trianglesHzbCulled;
    return true;
  }
  // Starts a frame: the buffer is logically cleared (and physically cleared row by row as
  // triangles reach it).
  void begin(FrameBuffer& fb) { begin(fb, 0, fb.height()); }
  // The same for the band of sample rows [rowBegin, rowEnd) alone (rowBegin a multiple of
  // DepthPyramid::kTileSize), with a pyramid of its own: triangles are drawn clipped to it.
  void begin(FrameBuffer& fb, int rowBegin, int rowEnd) {
    fb_ = &fb;
    rowBegin_ = rowBegin;
    rowEnd_ = rowEnd;
    pyramid_.begin(fb, rowBegin, rowEnd);
    coincident_.clear();
  }
  void drawTriangle(const ScreenTriangle& t, RenderStats& stats);
  // Asks the cache for the buffer lines a triangle will read (its bounds' end samples on each
  // row; rows of small triangles are one or two lines), ahead of drawTriangle.
  void prefetch(const ScreenTriangle& t) const {
    const FixedPoint* v = t.v;
    const int minX = std::max(firstSampleAtOrAfter(std::min({v[0].x, v[1].x, v[2].x})), 0);
    const int maxX =
        std::min(lastSampleAtOrBefore(std::max({v[0].x, v[1].x, v[2].x})), fb_->width() - 1);
    const int minY = std::max(firstSampleAtOrAfter(std::min({v[0].y, v[1].y, v[2].y})), 0);
    const int maxY = std::min(lastSampleAtOrBefore(std::max({v[0].y, v[1].y, v[2].y})),
                              std::min(fb_->height() - 1, minY + 15));
    if (minX > maxX) return;
    for (int y = minY; y <= maxY; ++y) {
      __builtin_prefetch(fb_->row(y) + minX, 1);
      __builtin_prefetch(fb_->row(y) + maxX, 1);
    }
  }
  // Clears what no triangle reached in sample rows [0, rows), so that they can be read.
  void finishRows(int rows) { pyramid_.prepareRows(rowBegin_, std::min(rows, rowEnd_) - 1); }
  // Clears what no triangle reached; the buffer is then final.
  void finish() { pyramid_.finish(); }
  const DepthPyramid& pyramid() const { return pyramid_; }

 private:
  FrameBuffer* fb_ = nullptr;
  int rowBegin_ = 0, rowEnd_ = 0;  // the rows drawn: the image's, or a band's
  DepthPyramid pyramid_;
  CoincidentTriangles coincident_;  // big triangles drawn this frame
  TriangleFillFunction fill_ = triangleFill();
};

}  // namespace zrender
