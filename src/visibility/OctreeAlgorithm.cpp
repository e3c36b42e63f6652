#include "zrender/visibility/OctreeAlgorithm.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "zrender/raster/RasterRules.hpp"
#include "zrender/raster/RowBands.hpp"
#include "zrender/transform/ScreenRows.hpp"

namespace zrender {

namespace {

// Bands per thread, as for the other algorithms' kBandsPerThread, but where the octree's
// leaves fall: on a grid the rows near the horizon hold far more work than the others, so the
// bands start longest first (BandOrder); each band's own traversal of the upper
// nodes and the leaves it shares with its neighbours cost more with more bands (measured:
// docs/performance.md, Two threads, 2026-11-27 (fifth session)).
constexpr int kOctreeBandsPerThread = 4;

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
    const OctreeNodeTest test(input.camera, fb.width(), fb.height());
    traverse(
        input, test, [&](uint32_t node) { return test.project(octree_.nodes()[node]); }, whole_,
        stats,
        [&](uint32_t leaf) {
          const size_t firstTriangle = g.triangles.size();
          input.source.pull(FaceRequest::batch(leafBatch_[leaf]), g);
          const ScreenTriangle* triangles = g.triangles.data() + firstTriangle;
          drawLeaf(
              whole_.rasterizer, g.triangles.size() - firstTriangle,
              [&](size_t t) -> const ScreenTriangle& { return triangles[t]; }, stats);
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
    leafRows_.resize(batches);
  }
  for (size_t b = 0; b < batches; ++b) leafState_[b].store(0, std::memory_order_relaxed);
  const size_t nodeCount = octree_.nodes().size();
  if (!nodeState_ || nodeBounds_.size() != nodeCount) {
    nodeState_ = std::make_unique<std::atomic<uint8_t>[]>(nodeCount);
    nodeBounds_.resize(nodeCount);
  }
  for (size_t n = 0; n < nodeCount; ++n) nodeState_[n].store(0, std::memory_order_relaxed);
  bands_.resize(size_t(rows.count()));
  // The bands' leaves are pulled into geometry of their own, never the frame's; the shader's
  // face colors, which need none, are prepared now, so that each band is shaded by the thread
  // that finishes it, while its keys are in cache (surfaces wait for the whole buffer).
  input.facesGathered({});
  bandOrder_.forEachBand(threads, rows, [&](size_t b) {
    Band& band = bands_[b];
    const int rowBegin = rows.rowBegin(int(b)), rowEnd = rows.rowEnd(int(b));
    band.rasterizer.begin(fb, rowBegin, rowEnd);
    band.stats = RenderStats();
    // The band's leaves of this frame only: its geometry is kept from frame to frame.
    band.geometry.counters = TransformCounters();
    const OctreeNodeTest test(input.camera, fb.width(), fb.height(), rowBegin, rowEnd);
    traverse(
        input, test, [&](uint32_t node) { return nodeBounds(node, test); }, band, band.stats,
        [&](uint32_t leaf) {
          const uint32_t batch = leafBatch_[leaf];
          const GeometryVector<ScreenTriangle>& t =
              leafTriangles(batch, input.source, band.geometry);
          // Only the triangles that reach the band's rows: a leaf crossing band edges
          // is drawn by each band it reaches, and its triangles, transformed by another
          // thread, are cache misses here.
          const std::vector<RowRange>& ranges = leafRows_[batch];
          std::vector<uint32_t>& kept = band.kept;
          kept.clear();
          for (uint32_t i = 0; i < ranges.size(); ++i)
            if (ranges[i].last >= rowBegin && ranges[i].first < rowEnd) kept.push_back(i);
          drawLeaf(
              band.rasterizer, kept.size(),
              [&](size_t k) -> const ScreenTriangle& { return t[kept[k]]; }, band.stats);
        });
    band.rasterizer.finish();
    input.rowsDone(rowBegin, rowEnd);
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
    source.pull(FaceRequest::batch(batch), scratch);
    leafTriangles_[batch].assign(scratch.triangles.begin(), scratch.triangles.end());
    std::vector<RowRange>& ranges = leafRows_[batch];
    ranges.resize(scratch.triangles.size());
    for (size_t i = 0; i < ranges.size(); ++i) {
      const FixedPoint* v = scratch.triangles[i].v;
      const SampleRect r = sampleBounds(v[0], v[1], v[2], scratch.width, scratch.height);
      ranges[i] = RowRange{int16_t(std::min(r.minY, INT16_MAX)), int16_t(std::max(r.maxY, -1))};
    }
    state.store(2, std::memory_order_release);
  }
  // Another band transforms it: a leaf takes microseconds.
  while (state.load(std::memory_order_acquire) != 2) _mm_pause();
  return leafTriangles_[batch];
}

NodeBounds OctreeAlgorithm::nodeBounds(uint32_t node, const OctreeNodeTest& test) {
  std::atomic<uint8_t>& state = nodeState_[node];
  if (state.load(std::memory_order_acquire) == 2) return nodeBounds_[node];
  uint8_t expected = 0;
  if (!state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel))
    // Another band projects it now: projecting it here too costs less than waiting.
    return test.project(octree_.nodes()[node]);
  nodeBounds_[node] = test.project(octree_.nodes()[node]);
  state.store(2, std::memory_order_release);
  return nodeBounds_[node];
}

template <typename Triangle>
void OctreeAlgorithm::drawLeaf(HzbRasterizer& rasterizer, size_t count, const Triangle& triangle,
                               RenderStats& stats) {
  // The leaf's screen region was usually not drawn recently: fetch the buffer rows of a
  // triangle a few places ahead while drawing.
  for (size_t t = 0; t < std::min(count, kAhead); ++t) rasterizer.prefetch(triangle(t));
  for (size_t t = 0; t < count; ++t) {
    if (t + kAhead < count) rasterizer.prefetch(triangle(t + kAhead));
    rasterizer.drawTriangle(triangle(t), stats);
  }
}

template <typename Bounds, typename DrawLeaf>
void OctreeAlgorithm::traverse(const FrameInput& input, const OctreeNodeTest& test,
                               const Bounds& bounds, Band& band, RenderStats& stats,
                               const DrawLeaf& drawLeaf) const {
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
    if (test.hidden(bounds(nodeIndex), band.rasterizer.pyramid())) {
      ++stats.octreeNodesCulled;
      continue;
    }
    if (node.childMask == 0) {
      // The next node is likely the next leaf: fetch its faces while this one draws.
      if (!stack.empty() && nodes[stack.back()].childMask == 0)
        input.source.prefetch(FaceRequest::batch(leafBatch_[stack.back()]));
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
