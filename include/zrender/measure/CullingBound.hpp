#pragma once

#include <cstddef>

#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/visibility/Octree.hpp"

namespace zrender {

// How fast exact culling could make a frame at best: the z-buffer given only the triangles of
// the faces that end up visible, as if an algorithm had culled every other one perfectly and
// for free. Its raster time bounds from below what `hierarchical` and `octree` can reach
// without a faster pixel loop (which the z-buffer would then share). Measured by
// `zrender-culling-bound` (tools/culling-bound.cpp), a developer tool, not part of `zrender`.
// The same for the octree's node culling at the granularity of its leaves (leaf*).
struct CullingBound {
  size_t triangles = 0;         // the z-buffer's triangles after the transform
  size_t visibleTriangles = 0;  // those of faces that own a sample of the final buffer
  size_t visibleFaces = 0;
  double frameMs = 0.0;          // z-buffer, transform + raster, median
  double rasterMs = 0.0;         // z-buffer raster, median
  double visibleRasterMs = 0.0;  // z-buffer raster of the visible faces' triangles, median
  bool identical = false;        // the visible faces alone give the same buffers (they must)

  // The octree as it is, and the octree with perfect culling of whole leaves: every leaf that
  // holds no visible face skipped for free, the others drawn as usual. Its frame bounds from
  // below what a better node test could reach with leaves of this size.
  size_t octreeLeavesDrawn = 0;   // leaves transformed and drawn by the octree
  size_t visibleLeaves = 0;       // leaves holding a visible face
  double octreeFrameMs = 0.0;     // median
  double leafBoundFrameMs = 0.0;  // octree skipping the leaves without a visible face, median
  double leafBoundTransformMs = 0.0;
  double leafBoundRasterMs = 0.0;
  bool leafBoundIdentical = false;  // its buffers equal the z-buffer's (they must)
};

// Renders `repeat` frames of each kind, alternated (so that all see the same machine state).
// The two octrees are built with leaves of at most `leafFaces` faces.
CullingBound measureCullingBound(const Scene& scene, const Camera& camera, int repeat,
                                 uint32_t leafFaces = Octree::kLeafFaces);

}  // namespace zrender
