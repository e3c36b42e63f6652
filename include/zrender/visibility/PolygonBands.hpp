#pragma once

#include <vector>

#include "zrender/raster/PolygonEdges.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/raster/RowBands.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// How the scan-line algorithms draw a frame on several threads: the image cut into bands of
// rows, each drawn by one thread from polygon tables of its own (PolygonTables::build for a
// band) and shaded by it; the counters of the bands added up in band order.
class PolygonBands {
 public:
  // drawBand(thread, tablesBuiltFor(band), rowEnd, stats) draws one band with the state of
  // `thread` (0..threads - 1), where tablesBuiltFor builds that thread's tables for the band.
  template <typename TablesOf, typename DrawBand>
  void draw(const FrameInput& input, int width, int height, RenderStats& stats,
            const TablesOf& tablesOf, const DrawBand& drawBand) {
    const Threads& threads = *input.threads;
    const FrameGeometry& g = input.geometry;
    input.facesReady();
    const RowBands bands(height, threads.count() * kBandsPerThread);
    faceLists_.build(g.faces.size(), bands, threads, [&](size_t f, int& first, int& last) {
      return faceRows(g, uint32_t(f), height, first, last);
    });
    bandStats_.assign(size_t(bands.count()), RenderStats());
    threads.forEach(size_t(bands.count()), [&](size_t b) {
      const int thread = threads.slot(), rowBegin = bands.rowBegin(int(b));
      const int rowEnd = bands.rowEnd(int(b));
      PolygonTables& tables = tablesOf(thread);
      tables.build(g, width, height, rowBegin, rowEnd, faceLists_.items(int(b)),
                   faceLists_.size(int(b)));
      bandStats_[b].trianglesRasterized += tables.triangleCount;
      drawBand(thread, rowEnd, bandStats_[b]);
      input.rowsReady(rowBegin, rowEnd);
    });
    for (const RenderStats& s : bandStats_) stats += s;
  }

 private:
  BandLists faceLists_;  // the faces of each band
  std::vector<RenderStats> bandStats_;
};

}  // namespace zrender
