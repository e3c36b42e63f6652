#pragma once

// Screen triangles and z-pyramids built directly by the tests of the pyramid, its rasterizer
// and the octree's node test.

#include <cstdint>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"

namespace zrender::test {

// A screen triangle with corners given in sample coordinates (snapped to the 1/256 grid; pass
// them positively oriented to draw it), face id `id` and the constant depth `depth` (plane
// a = b = 0, c = depth).
ScreenTriangle makeTriangle(double x0, double y0, double x1, double y1, double x2, double y2,
                            uint32_t id, double depth);

// Faces 0 and 1 of `scene` (a wall) drawn into a fresh buffer and its z-pyramid.
struct WallPyramid {
  FrameBuffer fb;
  HzbRasterizer r;
  WallPyramid(const Scene& scene, const Camera& camera);
  WallPyramid(const WallPyramid&) = delete;  // r points into fb
  WallPyramid& operator=(const WallPyramid&) = delete;
};

}  // namespace zrender::test
