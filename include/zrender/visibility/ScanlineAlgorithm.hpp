#pragma once

#include <vector>

#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/raster/PolygonEdges.hpp"
#include "zrender/visibility/PolygonBands.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// The scan-line z-buffer (docs/design.md, The algorithms: `scanline`): polygons are drawn natively,
// row by row from the top, from a classified polygon table and a classified edge table bucketed by
// top row. The active polygon table holds the polygons that cross the current row; each sorts its
// own active edges by column (a polygon with two, as every triangle has, takes the lesser as the
// left end instead) and fills its spans pairwise (even-odd) into a one-row depth buffer: the frame
// buffer's current row itself (copying a separate row buffer out costs a copy per row), so only
// that row is touched while it is built. With several threads, the image is cut into bands of
// rows, each drawn by one thread from tables of its own (PolygonTables for a band).
class ScanlineAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "scanline"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  // An edge in its polygon's active edge list.
  struct ActiveEdge {
    EdgeStepper step;
    int32_t lastRow;  // the edge leaves the list after this row
  };

  // What drawing a band of rows needs (the whole image, with one thread).
  struct Band {
    PolygonTables tables;
    std::vector<uint32_t> activePolygons;  // indices into tables.polygons
    // Active edges of polygon p live in activeEdges[p.edgeBegin, p.edgeBegin +
    // activeCount[p]): a polygon never has more active edges than edges, so the slots never
    // overflow. A slot is written when its edge joins, before it is read.
    std::vector<ActiveEdge, UninitializedAllocator<ActiveEdge>> activeEdges;
    std::vector<uint32_t> activeCount;
  };
  // Draws rows [band.tables.rowBegin, rowEnd) from band.tables.
  void drawRows(Band& band, int rowEnd, const FrameInput& input, FrameBuffer& fb,
                RenderStats& stats) const;

  Band whole_;                   // one thread
  std::vector<Band> perThread_;  // several: each thread's
  PolygonBands bands_;           // several: how they are drawn
};

}  // namespace zrender
