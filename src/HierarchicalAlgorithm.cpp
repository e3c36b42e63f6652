#include "zrender/HierarchicalAlgorithm.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/TriangleFill.hpp"

namespace zrender {

namespace {

// `hierarchical` visits triangles in bands of 32 sample rows, top to bottom, face id order
// within a band: the rows a triangle touches are then still in cache from its neighbours, and
// the buffer is cleared just ahead of the band being drawn. Within a band the id order is
// kept, so a scene whose faces come front to back in the file keeps most of its culling.
constexpr int kBandShift = 5;

}  // namespace

void HzbRasterizer::drawTriangle(const ScreenTriangle& t, RenderStats& stats) {
  // The clipped sample bounds, as TriangleSetup::setup computes them, before the edge
  // functions: a rejected triangle costs the bounds, one plane evaluation and a few loads.
  const FixedPoint* v = t.v;
  const int width = fb_->width(), height = fb_->height();
  const int minX = std::max(firstSampleAtOrAfter(std::min({v[0].x, v[1].x, v[2].x})), 0);
  const int maxX = std::min(lastSampleAtOrBefore(std::max({v[0].x, v[1].x, v[2].x})), width - 1);
  const int minY = std::max(firstSampleAtOrAfter(std::min({v[0].y, v[1].y, v[2].y})), 0);
  const int maxY = std::min(lastSampleAtOrBefore(std::max({v[0].y, v[1].y, v[2].y})), height - 1);
  if (minX > maxX || minY > maxY) return;  // no sample centre of the image (setup() agrees)
  // Every sample the triangle covers lies in these bounds, so a nearest key behind the
  // pyramid there means every depth test would fail (ids included).
  const DepthKey nearest = nearestKeyOver(t.plane, t.id, minX, minY, maxX, maxY);
  if (pyramid_.occludes(minX, minY, maxX, maxY, nearest)) {
    ++stats.trianglesHzbCulled;
    return;
  }
  TriangleSetup s;
  if (!s.setup(t.v, width, height)) return;
  ++stats.trianglesRasterized;
  pyramid_.prepareRows(s.minY, s.maxY);
  // The z-buffer's own pixel loop; the pyramid needs updating only if it wrote something.
  const uint64_t written = stats.pixelsWritten;
  fillTriangle(s, t.plane, t.id, *fb_, stats);
  if (stats.pixelsWritten != written) pyramid_.update(s.minX, s.minY, s.maxX, s.maxY);
}

void HierarchicalAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const FrameGeometry& g = input.geometry;
  const int width = fb.width(), height = fb.height();
  const int bandCount = ((height - 1) >> kBandShift) + 1;

  // Counting sort of the triangles by the band of their first row, stable (face id order
  // within a band); triangles that miss the image are dropped here.
  band_.resize(g.triangles.size());
  bandStart_.assign(size_t(bandCount) + 1, 0);
  for (size_t i = 0; i < g.triangles.size(); ++i) {
    const FixedPoint* v = g.triangles[i].v;
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
  // Copied into band order (reading the array once in order and appending to each band's
  // run), so that the loop below reads the triangles sequentially.
  sorted_.resize(bandStart_[size_t(bandCount)]);
  cursor_.assign(bandStart_.begin(), bandStart_.end() - 1);
  for (size_t i = 0; i < g.triangles.size(); ++i)
    if (band_[i] < uint32_t(bandCount)) sorted_[cursor_[band_[i]]++] = g.triangles[i];

  rasterizer_.begin(fb);
  for (const ScreenTriangle& t : sorted_) rasterizer_.drawTriangle(t, stats);
  rasterizer_.finish();
}

}  // namespace zrender
