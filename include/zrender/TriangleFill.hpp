#pragma once

#include "zrender/FrameBuffer.hpp"
#include "zrender/RasterRules.hpp"
#include "zrender/RenderStats.hpp"

namespace zrender {

// Depth-tests and writes every sample of a set-up triangle: the pixel loop of the z-buffer,
// shared by the triangle-based algorithms.
inline void fillTriangle(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                         FrameBuffer& fb, RenderStats& stats) {
  int64_t e0 = s.edge[0].value, e1 = s.edge[1].value, e2 = s.edge[2].value;
  const int64_t x0 = s.edge[0].stepX, x1 = s.edge[1].stepX, x2 = s.edge[2].stepX;
  uint64_t tested = 0, written = 0;
  for (int y = s.minY; y <= s.maxY; ++y) {
    const double rowBase = plane.rowBase(y);
    DepthKey* row = fb.row(y);
    int64_t r0 = e0, r1 = e1, r2 = e2;
    int x = s.minX;
    // Step to the first covered sample of the row, then test depth until the last one: a
    // triangle's samples on a row are contiguous.
    while (x <= s.maxX && (r0 | r1 | r2) < 0) {
      r0 += x0;
      r1 += x1;
      r2 += x2;
      ++x;
    }
    double xCentre = x + 0.5;
    while (x <= s.maxX && (r0 | r1 | r2) >= 0) {
      const DepthKey key = makeDepthKey(plane.atCentre(xCentre, rowBase), faceId);
      ++tested;
      if (key < row[x]) {
        row[x] = key;
        ++written;
      }
      r0 += x0;
      r1 += x1;
      r2 += x2;
      ++x;
      xCentre += 1.0;
    }
    e0 += s.edge[0].stepY;
    e1 += s.edge[1].stepY;
    e2 += s.edge[2].stepY;
  }
  stats.pixelsTested += tested;
  stats.pixelsWritten += written;
}

}  // namespace zrender
