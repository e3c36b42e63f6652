#include "zrender/raster/TriangleBands.hpp"

#include <algorithm>

namespace zrender {

bool TriangleBands::bandsOf(const ScreenTriangle& t, int width, int height, int& first, int& last) {
  const FixedPoint* v = t.v;
  const int top = firstRow(t);
  const int bottom = lastSampleAtOrBefore(std::max({v[0].y, v[1].y, v[2].y}));
  const int left = firstSampleAtOrAfter(std::min({v[0].x, v[1].x, v[2].x}));
  const int right = lastSampleAtOrBefore(std::max({v[0].x, v[1].x, v[2].x}));
  if (!(top <= std::min(bottom, height - 1) && right >= 0 && left < width && left <= right))
    return false;
  first = top >> kBandShift;
  last = std::min(bottom, height - 1) >> kBandShift;
  return true;
}

const GeometryVector<ScreenTriangle>& TriangleBands::sort(const FrameGeometry& g, size_t first,
                                                          int width, int height) {
  const int bandCount = ((height - 1) >> kBandShift) + 1;
  const ScreenTriangle* triangles = g.triangles.data() + first;
  const size_t count = g.triangles.size() - first;
  band_.resize(count);
  bandStart_.assign(size_t(bandCount) + 1, 0);
  for (size_t i = 0; i < count; ++i) {
    int top = 0, bottom = 0;
    const bool inside = bandsOf(triangles[i], width, height, top, bottom);
    band_[i] = inside ? uint32_t(top) : uint32_t(bandCount);
    if (inside) ++bandStart_[band_[i] + 1];
  }
  for (int b = 0; b < bandCount; ++b) bandStart_[size_t(b) + 1] += bandStart_[size_t(b)];
  sorted_.resize(bandStart_[size_t(bandCount)]);
  cursor_.assign(bandStart_.begin(), bandStart_.end() - 1);
  for (size_t i = 0; i < count; ++i)
    if (band_[i] < uint32_t(bandCount)) sorted_[cursor_[band_[i]]++] = triangles[i];
  return sorted_;
}

const GeometryVector<ScreenTriangle>& TriangleBands::bin(
    const std::vector<const FrameGeometry*>& parts, int width, int height, const Threads& threads) {
  const int bandCount = ((height - 1) >> kBandShift) + 1;
  const RowBands bands(height, bandCount, 1 << kBandShift);
  std::vector<size_t> sizes;
  for (const FrameGeometry* g : parts) sizes.push_back(g->triangles.size());
  // Copied into place, so that a band's pixel loop reads its triangles in a row.
  placer_.placeSegments(
      sizes, bands, threads,
      [&](size_t part, size_t i, int& first, int& last) {
        int top = 0, bottom = 0;
        if (!bandsOf(parts[part]->triangles[i], width, height, top, bottom)) return false;
        first = top << kBandShift;
        last = bottom << kBandShift;
        return true;
      },
      [&](uint32_t total) { sorted_.resize(total); },
      [&](size_t part, size_t i, uint32_t k) { sorted_[k] = parts[part]->triangles[i]; });
  bandStart_ = placer_.starts();
  return sorted_;
}

}  // namespace zrender
