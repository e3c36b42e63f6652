#include "support/CoverageOracle.hpp"

#include <utility>

namespace zrender::test {

bool oracleCovers(const Polygon& poly, int i, int j) {
  const __int128 s = __int128(1) << 32;
  const __int128 px = __int128(sampleCentre(i)) * s + (__int128(1) << 16);
  const __int128 py = __int128(sampleCentre(j)) * s + 1;
  bool inside = false;
  for (size_t k = 0; k < poly.size(); ++k) {
    const FixedPoint& a = poly[k];
    const FixedPoint& b = poly[(k + 1) % poly.size()];
    const __int128 ax = a.x * s, ay = a.y * s, bx = b.x * s, by = b.y * s;
    if ((ay > py) == (by > py)) continue;
    const __int128 lhs = (px - ax) * (by - ay), rhs = (py - ay) * (bx - ax);
    if (by > ay ? lhs > rhs : lhs < rhs) inside = !inside;  // crossing left of the point
  }
  return inside;
}

void addCoverage(const FixedPoint v[3], int size, std::vector<int>& count) {
  TriangleSetup s;
  if (!s.setup(v, size, size)) return;
  for (int y = s.minY; y <= s.maxY; ++y) {
    for (int x = s.minX; x <= s.maxX; ++x) {
      bool in = true;
      for (const EdgeFunction& e : s.edge)
        in &= e.covers(e.value + e.stepX * (x - s.minX) + e.stepY * (y - s.minY));
      count[size_t(y) * size + x] += in;
    }
  }
}

std::array<FixedPoint, 3> oriented(FixedPoint a, FixedPoint b, FixedPoint c) {
  if (orient2d(a, b, c) < 0) std::swap(b, c);
  return {a, b, c};
}

}  // namespace zrender::test
