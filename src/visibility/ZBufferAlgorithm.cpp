#include "zrender/visibility/ZBufferAlgorithm.hpp"

#include <algorithm>

#include "zrender/raster/TriangleFill.hpp"

namespace zrender {

void ZBufferAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  input.source.pullAll(input.geometry);
  const int width = fb.width(), height = fb.height();
  const std::vector<ScreenTriangle>& triangles = bands_.sort(input.geometry, width, height);

  // Rows are cleared just before the first triangle that reaches them, while they are about
  // to be used, instead of in a separate pass over the whole buffer.
  int clearedRows = 0;
  auto clearRowsUpTo = [&](int lastRow) {
    if (lastRow < clearedRows) return;
    std::fill(fb.row(clearedRows), fb.row(lastRow) + width, kClearKey);
    clearedRows = lastRow + 1;
  };
  const TriangleFillFunction fill = triangleFill();
  TriangleSetup setup;
  for (int band = 0; band < bands_.bandCount(); ++band) {
    // No later triangle starts above this band: the rows above it are final.
    const int bandTop = band << TriangleBands::kBandShift;
    if (bandTop > 0) {
      clearRowsUpTo(bandTop - 1);
      input.rowsFinal(bandTop);
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

}  // namespace zrender
