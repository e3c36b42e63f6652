#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// Triangulates a simple polygon given in fixed point, by fan when convex and by ear clipping
// (exact integer predicates) otherwise. Appends index triples, each positively oriented
// (orient2d > 0); zero-area pieces are left out. `scratch` avoids allocations across calls.
// Returns false when the polygon is not simple (no ear can be found); the caller then skips the
// face so that every algorithm treats it the same way.
bool triangulatePolygon(const FixedPoint* points, uint32_t count,
                        std::vector<std::array<uint32_t, 3>>& out, std::vector<uint32_t>& scratch);

}  // namespace zrender
