#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// The sample rows [first, last] of the image that a face's corners span (clamped to it):
// what binning faces by rows needs, without reading the corners again. first > last when the
// face reaches no row.
struct FaceRowSpan {
  uint16_t first, last;  // sample rows: at most 16384 pixels times 2 (MSAA 4) fit
};

// The span of a face whose corners' y lie in [minY, maxY] (fixed point) on an image of
// `height` sample rows.
inline FaceRowSpan faceRowSpan(int32_t minY, int32_t maxY, int height) {
  const int first = std::max(firstSampleAtOrAfter(minY), 0);
  const int last = std::min(lastSampleAtOrBefore(maxY), height - 1);
  if (first > last) return FaceRowSpan{1, 0};
  return FaceRowSpan{uint16_t(first), uint16_t(last)};
}

// The most corners a face may have after clipping (ScreenFace's counts are 16-bit).
constexpr uint32_t kMaxScreenFaceCorners = 0xFFFF;

// A face after transform, near/far clipping, snapping and culling: a polygon in fixed-point
// sample coordinates plus its triangulation. All algorithms read the same FrameGeometry.
struct ScreenFace {
  uint32_t id;             // face id (docs/design.md, Faces, ids and shading)
  uint32_t firstVertex;    // corners in FrameGeometry::vertices, as projected (either winding)
  uint32_t firstTriangle;  // pieces in FrameGeometry::triangles (at least one), which carry
  uint16_t triangleCount;  // the face's depth plane
  uint16_t vertexCount;    // 3..kMaxScreenFaceCorners
  FaceRowSpan rows;        // of its corners, faceRowSpan()
  bool frontFacing;        // counter-clockwise in NDC
};

// A triangulation piece of a face, positively oriented (orient2d(v0, v1, v2) > 0). The face's
// id and depth plane live here so that the pixel loops never look the face up: with the
// faces in a separate array that look-up was a cache miss per triangle. (The face's plane is
// its first triangle's; a face record without it is less memory to write per frame.)
struct ScreenTriangle {
  FixedPoint v[3];
  uint32_t face;     // index into FrameGeometry::faces
  uint32_t id;       // = faces[face].id
  DepthPlane plane;  // window depth over the face, in sample coordinates
};

// Per-frame counters of the transform stage (docs/design.md, Timings and JSON: names in comments).
struct TransformCounters {
  uint64_t backfaceCulled = 0;  // triangles_backface_culled (faces, counted in triangles)
  uint64_t clippedAway = 0;     // triangles_clipped_away: outside near/far or the view
  uint64_t degenerate = 0;      // zero area after snapping, fewer than 3 corners, non-simple
  uint64_t filtered = 0;        // dropped by a TriangleFilter's hidden tiles (HiddenTiles)

  TransformCounters& operator+=(const TransformCounters& o) {
    backfaceCulled += o.backfaceCulled;
    clippedAway += o.clippedAway;
    degenerate += o.degenerate;
    filtered += o.filtered;
    return *this;
  }
};

// The arrays of a frame's geometry: written in full after they grow (UninitializedAllocator).
template <class T>
using GeometryVector = std::vector<T, UninitializedAllocator<T>>;

struct FrameGeometry;
// The frame's faces in parts, part after part (a GeometrySource pull with parts): what the shader
// reads of them (their ids), without a join into one geometry.
using FaceParts = std::vector<const FrameGeometry*>;

struct FrameGeometry {
  int width = 0, height = 0;  // in samples (pixels times 2 with MSAA 4)
  GeometryVector<FixedPoint> vertices;
  GeometryVector<ScreenFace> faces;
  GeometryVector<ScreenTriangle> triangles;
  TransformCounters counters;

  void clear() {
    vertices.clear();
    faces.clear();
    triangles.clear();
    counters = TransformCounters();
  }
};

// The faces that `parts` hold together.
// Views of `geometries`, valid while they live unresized.
inline FaceParts partsOf(const std::vector<FrameGeometry>& geometries) {
  FaceParts parts;
  parts.reserve(geometries.size());
  for (const FrameGeometry& g : geometries) parts.push_back(&g);
  return parts;
}

inline size_t totalFaces(const FaceParts& parts) {
  size_t n = 0;
  for (const FrameGeometry* part : parts) n += part->faces.size();
  return n;
}

}  // namespace zrender
