#include "zrender/visibility/ScanlineAlgorithm.hpp"

#include <algorithm>

#include "zrender/raster/TriangleFill.hpp"

namespace zrender {

void ScanlineAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  input.source.pullAll(input.geometry);
  const int width = fb.width(), height = fb.height();
  tables_.build(input.geometry, width, height);
  stats.trianglesRasterized += tables_.triangleCount;
  activeEdges_.resize(tables_.edges.size());
  activeCount_.assign(tables_.polygons.size(), 0);
  activePolygons_.clear();

  const SpanFillFunction fill = spanFill();
  uint64_t tested = 0, written = 0, spans = 0;
  size_t activeEdgeTotal = 0, maxActiveEdges = 0, maxActivePolygons = 0;
  for (int y = 0; y < height; ++y) {
    // Polygons and edges whose top row is y join the active tables.
    for (uint32_t k = tables_.polygonBucket[y]; k < tables_.polygonBucket[y + 1]; ++k)
      activePolygons_.push_back(k);
    for (uint32_t k = tables_.edgeBucket[y]; k < tables_.edgeBucket[y + 1]; ++k) {
      const ClassifiedEdge& e = tables_.edges[k];
      ActiveEdge& a =
          activeEdges_[tables_.polygons[e.polygon].edgeBegin + activeCount_[e.polygon]++];
      a.step.start(e.top, e.bottom, y);
      a.lastRow = e.lastRow;
      ++activeEdgeTotal;
    }
    maxActiveEdges = std::max(maxActiveEdges, activeEdgeTotal);
    maxActivePolygons = std::max(maxActivePolygons, activePolygons_.size());

    // The one-row depth buffer is the frame buffer's row itself: cleared, then filled.
    DepthKey* row = fb.row(y);
    std::fill(row, row + width, kClearKey);
    size_t keep = 0;
    for (size_t i = 0; i < activePolygons_.size(); ++i) {
      const uint32_t pi = activePolygons_[i];
      const ClassifiedPolygon& p = tables_.polygons[pi];
      ActiveEdge* list = activeEdges_.data() + p.edgeBegin;
      const uint32_t n = activeCount_[pi];
      const double rowBase = p.plane.rowBase(y);
      // The span [left, right) of the row, already clipped to the image; nothing when empty.
      auto fillSpan = [&](int left, int right) {
        if (left >= right) return;
        ++spans;
        tested += uint64_t(right - left);
        written += fill(row, left, right, p.plane, rowBase, p.id);
      };
      if (n == 2) {
        // Two active edges (every triangle, and most rows of other polygons): the span lies
        // between them in either order, so there is nothing to sort. Branch-free, because
        // which edge is on the left depends on the face's winding.
        const int c0 = list[0].step.column, c1 = list[1].step.column;
        fillSpan(std::max(std::min(c0, c1), 0), std::min(std::max(c0, c1), width));
      } else {
        // Insertion sort by column: the order changes little from row to row.
        for (uint32_t k = 1; k < n; ++k) {
          const ActiveEdge e = list[k];
          uint32_t j = k;
          for (; j > 0 && list[j - 1].step.column > e.step.column; --j) list[j] = list[j - 1];
          list[j] = e;
        }
        // Even-odd spans [q1, q2), [q3, q4), ... clipped to the image.
        for (uint32_t k = 0; k + 1 < n; k += 2)
          fillSpan(std::max(list[k].step.column, 0), std::min(list[k + 1].step.column, width));
      }
      // Edges ending on this row leave; the others step to the next row.
      uint32_t m = 0;
      for (uint32_t k = 0; k < n; ++k) {
        if (list[k].lastRow == y) continue;
        if (m != k) list[m] = list[k];
        list[m].step.step();
        ++m;
      }
      activeEdgeTotal -= n - m;
      activeCount_[pi] = m;
      if (p.bottomRow != y) activePolygons_[keep++] = pi;
    }
    activePolygons_.resize(keep);
    input.rowFinished(y);
  }

  // pixelsWritten counts row writes; a sample can be overwritten by nearer faces.
  stats.pixelsTested += tested;
  stats.pixelsWritten += written;
  stats.extra.emplace_back("spans", spans);
  stats.extra.emplace_back("max_active_edges", maxActiveEdges);
  stats.extra.emplace_back("max_active_polygons", maxActivePolygons);
}

}  // namespace zrender
