#include "zrender/visibility/HzbRasterizer.hpp"

namespace zrender {

void HzbRasterizer::drawTriangle(const ScreenTriangle& t, RenderStats& stats) {
  // The sample bounds before the edge functions: a rejected triangle costs the bounds and a
  // few loads.
  TriangleSetup s;
  if (!s.bounds(t.v, fb_->width(), rowBegin_, rowEnd_)) return;  // no sample centre in the rows
  // Every sample the triangle covers lies in these bounds, so a nearest key behind the
  // pyramid there means every depth test would fail (ids included). First the key of the
  // nearest corner, below which no sample's depth goes (DepthPlane's clamp): for a small
  // triangle as good as any bound. A big one may show only its far part in the image, or
  // cover few samples near its nearest corner: the plane over its sample bounds may then
  // give a nearer bound, worth its cost there; for every triangle it costs more than it rejects
  // (docs/performance.md).
  const DepthKey nearestCorner = makeDepthKey(t.plane.minDepth(), t.id);
  bool hidden = pyramid_.occludes(s.minX, s.minY, s.maxX, s.maxY, nearestCorner);
  if (!hidden &&
      (s.maxX - s.minX >= DepthPyramid::kTileSize || s.maxY - s.minY >= DepthPyramid::kTileSize)) {
    const DepthKey nearest = nearestKeyOver(t.plane, t.id, s.minX, s.minY, s.maxX, s.maxY);
    hidden = nearest > nearestCorner && pyramid_.occludes(s.minX, s.minY, s.maxX, s.maxY, nearest);
    // A copy of a triangle drawn before (see CoincidentTriangles): only big ones are looked
    // up, for which the look-up costs far less than the pixels.
    hidden = hidden || coincident_.hiddenByEarlier(t);
  }
  if (hidden) {
    ++stats.trianglesHzbCulled;
    return;
  }
  s.edges(t.v);
  ++stats.trianglesRasterized;
  pyramid_.prepareRows(s.minY, s.maxY);
  // The z-buffer's own pixel loop; the pyramid needs updating only if it wrote something.
  const uint64_t written = stats.pixelsWritten;
  fill_(s, t.plane, t.id, *fb_, stats);
  if (stats.pixelsWritten != written) pyramid_.update(s.minX, s.minY, s.maxX, s.maxY);
}

}  // namespace zrender
