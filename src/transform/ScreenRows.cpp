#include "zrender/transform/ScreenRows.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

RowSpan screenRows(const Scene& scene, const Camera& camera, int heightSamples) {
  const RowSpan all{0, std::max(heightSamples, 0)};
  const Mat4 viewProjection = camera.projection * camera.view;
  double y0 = HUGE_VAL, y1 = -HUGE_VAL;  // samples, down
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    const Box3& box = scene.modelOf(k).box;
    const Mat4 mvp = viewProjection * scene.modelMatrix(k);
    for (int c = 0; c < 8; ++c) {
      const Vec4 p = mvp * Vec4(c & 1 ? box.hi[0] : box.lo[0], c & 2 ? box.hi[1] : box.lo[1],
                                c & 4 ? box.hi[2] : box.lo[2], 1.0);
      // NaN fails too.
      if (!(p[3] > 0.0 && p[2] > -p[3])) return all;
      const double y = (1.0 - p[1] / p[3]) * 0.5 * heightSamples;
      y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (!(y0 <= y1)) return all;
  RowSpan rows;
  rows.begin = int(std::clamp(std::floor(y0) - 1.0, 0.0, double(all.end)));
  rows.end = int(std::clamp(std::ceil(y1) + 1.0, double(rows.begin), double(all.end)));
  return rows;
}

}  // namespace zrender
