#include "zrender/visibility/ZBufferAlgorithm.hpp"

#include <algorithm>

#include "zrender/raster/TriangleFill.hpp"

namespace zrender {

void ZBufferAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  if (input.parallel()) {
    renderBands(input, fb, stats);
    return;
  }
  input.source.pull(FaceRequest::frame(), input.geometry);
  const int width = fb.width(), height = fb.height();
  const GeometryVector<ScreenTriangle>& triangles = bands_.sort(input.geometry, width, height);

  // Rows are cleared just before the first triangle that reaches them, while they are about
  // to be used, instead of in a separate pass over the whole buffer.
  int clearedRows = 0;
  auto clearRowsUpTo = [&](int lastRow) {
    if (lastRow < clearedRows) return;
    fb.clearRows(clearedRows, lastRow + 1);
    clearedRows = lastRow + 1;
  };
  const TriangleFillFunction fill = triangleFill();
  TriangleSetup setup;
  for (int band = 0; band < bands_.bandCount(); ++band) {
    // No later triangle starts above this band: the rows above it are final.
    const int bandTop = band << TriangleBands::kBandShift;
    if (bandTop > 0) {
      clearRowsUpTo(bandTop - 1);
      input.rowsDone(bandTop - (1 << TriangleBands::kBandShift), bandTop);
    }
    for (uint32_t i = bands_.bandStart(band); i < bands_.bandStart(band + 1); ++i) {
      const ScreenTriangle& t = triangles[i];
      if (!setup.setup(t.v, width, height)) continue;
      clearRowsUpTo(setup.maxY);
      ++stats.trianglesRasterized;
      fill(setup, t.plane, t.id, fb, stats);
    }
  }
  clearRowsUpTo(height - 1);
}

void ZBufferAlgorithm::renderBands(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const Threads& threads = *input.threads;
  input.source.pull(FaceRequest::frame(), input.geometry, &partGeometry_);
  parts_ = partsOf(partGeometry_);
  input.facesGathered(parts_);
  const int width = fb.width(), height = fb.height();
  const GeometryVector<ScreenTriangle>& triangles = bands_.bin(parts_, width, height, threads);
  // Each band is cleared and drawn by one thread, its triangles clipped to its rows; a
  // triangle is counted by the first band it reaches, as one thread counts it once.
  bandStats_.assign(size_t(bands_.bandCount()), RenderStats());
  const TriangleFillFunction fill = triangleFill();
  threads.forEach(size_t(bands_.bandCount()), [&](size_t b) {
    const int band = int(b);
    const int top = band << TriangleBands::kBandShift;
    const int bottom = std::min(height, top + (1 << TriangleBands::kBandShift));
    fb.clearRows(top, bottom);
    RenderStats& s = bandStats_[b];
    TriangleSetup setup;
    for (uint32_t i = bands_.bandStart(band); i < bands_.bandStart(band + 1); ++i) {
      const ScreenTriangle& t = triangles[i];
      if (!setup.bounds(t.v, width, top, bottom)) continue;
      setup.edges(t.v);
      s.trianglesRasterized += TriangleBands::firstBandOf(t, band);
      fill(setup, t.plane, t.id, fb, s);
    }
    input.rowsDone(top, bottom);
  });
  for (const RenderStats& s : bandStats_) stats += s;
}

}  // namespace zrender
