#pragma once

#include <cstddef>

#include "zrender/Transforms.hpp"

namespace zrender {

// Sutherland–Hodgman clipping of a polygon in homogeneous clip space against the near
// (z >= -w) and far (z <= w) planes. `out` must hold count + 2 points. Returns the new count
// (0 when nothing is left). Intersections are computed from the edge's endpoints in a fixed
// order so that an edge shared by two faces is cut at the same point for both.
size_t clipNearFar(const Vec4* in, size_t count, Vec4* out, Vec4* scratch);

// Clips a window-space polygon (x, y in samples) to the square [-guard, guard]^2 so that snapped
// coordinates stay in range. `out` and `scratch` must hold count + 4 points.
size_t clipGuardBand(const Vec3* in, size_t count, double guard, Vec3* out, Vec3* scratch);

}  // namespace zrender
