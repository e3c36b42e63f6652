#pragma once

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
// go through the pyramid test of HzbRasterizer.
class OctreeAlgorithm : public VisibilityAlgorithm {
 public:
  // `leafFaces`: the octree's leaf size (Octree::build); other sizes are for measurements.
  explicit OctreeAlgorithm(uint32_t leafFaces = Octree::kLeafFaces) : leafFaces_(leafFaces) {}
  std::string name() const override { return "octree"; }
  // Builds the octree; one batch per leaf, in the order of octree().faces().
  FaceBatches prepare(const Scene& scene) override;
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

  const Octree& octree() const { return octree_; }

 private:
  uint32_t leafFaces_;
  Octree octree_;
  HzbRasterizer rasterizer_;
  std::vector<uint32_t> stack_;      // nodes still to visit, nearest on top
  std::vector<uint32_t> batches_;    // leaf boundaries in octree_.faces(), in order
  std::vector<uint32_t> leafBatch_;  // per node: its batch, for leaves
};

}  // namespace zrender
