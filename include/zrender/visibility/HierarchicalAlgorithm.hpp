#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/raster/TriangleBands.hpp"
#include "zrender/raster/TriangleFill.hpp"
#include "zrender/visibility/CoincidentTriangles.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// A key with the given id whose depth is a float no greater than `depth`, after the clamp
// to [0, 1] that DepthPlane::at applies (a few ulps below it); 0 (never occludes) for NaN.
inline DepthKey keyAtOrBelow(double depth, uint32_t faceId) {
  if (!(depth > 0.0)) return depth <= 0.0 ? makeDepthKey(0.0f, faceId) : 0;  // NaN: 0
  // Rounding to float is monotonic and within half an ulp, so three ulps down from the
  // rounded value (positive floats order like their bits) is below `depth` with two ulps to
  // spare; the clamp to [0, 1] keeps the order.
  const uint32_t bits = floatBits(static_cast<float>(depth));
  const float f = bits > 3u ? bitsToFloat(bits - 3u) : 0.0f;
  return makeDepthKey(std::min(f, 1.0f), faceId);
}

// A lower bound of the key the face gets at any sample of the rectangle [minX, maxX] x
// [minY, maxY] (inclusive, sample indices inside the image): never greater than
// makeDepthKey(plane.at(x, plane.rowBase(y)), faceId) there, and 0 when the plane gives NaN.
// Rounding is accounted for, so it can be compared with the z-pyramid without ever breaking
// the (depth, id) order.
inline DepthKey nearestKeyOver(const DepthPlane& plane, uint32_t faceId, int minX, int minY,
                               int maxX, int maxY) {
  // The plane is affine, so its minimum over the rectangle is at the corner picked by the
  // signs of its slopes. Evaluated as DepthPlane::at does.
  const int x = plane.a >= 0.0 ? minX : maxX;
  const int y = plane.b >= 0.0 ? minY : maxY;
  const double v = plane.a * (x + 0.5) + plane.rowBase(y);
  // at() rounds two products and two sums (each within 2^-53 relative) at the corner and at
  // the sample; 2^-49 of the magnitude of the terms bounds the sum of these errors with room
  // to spare (sample indices inside the image are >= 0).
  const double reach =
      std::abs(plane.a) * (maxX + 1.0) + std::abs(plane.b) * (maxY + 1.0) + std::abs(plane.c);
  // DepthPlane clamps the depth to the face's corner range [lo, hi]: a sample just outside the
  // exact face, where the plane has risen above hi, gets hi, so the plane's bound holds only up
  // to hi; and no sample is nearer than lo.
  const DepthKey planeBound = keyAtOrBelow(v - reach * 0x1p-49, faceId);
  return std::max(std::min(planeBound, makeDepthKey(plane.maxDepth(), faceId)),
                  makeDepthKey(plane.minDepth(), faceId));
}

// The triangle stage shared by `hierarchical` and `octree`: a triangle whose nearest key is
// behind the z-pyramid over its sample bounds is rejected before any pixel work; the others
// are filled exactly as by the z-buffer and the pyramid is brought up to date.
class HzbRasterizer {
 public:
  // Whether a triangle is proved hidden from its snapped corners `v` and the least depth of
  // its corners alone (the first test of drawTriangle); counts it in `stats` if so.
  bool rejects(const FixedPoint* v, float nearestDepth, uint32_t faceId, RenderStats& stats) const {
    const SampleRect r = sampleBounds(v[0], v[1], v[2], fb_->width(), fb_->height());
    if (r.empty()) return true;  // no sample centre in the image
    if (!pyramid_.occludes(r.minX, r.minY, r.maxX, r.maxY, makeDepthKey(nearestDepth, faceId)))
      return false;
    ++stats.trianglesHzbCulled;
    return true;
  }
  // Starts a frame: the buffer is logically cleared (and physically cleared row by row as
  // triangles reach it).
  void begin(FrameBuffer& fb) {
    fb_ = &fb;
    pyramid_.begin(fb);
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
  void finishRows(int rows) { pyramid_.prepareRows(0, std::min(rows, fb_->height()) - 1); }
  // Clears what no triangle reached; the buffer is then final.
  void finish() { pyramid_.finish(); }
  const DepthPyramid& pyramid() const { return pyramid_; }

 private:
  FrameBuffer* fb_ = nullptr;
  DepthPyramid pyramid_;
  CoincidentTriangles coincident_;  // big triangles drawn this frame
  TriangleFillFunction fill_ = triangleFill();
};

// Greene, Kass and Miller's hierarchical z-buffer without the object-space octree: every face
// is transformed, and each triangle is tested against the z-pyramid before rasterization.
// Instances (of a grid) are taken one at a time, nearest first: each is transformed
// (transformInstance) with the pyramid as its previous ones left it as a filter, so that a
// triangle face already proved hidden there costs no depth plane, no storage and no sorting;
// then its triangles are drawn in bands of sample rows, top to bottom, in face id order within
// a band (TriangleBands), each tested against the pyramid again. A model whose faces come front
// to back in the file keeps most of its culling within one instance.
class HierarchicalAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "hierarchical"; }
  FaceBatches prepare(const Scene& scene) override;
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  HzbRasterizer rasterizer_;
  TriangleBands bands_;
  Vec3 meshCentre_{0, 0, 0};         // model space: the centre of the mesh's bounding box
  std::vector<uint32_t> instances_;  // this frame's instance order, nearest first
};

}  // namespace zrender
