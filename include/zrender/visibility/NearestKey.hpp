#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "zrender/raster/RasterRules.hpp"

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

}  // namespace zrender
