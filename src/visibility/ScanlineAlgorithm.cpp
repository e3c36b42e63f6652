#include "zrender/visibility/ScanlineAlgorithm.hpp"

#include <algorithm>

#include "zrender/raster/TriangleFill.hpp"

namespace zrender {

void ScanlineAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const int width = fb.width(), height = fb.height();
  if (!input.parallel()) {
    input.source.pull(FaceRequest::frame(), input.geometry);
    const FrameGeometry& g = input.geometry;
    whole_.tables.build(g, width, height);
    stats.trianglesRasterized += whole_.tables.triangleCount;
    drawRows(whole_, height, input, fb, stats);
    return;
  }
  perThread_.resize(size_t(input.threads->count()));
  bands_.draw(
      input, width, height, stats,
      [&](int thread) -> PolygonTables& { return perThread_[size_t(thread)].tables; },
      [&](int thread, int rowEnd, RenderStats& bandStats) {
        drawRows(perThread_[size_t(thread)], rowEnd, input, fb, bandStats);
      });
}

void ScanlineAlgorithm::drawRows(Band& band, int rowEnd, const FrameInput& input, FrameBuffer& fb,
                                 RenderStats& stats) const {
  const PolygonTables& tables = band.tables;
  auto& activeEdges = band.activeEdges;
  std::vector<uint32_t>& activeCount = band.activeCount;
  std::vector<uint32_t>& activePolygons = band.activePolygons;
  activeEdges.resize(tables.edges.size());
  activeCount.assign(tables.polygons.size(), 0);
  activePolygons.clear();

  const int width = fb.width();
  const SpanFillFunction fill = spanFill();
  uint64_t tested = 0, written = 0, spans = 0;
  size_t activeEdgeTotal = 0, maxActiveEdges = 0, maxActivePolygons = 0;
  for (int y = tables.rowBegin; y < rowEnd; ++y) {
    // Polygons and edges whose top row is y join the active tables.
    const int r = y - tables.rowBegin;
    for (uint32_t k = tables.polygonBucket[r]; k < tables.polygonBucket[r + 1]; ++k)
      activePolygons.push_back(k);
    for (uint32_t k = tables.edgeBucket[r]; k < tables.edgeBucket[r + 1]; ++k) {
      const ClassifiedEdge& e = tables.edges[k];
      ActiveEdge& a = activeEdges[tables.polygons[e.polygon].edgeBegin + activeCount[e.polygon]++];
      a.step.start(e.top, e.bottom, y);
      a.lastRow = e.lastRow;
      ++activeEdgeTotal;
    }
    maxActiveEdges = std::max(maxActiveEdges, activeEdgeTotal);
    maxActivePolygons = std::max(maxActivePolygons, activePolygons.size());

    // The one-row depth buffer is the frame buffer's row itself: cleared, then filled.
    DepthKey* row = fb.row(y);
    fb.clearRows(y, y + 1);
    size_t keep = 0;
    for (size_t i = 0; i < activePolygons.size(); ++i) {
      const uint32_t pi = activePolygons[i];
      const ClassifiedPolygon& p = tables.polygons[pi];
      ActiveEdge* list = activeEdges.data() + p.edgeBegin;
      const uint32_t n = activeCount[pi];
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
      activeCount[pi] = m;
      if (p.bottomRow != y) activePolygons[keep++] = pi;
    }
    activePolygons.resize(keep);
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
