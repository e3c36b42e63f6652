#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "zrender/raster/BandOrder.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"
#include "zrender/visibility/Octree.hpp"
#include "zrender/visibility/OctreeNodeTest.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// Greene, Kass and Miller's hierarchical z-buffer with an object-space octree: the octree is
// built once (prepare) over all instances in world space and traversed front to back; a node
// whose projected box lies behind the z-pyramid (or outside the view volume) is skipped with
// everything below it. Faces of the other leaves are transformed lazily and their triangles
// go through the pyramid test of HzbRasterizer. With several threads, the image is cut into
// bands of rows, each traversing the octree against a pyramid of its own and drawing the
// leaves it keeps clipped to its rows; the first band to keep a leaf transforms it for all,
// the first to reach a node projects its box for all, and the bands start longest first.
class OctreeAlgorithm : public VisibilityAlgorithm {
 public:
  // `leafFaces`: the octree's leaf size (Octree::build); other sizes are for measurements.
  explicit OctreeAlgorithm(uint32_t leafFaces = Octree::kLeafFaces) : leafFaces_(leafFaces) {}
  std::string name() const override { return "octree"; }
  // Builds the octree; one batch per leaf, in the order of octree().faces().
  FaceBatches prepare(const Scene& scene) override;
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;
  // With several threads the bands keep the faces they pull: they leave none in the geometry.
  bool gathersFaces(bool parallel) const override { return !parallel; }

  const Octree& octree() const { return octree_; }

 private:
  // What one traversal needs: the whole image's with one thread, a band's with several.
  struct Band {
    HzbRasterizer rasterizer;
    std::vector<uint32_t> stack;  // nodes still to visit, nearest on top
    FrameGeometry geometry;       // several threads: where the band transforms leaves
    RenderStats stats;
    std::vector<uint32_t> kept;  // several threads: the drawn leaf's triangles in the band
  };
  // A triangle's sample rows [first, last] in the image (first > last: none), in 16 bits.
  struct RowRange {
    int16_t first, last;
  };
  // Traverses the octree front to back, drawing the leaves it keeps through band.rasterizer,
  // begun for the rows `test` tests: drawLeaf(leafNode) draws one.
  // bounds(node) gives the node's NodeBounds.
  template <typename Bounds, typename DrawLeaf>
  void traverse(const FrameInput& input, const OctreeNodeTest& test, const Bounds& bounds,
                Band& band, RenderStats& stats, const DrawLeaf& drawLeaf) const;
  // With several threads: node `node`'s bounds, projected by the first band that asks and
  // kept for the others (a node's projection costs more than its test against a pyramid).
  NodeBounds nodeBounds(uint32_t node, const OctreeNodeTest& test);
  // Draws a leaf's `count` triangles, triangle(i) for i in [0, count).
  template <typename Triangle>
  static void drawLeaf(HzbRasterizer& rasterizer, size_t count, const Triangle& triangle,
                       RenderStats& stats);
  // With several threads: the triangles of batch `batch`, transformed by the first band that
  // asks (into its `scratch`) while the others wait for them.
  const GeometryVector<ScreenTriangle>& leafTriangles(uint32_t batch, GeometrySource& source,
                                                      FrameGeometry& scratch);

  uint32_t leafFaces_;
  Octree octree_;
  Band whole_;
  std::vector<Band> bands_;
  // With several threads, per batch: 0 not transformed yet this frame, 1 being transformed,
  // 2 done; and its triangles.
  std::unique_ptr<std::atomic<uint8_t>[]> leafState_;
  std::vector<GeometryVector<ScreenTriangle>> leafTriangles_;
  std::vector<std::vector<RowRange>> leafRows_;  // per batch: its triangles' rows
  BandOrder bandOrder_;  // several threads: the bands' order, from the last frame's times
  // With several threads, per node: 0 not projected yet this frame, 1 being projected, 2 done;
  // and its bounds.
  std::unique_ptr<std::atomic<uint8_t>[]> nodeState_;
  std::vector<NodeBounds> nodeBounds_;
  std::vector<uint32_t> batches_;    // leaf boundaries in octree_.faces(), in order
  std::vector<uint32_t> leafBatch_;  // per node: its batch, for leaves
};

}  // namespace zrender
