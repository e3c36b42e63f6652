#pragma once

#include <cstddef>

#include "zrender/scene/Transforms.hpp"

namespace zrender {

// Room for the result of one Sutherland–Hodgman pass over a polygon of `count` corners: the
// inside corners plus one per edge that crosses the plane. A convex polygon gains at most one
// corner, but a concave one can reach 3 * count / 2 (corners alternately in and out).
inline size_t clipPassCapacity(size_t count) {
  return count + count / 2 + 1;
}
inline size_t clipNearFarCapacity(size_t count) {
  return clipPassCapacity(clipPassCapacity(count));
}
inline size_t clipGuardBandCapacity(size_t count) {
  return clipPassCapacity(clipPassCapacity(clipPassCapacity(clipPassCapacity(count))));
}

// Sutherland–Hodgman clipping of a polygon in homogeneous clip space against the near
// (z >= -w) and far (z <= w) planes. `out` and `scratch` must hold clipNearFarCapacity(count)
// points. Returns the new count (0 when nothing is left). Intersections are computed from the
// edge's endpoints in a fixed order so that an edge shared by two faces is cut at the same
// point for both.
size_t clipNearFar(const Vec4* in, size_t count, Vec4* out, Vec4* scratch);

// Clips a window-space polygon (x, y in samples) to the square [-guard, guard]^2 so that snapped
// coordinates stay in range. `out` and `scratch` must hold clipGuardBandCapacity(count) points.
size_t clipGuardBand(const Vec3* in, size_t count, double guard, Vec3* out, Vec3* scratch);

}  // namespace zrender
