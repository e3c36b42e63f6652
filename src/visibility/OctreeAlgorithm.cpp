#include "zrender/visibility/OctreeAlgorithm.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "zrender/raster/RowBands.hpp"
#include "zrender/scene/ScreenRows.hpp"

namespace zrender {

namespace {

// Bands per thread: more than the other algorithms' kBandsPerThread. A band's work is where the
// octree's leaves fall in its rows, and on a grid the front rows hold far more than the back
// ones; thinner bands balance that better, until each band's own traversal of the upper nodes
// costs more (measured: docs/performance.md, Two threads, 2026-11-26 (later)).
constexpr int kOctreeBandsPerThread = 12;

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
  FrameGeometry& g = input.geometry;
  if (!input.parallel()) {
    whole_.rasterizer.begin(fb);
    traverse(input, OctreeNodeTest(input.camera, fb.width(), fb.height()), whole_, stats,
             [&](uint32_t leaf) {
               const size_t firstTriangle = g.triangles.size();
               input.source.pullBatch(leafBatch_[leaf], g);
               drawLeaf(whole_.rasterizer, g.triangles.data() + firstTriangle,
                        g.triangles.size() - firstTriangle, stats);
               // Drawn: the next leaf's triangles reuse the same, cached, storage instead of
               // appending to megabytes of them.
               g.triangles.resize(firstTriangle);
             });
    whole_.rasterizer.finish();
    return;
  }
  const Threads& threads = *input.threads;
  // The bands share out the rows the instances cover, where the work is.
  const RowSpan busy = screenRows(input.scene, input.camera, fb.height());
  const RowBands rows(fb.height(), threads.count() * kOctreeBandsPerThread, DepthPyramid::kTileSize,
                      busy.begin, busy.end);
  const size_t batches = batches_.size() - 1;
  if (!leafState_ || leafTriangles_.size() != batches) {
    leafState_ = std::make_unique<std::atomic<uint8_t>[]>(batches);
    leafTriangles_.resize(batches);
  }
  for (size_t b = 0; b < batches; ++b) leafState_[b].store(0, std::memory_order_relaxed);
  bands_.resize(size_t(rows.count()));
  // The bands' leaves are pulled into geometry of their own, never the frame's; the shader's
  // face colors, which need none, are prepared now, so that each band is shaded by the thread
  // that finishes it, while its keys are in cache (surfaces wait for the whole buffer).
  input.facesReady({});
  threads.forEach(size_t(rows.count()), [&](size_t b) {
    Band& band = bands_[b];
    const int rowBegin = rows.rowBegin(int(b)), rowEnd = rows.rowEnd(int(b));
    band.rasterizer.begin(fb, rowBegin, rowEnd);
    band.stats = RenderStats();
    // The band's leaves of this frame only: its geometry is kept from frame to frame.
    band.geometry.counters = TransformCounters();
    traverse(input, OctreeNodeTest(input.camera, fb.width(), fb.height(), rowBegin, rowEnd), band,
             band.stats, [&](uint32_t leaf) {
               const GeometryVector<ScreenTriangle>& t =
                   leafTriangles(leafBatch_[leaf], input.source, band.geometry);
               drawLeaf(band.rasterizer, t.data(), t.size(), band.stats);
             });
    band.rasterizer.finish();
    input.rowsReady(rowBegin, rowEnd);
  });
  for (const Band& band : bands_) {
    stats += band.stats;
    g.counters.backfaceCulled += band.geometry.counters.backfaceCulled;
    g.counters.clippedAway += band.geometry.counters.clippedAway;
    g.counters.degenerate += band.geometry.counters.degenerate;
  }
}

const GeometryVector<ScreenTriangle>& OctreeAlgorithm::leafTriangles(uint32_t batch,
                                                                     GeometrySource& source,
                                                                     FrameGeometry& scratch) {
  std::atomic<uint8_t>& state = leafState_[batch];
  uint8_t expected = 0;
  if (state.load(std::memory_order_acquire) != 2 &&
      state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) {
    scratch.triangles.clear();
    scratch.faces.clear();
    scratch.vertices.clear();
    source.pullBatch(batch, scratch);
    leafTriangles_[batch].assign(scratch.triangles.begin(), scratch.triangles.end());
    state.store(2, std::memory_order_release);
  }
  // Another band transforms it: a leaf takes microseconds.
  while (state.load(std::memory_order_acquire) != 2) _mm_pause();
  return leafTriangles_[batch];
}

void OctreeAlgorithm::drawLeaf(HzbRasterizer& rasterizer, const ScreenTriangle* triangles,
                               size_t count, RenderStats& stats) {
  // The leaf's screen region was usually not drawn recently: fetch the buffer rows of a
  // triangle a few places ahead while drawing.
  for (size_t t = 0; t < std::min(count, kAhead); ++t) rasterizer.prefetch(triangles[t]);
  for (size_t t = 0; t < count; ++t) {
    if (t + kAhead < count) rasterizer.prefetch(triangles[t + kAhead]);
    rasterizer.drawTriangle(triangles[t], stats);
  }
}

template <typename DrawLeaf>
void OctreeAlgorithm::traverse(const FrameInput& input, const OctreeNodeTest& test, Band& band,
                               RenderStats& stats, const DrawLeaf& drawLeaf) const {
  std::vector<uint32_t>& stack = band.stack;
  const std::vector<OctreeNode>& nodes = octree_.nodes();
  const Vec3& eye = input.camera.eye;
  stack.clear();
  if (!nodes.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const uint32_t nodeIndex = stack.back();
    const OctreeNode& node = nodes[nodeIndex];
    stack.pop_back();
    ++stats.octreeNodesVisited;
    if (test.hidden(node, band.rasterizer.pyramid())) {
      ++stats.octreeNodesCulled;
      continue;
    }
    if (node.childMask == 0) {
      // The next node is likely the next leaf: fetch its faces while this one draws.
      if (!stack.empty() && nodes[stack.back()].childMask == 0)
        input.source.prefetchBatch(leafBatch_[stack.back()]);
      drawLeaf(nodeIndex);
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
      stack.push_back(node.firstChild + before);
    }
  }
}

}  // namespace zrender
