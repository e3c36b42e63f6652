#include "zrender/transform/InstanceView.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

InstanceView viewOfInstance(const Mat4& m, const Box3& bounds, const VertexViewport& viewport) {
  InstanceView view;
  // Clip coordinates are affine in the position, so over the box they are bounded by its
  // corners. A vertex's own product rounds each of its four terms and three sums: within
  // 2^-50 of reach[i], the sum of the terms' magnitudes. A plane rejects the instance only when
  // every corner is beyond it by far more than that (1e-9 of the reach), so that every vertex's
  // outcode has that plane's bit whatever the rounding.
  double reach[4];
  for (int i = 0; i < 4; ++i) {
    reach[i] = std::abs(m(i, 3));
    for (int j = 0; j < 3; ++j)
      reach[i] += std::abs(m(i, j)) * std::max(std::abs(bounds.lo[j]), std::abs(bounds.hi[j]));
    if (!(reach[i] < 1e300)) return view;  // NaN or huge: leave it to the vertices
  }
  // Plane i: 2a + s beyond it, for coordinate a = i / 2 against w, on side s = i % 2.
  double beyond[6];
  for (double& b : beyond) b = HUGE_VAL;
  double minW = HUGE_VAL, minNdcZ = HUGE_VAL;
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;  // samples
  for (int c = 0; c < 8; ++c) {
    const Vec3 p((c & 1) ? bounds.hi[0] : bounds.lo[0], (c & 2) ? bounds.hi[1] : bounds.lo[1],
                 (c & 4) ? bounds.hi[2] : bounds.lo[2]);
    const Vec4 clip = m * Vec4(p[0], p[1], p[2], 1.0);
    for (int a = 0; a < 3; ++a) {
      beyond[2 * a] = std::min(beyond[2 * a], -(clip[a] + clip[3]));       // a < -w
      beyond[2 * a + 1] = std::min(beyond[2 * a + 1], clip[a] - clip[3]);  // a > w
    }
    minW = std::min(minW, clip[3]);
    minNdcZ = std::min(minNdcZ, clip[2] / clip[3]);
    const double x = (clip[0] / clip[3] + 1.0) * 0.5 * viewport.width * viewport.scale;
    const double y = (1.0 - clip[1] / clip[3]) * 0.5 * viewport.height * viewport.scale;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  for (int i = 0; i < 6; ++i)
    if (beyond[i] > 1e-9 * (reach[i / 2] + reach[3])) view.outside = true;
  // z / w over the box, where w > 0 throughout, is least at a corner (a ratio of affine
  // functions is monotonic along every line). Each vertex's z / w is within 2^-49 of
  // (reach[2] + |z / w| reach[3]) / w of its exact value, and so are the corners': 1e-9 of that
  // bounds both with room to spare. The window depth is (z / w + 1) / 2.
  if (minW > 1e-6 * reach[3] && std::isfinite(minNdcZ)) {
    const double slack = 1e-9 * (reach[2] + (std::abs(minNdcZ) + 1.0) * reach[3]) / minW;
    const double depth = (minNdcZ - slack + 1.0) * 0.5 - 1e-12;
    if (depth > 0.0) {
      float f = static_cast<float>(depth);
      if (double(f) > depth) f = nextFloatTowardZero(f);
      view.nearest = std::min(f, 1.0f);
      // The box's projection (w > 0 at every corner), widened for rounding and snapping.
      const double w = viewport.width * viewport.scale - 1.0,
                   h = viewport.height * viewport.scale - 1.0;
      view.area.minX = int(std::min(std::max(std::floor(x0) - 2.0, 0.0), w));
      view.area.maxX = int(std::min(std::max(std::ceil(x1) + 2.0, 0.0), w));
      view.area.minY = int(std::min(std::max(std::floor(y0) - 2.0, 0.0), h));
      view.area.maxY = int(std::min(std::max(std::ceil(y1) + 2.0, 0.0), h));
    }
  }
  return view;
}

}  // namespace zrender
