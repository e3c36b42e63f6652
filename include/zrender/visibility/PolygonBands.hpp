#pragma once

#include <vector>

#include "zrender/raster/BandOrder.hpp"
#include "zrender/raster/PolygonEdges.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/raster/RowBands.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// How the scan-line algorithms draw a frame on several threads: the image cut into bands of
// rows, each drawn by one thread from polygon tables of its own (PolygonTables::build for a
// band) and shaded by it, the longest bands first (BandOrder); the counters of the bands added
// up in band order. The frame's faces come in parts (a Frame pull with parts): a big
// frame's are not joined into one geometry, a copy of all of them.
class PolygonBands {
 public:
  // drawBand(thread, tablesBuiltFor(band), rowEnd, stats) draws one band with the state of
  // `thread` (0..threads - 1), where tablesBuiltFor builds that thread's tables for the band.
  template <typename TablesOf, typename DrawBand>
  void draw(FrameInput& input, int width, int height, RenderStats& stats, const TablesOf& tablesOf,
            const DrawBand& drawBand) {
    const Threads& threads = *input.threads;
    input.source.pull(FaceRequest::frame(), input.geometry, &partGeometry_);
    parts_ = partsOf(partGeometry_);
    input.facesGathered(parts_);
    const RowBands bands(height, threads.count() * kBandsPerThread);
    std::vector<size_t> faceCounts;
    for (const FrameGeometry* part : parts_) faceCounts.push_back(part->faces.size());
    placer_.placeSegments(
        faceCounts, bands, threads,
        [&](size_t part, size_t f, int& first, int& last) {
          const FaceRowSpan rows = parts_[part]->faces[f].rows;
          first = rows.first;
          last = rows.last;
          return first <= last;
        },
        [&](uint32_t total) { faces_.resize(total); },
        [&](size_t part, size_t f, uint32_t k) {
          faces_[k] = PartFace{uint32_t(part), uint32_t(f)};
        });
    bandStats_.assign(size_t(bands.count()), RenderStats());
    order_.forEachBand(threads, bands, [&](size_t b) {
      const int thread = threads.slot(), rowBegin = bands.rowBegin(int(b));
      const int rowEnd = bands.rowEnd(int(b));
      PolygonTables& tables = tablesOf(thread);
      const uint32_t first = placer_.start(int(b));
      tables.build(parts_, width, height, rowBegin, rowEnd, faces_.data() + first,
                   placer_.start(int(b) + 1) - first);
      bandStats_[b].trianglesRasterized += tables.triangleCount;
      drawBand(thread, rowEnd, bandStats_[b]);
      input.rowsDone(rowBegin, rowEnd);
    });
    for (const RenderStats& s : bandStats_) stats += s;
  }

 private:
  std::vector<FrameGeometry> partGeometry_;  // the frame's faces
  FaceParts parts_;                          // views of them
  BandPlacer placer_;
  std::vector<PartFace> faces_;  // the faces of each band, band after band
  std::vector<RenderStats> bandStats_;
  BandOrder order_;  // the bands longest first, by the last frame's times
};

}  // namespace zrender
