#include "zrender/visibility/OctreeAlgorithm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace zrender {

namespace {

// Buffer rows are fetched this many triangles ahead of drawing.
constexpr size_t kAhead = 4;

}  // namespace

FaceBatches OctreeAlgorithm::prepare(const Scene& scene) {
  octree_.build(scene, leafFaces_);
  // The leaves' face ranges follow one another in octree_.faces() (the tree is built in
  // Morton order), so they are the batches in that order.
  const std::vector<OctreeNode>& nodes = octree_.nodes();
  std::vector<uint32_t> leaves;
  for (uint32_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].childMask == 0) leaves.push_back(i);
  std::sort(leaves.begin(), leaves.end(),
            [&](uint32_t a, uint32_t b) { return nodes[a].faceBegin < nodes[b].faceBegin; });
  batches_.assign(1, 0);
  leafBatch_.assign(nodes.size(), 0);
  for (uint32_t leaf : leaves) {
    if (nodes[leaf].faceBegin != batches_.back())
      throw std::logic_error("octree leaves do not tile the face list");
    leafBatch_[leaf] = uint32_t(batches_.size() - 1);
    batches_.push_back(nodes[leaf].faceEnd);
  }
  if (batches_.back() != octree_.faces().size())
    throw std::logic_error("octree leaves do not tile the face list");
  return FaceBatches{&octree_.faces(), &batches_};
}

void OctreeAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  rasterizer_.begin(fb);
  const std::vector<OctreeNode>& nodes = octree_.nodes();
  FrameGeometry& g = input.geometry;
  const Camera& camera = input.camera;
  const OctreeNodeTest test(camera, fb.width(), fb.height());
  const Vec3& eye = camera.eye;

  stack_.clear();
  if (!nodes.empty()) stack_.push_back(0);
  while (!stack_.empty()) {
    const uint32_t nodeIndex = stack_.back();
    const OctreeNode& node = nodes[nodeIndex];
    stack_.pop_back();
    ++stats.octreeNodesVisited;
    if (test.hidden(node, rasterizer_.pyramid())) {
      ++stats.octreeNodesCulled;
      continue;
    }
    if (node.childMask == 0) {
      const size_t firstTriangle = g.triangles.size();
      input.source.pullBatch(leafBatch_[nodeIndex], g);
      // The next node is likely the next leaf: fetch its faces while this one draws.
      if (!stack_.empty() && nodes[stack_.back()].childMask == 0)
        input.source.prefetchBatch(leafBatch_[stack_.back()]);
      // The leaf's screen region was usually not drawn recently: fetch the buffer rows of a
      // triangle a few places ahead while drawing.
      const size_t end = g.triangles.size();
      for (size_t t = firstTriangle; t < std::min(end, firstTriangle + kAhead); ++t)
        rasterizer_.prefetch(g.triangles[t]);
      for (size_t t = firstTriangle; t < end; ++t) {
        if (t + kAhead < end) rasterizer_.prefetch(g.triangles[t + kAhead]);
        rasterizer_.drawTriangle(g.triangles[t], stats);
      }
      // Drawn: the next leaf's triangles reuse the same, cached, storage instead of
      // appending to megabytes of them.
      g.triangles.resize(firstTriangle);
      continue;
    }
    // Front to back: the octant on the eye's side of all three split planes first, then
    // octant ^ i for growing i (an octant never hides one with fewer flipped axes). Pushed in
    // reverse so the nearest is popped first.
    const unsigned near = unsigned(eye[0] > node.split[0]) | unsigned(eye[1] > node.split[1]) << 1 |
                          unsigned(eye[2] > node.split[2]) << 2;
    for (int i = 7; i >= 0; --i) {
      const unsigned o = near ^ unsigned(i);
      if (!(node.childMask & (1u << o))) continue;
      const unsigned before = __builtin_popcount(node.childMask & ((1u << o) - 1u));
      stack_.push_back(node.firstChild + before);
    }
  }
  rasterizer_.finish();
}

}  // namespace zrender
