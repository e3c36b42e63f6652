#include "zrender/ZBufferAlgorithm.hpp"

#include <algorithm>

#include "zrender/TriangleFill.hpp"

namespace zrender {

namespace {

// Triangles are visited in bands of 32 sample rows (top to bottom, file order within a band)
// so that the rows a triangle touches are still in cache from its neighbours. The order does
// not change the result: the DepthKey comparison makes it order-independent.
constexpr int kBandShift = 5;

}  // namespace

void ZBufferAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const FrameGeometry& g = input.geometry;
  const int width = fb.width(), height = fb.height();
  const int bandCount = ((height - 1) >> kBandShift) + 1;

  // Counting sort of the triangles by the band of their first row; off-screen ones are dropped.
  band_.resize(g.triangles.size());
  bandStart_.assign(size_t(bandCount) + 1, 0);
  for (size_t i = 0; i < g.triangles.size(); ++i) {
    const FixedPoint* v = g.triangles[i].v;
    const int top = std::max(firstSampleAtOrAfter(std::min({v[0].y, v[1].y, v[2].y})), 0);
    const int bottom = lastSampleAtOrBefore(std::max({v[0].y, v[1].y, v[2].y}));
    const int left = firstSampleAtOrAfter(std::min({v[0].x, v[1].x, v[2].x}));
    const int right = lastSampleAtOrBefore(std::max({v[0].x, v[1].x, v[2].x}));
    const bool visible =
        top <= std::min(bottom, height - 1) && right >= 0 && left < width && left <= right;
    band_[i] = visible ? uint32_t(top >> kBandShift) : uint32_t(bandCount);
    if (visible) ++bandStart_[band_[i] + 1];
  }
  for (int b = 0; b < bandCount; ++b) bandStart_[size_t(b) + 1] += bandStart_[size_t(b)];
  // Copied into band order, so the fill loop below reads them sequentially.
  sorted_.resize(bandStart_[size_t(bandCount)]);
  cursor_.assign(bandStart_.begin(), bandStart_.end() - 1);
  for (size_t i = 0; i < g.triangles.size(); ++i)
    if (band_[i] < uint32_t(bandCount)) sorted_[cursor_[band_[i]]++] = g.triangles[i];

  // Rows are cleared just before the first triangle that reaches them, while they are about
  // to be used, instead of in a separate pass over the whole buffer.
  int clearedRows = 0;
  auto clearRowsUpTo = [&](int lastRow) {
    if (lastRow < clearedRows) return;
    std::fill(fb.row(clearedRows), fb.row(lastRow) + width, kClearKey);
    clearedRows = lastRow + 1;
  };
  TriangleSetup setup;
  for (const ScreenTriangle& t : sorted_) {
    if (!setup.setup(t.v, width, height)) continue;
    clearRowsUpTo(setup.maxY);
    ++stats.trianglesRasterized;
    fillTriangle(setup, t.plane, t.id, fb, stats);
  }
  clearRowsUpTo(height - 1);
}

}  // namespace zrender
