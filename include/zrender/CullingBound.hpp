#pragma once

#include <cstddef>

#include "zrender/Camera.hpp"
#include "zrender/Scene.hpp"

namespace zrender {

// How fast exact culling could make a frame at best: the z-buffer given only the triangles of
// the faces that end up visible, as if an algorithm had culled every other one perfectly and
// for free. Its raster time bounds from below what `hierarchical` and `octree` can reach
// without a faster pixel loop (which the z-buffer would then share). Measured by
// `zrender-culling-bound` (tools/culling-bound.cpp), a developer tool, not part of `zrender`.
struct CullingBound {
  size_t triangles = 0;         // the z-buffer's triangles after the transform
  size_t visibleTriangles = 0;  // those of faces that own a sample of the final buffer
  size_t visibleFaces = 0;
  double frameMs = 0.0;          // z-buffer, transform + raster, median
  double rasterMs = 0.0;         // z-buffer raster, median
  double visibleRasterMs = 0.0;  // z-buffer raster of the visible faces' triangles, median
  bool identical = false;        // the visible faces alone give the same buffers (they must)
};

// Renders `repeat` frames of each kind, alternated (so that both see the same machine state).
CullingBound measureCullingBound(const Scene& scene, const Camera& camera, int repeat);

}  // namespace zrender
