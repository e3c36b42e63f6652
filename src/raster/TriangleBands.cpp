#include "zrender/raster/TriangleBands.hpp"

#include <algorithm>

namespace zrender {

const std::vector<ScreenTriangle>& TriangleBands::sort(const FrameGeometry& g, size_t first,
                                                       int width, int height) {
  const int bandCount = ((height - 1) >> kBandShift) + 1;
  const ScreenTriangle* triangles = g.triangles.data() + first;
  const size_t count = g.triangles.size() - first;
  band_.resize(count);
  bandStart_.assign(size_t(bandCount) + 1, 0);
  for (size_t i = 0; i < count; ++i) {
    const FixedPoint* v = triangles[i].v;
    const int top = std::max(firstSampleAtOrAfter(std::min({v[0].y, v[1].y, v[2].y})), 0);
    const int bottom = lastSampleAtOrBefore(std::max({v[0].y, v[1].y, v[2].y}));
    const int left = firstSampleAtOrAfter(std::min({v[0].x, v[1].x, v[2].x}));
    const int right = lastSampleAtOrBefore(std::max({v[0].x, v[1].x, v[2].x}));
    const bool inside =
        top <= std::min(bottom, height - 1) && right >= 0 && left < width && left <= right;
    band_[i] = inside ? uint32_t(top >> kBandShift) : uint32_t(bandCount);
    if (inside) ++bandStart_[band_[i] + 1];
  }
  for (int b = 0; b < bandCount; ++b) bandStart_[size_t(b) + 1] += bandStart_[size_t(b)];
  sorted_.resize(bandStart_[size_t(bandCount)]);
  cursor_.assign(bandStart_.begin(), bandStart_.end() - 1);
  for (size_t i = 0; i < count; ++i)
    if (band_[i] < uint32_t(bandCount)) sorted_[cursor_[band_[i]]++] = triangles[i];
  return sorted_;
}

}  // namespace zrender
