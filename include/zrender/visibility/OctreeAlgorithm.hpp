#pragma once

#include <atomic>
#include <memory>
#include <vector>

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
// leaves it keeps clipped to its rows; the first band to keep a leaf transforms it for all.
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
  };
  // Traverses the octree front to back, drawing the leaves it keeps through band.rasterizer,
  // begun for the rows `test` tests: drawLeaf(leafNode) draws one.
  template <typename DrawLeaf>
  void traverse(const FrameInput& input, const OctreeNodeTest& test, Band& band, RenderStats& stats,
                const DrawLeaf& drawLeaf) const;
  // Draws a leaf's triangles.
  static void drawLeaf(HzbRasterizer& rasterizer, const ScreenTriangle* triangles, size_t count,
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
  std::vector<uint32_t> batches_;    // leaf boundaries in octree_.faces(), in order
  std::vector<uint32_t> leafBatch_;  // per node: its batch, for leaves
};

}  // namespace zrender
