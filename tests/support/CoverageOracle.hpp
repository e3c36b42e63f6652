#pragma once

// An independent oracle of the fill rule (docs/design.md, Rasterization rules): a sample is
// covered when its centre, nudged by (2^-16, 2^-32) of a 1/256 unit, lies inside the polygon by
// the even-odd rule, evaluated exactly in 128-bit integers. For coordinates below 2^12 units that
// nudge is small enough to be the infinitesimal (e, e^2) of the top-left rule.

#include <array>
#include <vector>

#include "zrender/raster/RasterRules.hpp"

namespace zrender::test {

using Polygon = std::vector<FixedPoint>;

// The oracle's images are kOracleSize x kOracleSize samples: coordinates stay below
// 16 * 256 = 2^12 units.
constexpr int kOracleSize = 16;

// Whether the oracle says sample (i, j) is inside `poly`.
bool oracleCovers(const Polygon& poly, int i, int j);

// Adds 1 to `count` (size x size samples, row by row) for every sample the shared TriangleSetup
// says the triangle `v` covers.
void addCoverage(const FixedPoint v[3], int size, std::vector<int>& count);

// Positively oriented copy of a triangle.
std::array<FixedPoint, 3> oriented(FixedPoint a, FixedPoint b, FixedPoint c);

}  // namespace zrender::test
