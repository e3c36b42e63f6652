#pragma once

// The classified polygon and edge tables shared by the scan-line algorithms (`scanline`,
// `interval`), and the exact per-row stepping of a polygon edge.
//
// Coverage of a polygon drawn natively (even-odd), equivalent to the top-left rule of
// RasterRules.hpp for its triangulation: a non-horizontal edge (a, b) is active on the row whose
// centre is yc iff min(a.y, b.y) <= yc < max(a.y, b.y); sample column i is covered iff the
// number of active edges whose crossing c satisfies c <= centre(i) is odd. With
// q = the first column whose centre is >= c, that is "#{q <= i} is odd", so only the integer q
// of each active edge matters, and spans are [q1, q2), [q3, q4), ... of the sorted q values.

#include <cstdint>
#include <vector>

#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// q = ceil((N - 128 D) / (256 D)) for the crossing c = N / D of a non-horizontal edge with the
// row centre line, kept as an exact quotient and remainder and stepped one row down at a time
// (an integer DDA): no rounding, so every row gets the same q as a direct evaluation.
struct EdgeStepper {
  int64_t rem;         // q * denom - M, in [0, denom), M = N - 128 D (1/256 units times D)
  int64_t remStep;     // (256 dx) mod denom
  int64_t denom;       // 256 D, D = bottom.y - top.y > 0
  int32_t column;      // q: first sample column whose centre is at or right of the crossing
  int32_t columnStep;  // floor(dx / D)

  // Evaluates q directly on `row`; `top` is the upper end (smaller y), `bottom` the lower.
  // Exact in int64 for |coordinates| <= 2^28 (products <= 2^58).
  void start(const FixedPoint& top, const FixedPoint& bottom, int row) {
    const int64_t dx = int64_t(bottom.x) - top.x, d = int64_t(bottom.y) - top.y;
    denom = d * kSubpixel;
    const int64_t m = int64_t(top.x) * d + (sampleCentre(row) - top.y) * dx - kHalfSubpixel * d;
    const int64_t q = ceilDiv(m, denom);
    column = int32_t(q);
    rem = q * denom - m;
    const int64_t qs = floorDiv(dx, d);
    columnStep = int32_t(qs);
    remStep = (dx - qs * d) * kSubpixel;
  }
  // Advances to the next row (centre 256 units lower): M grows by 256 dx.
  // Branch-free: whether the remainder wraps is data dependent and mispredicts often.
  void step() {
    rem -= remStep;
    const int64_t wrap = -int64_t(rem < 0);  // -1 when rem < 0, else 0 (no signed shift)
    rem += denom & wrap;
    column += columnStep - int32_t(wrap);
  }
};

// A non-horizontal polygon edge that is active on at least one row of the image.
struct ClassifiedEdge {
  FixedPoint top, bottom;  // top.y < bottom.y (fixed point)
  int32_t firstRow;        // first active row, clamped to the image
  int32_t lastRow;         // last active row, clamped to the image
  uint32_t polygon;        // index into PolygonTables::polygons
};

// A face that covers at least one row of the image, with what the row loops need of it.
struct ClassifiedPolygon {
  DepthPlane plane;    // the face's depth plane (copied: the row loops read nothing else)
  uint32_t id;         // face id
  int32_t topRow;      // first row with an active edge (clamped)
  int32_t bottomRow;   // last row with an active edge (clamped)
  uint32_t edgeBegin;  // first of its edgeCount slots in a per-polygon edge pool
  uint32_t edgeCount;  // its edges that are active on some row of the image
};

// Face `face` of part `part` of a frame's geometry in parts (a GeometrySource pull with parts).
struct PartFace {
  uint32_t part;
  uint32_t face;
};

// Classified polygon table (CPT) and classified edge table (CET) of one frame, bucketed by top
// row with counting sorts and stored in that order, so that the row loops walk memory forward.
// Vectors are kept between frames so that building allocates only on growth, and those written
// in full before they are read grow without being zeroed first (UninitializedAllocator): with
// several threads, a thread's tables hold another band each time, so they grow again in every
// frame (docs/performance.md).
class PolygonTables {
 public:
  // Classifies every face of `g` against an image of width x height samples. Faces that cover
  // no sample of the image (above, below, left or right of it) are left out.
  void build(const FrameGeometry& g, int width, int height);
  // The same for the band of sample rows [rowBegin, rowEnd) of the image alone, as if the
  // image began at rowBegin, with the faces that may reach the band: faces[i] is face
  // faces[i].face of parts[faces[i].part]. A polygon or an edge that starts above the band is
  // classified as starting on its first row (and its stepping starts there, exactly).
  // triangleCount counts the faces whose first row in the image lies in the band.
  void build(const std::vector<const FrameGeometry*>& parts, int width, int height, int rowBegin,
             int rowEnd, const PartFace* faces, size_t count);

  int rowBegin = 0;  // the band's rows: the buckets below are indexed by row - rowBegin
  // Sorted by top row: the polygons whose top row is y are polygons[polygonBucket[y],
  // polygonBucket[y + 1]). Polygon indices below are indices into this table.
  std::vector<ClassifiedPolygon> polygons;
  std::vector<uint32_t> polygonBucket;  // height + 1 offsets
  // Sorted by first row: the edges that become active on row y are edges[edgeBucket[y],
  // edgeBucket[y + 1]).
  std::vector<ClassifiedEdge, UninitializedAllocator<ClassifiedEdge>> edges;
  std::vector<uint32_t> edgeBucket;  // height + 1 offsets
  // Number of polygons whose bottom row is y (they leave the active table after row y).
  std::vector<uint32_t> polygonsEnding;
  uint64_t triangleCount = 0;  // triangulation pieces of the classified polygons (a statistic)

 private:
  // build() in three steps: start the band, classify each face (in face order), sort.
  void begin(int height, int rowBegin, int rowEnd);
  void classify(const FrameGeometry& g, uint32_t f, int width);
  void sort();

  int height_ = 0, rowEnd_ = 0;  // of the build under way
  // Classification in face order, before the sorts.
  std::vector<ClassifiedPolygon> unsortedPolygons_;
  std::vector<ClassifiedEdge, UninitializedAllocator<ClassifiedEdge>> unsortedEdges_;
  std::vector<uint32_t, UninitializedAllocator<uint32_t>> newIndex_;
};

}  // namespace zrender
