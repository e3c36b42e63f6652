#include "zrender/transform/FaceTransformer.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/transform/Clipping.hpp"
#include "zrender/transform/Triangulation.hpp"

namespace zrender {

FaceTransformer::FaceTransformer(const Scene& scene, int sampleScale, bool cull)
    : scene_(scene), scale_(sampleScale), avx2_(cpuHasAvx2()), cull_(cull) {}

FaceTransformer::FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale,
                                 bool cull)
    : FaceTransformer(scene, sampleScale, cull) {
  beginFrame(camera);
}

void FaceTransformer::beginFrame(const Camera& camera) {
  width_ = camera.width;
  height_ = camera.height;
  viewport_ = VertexViewport{width_, height_, scale_};
  const Mat4 viewProjection = camera.projection * camera.view;
  mvp_.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    mvp_.push_back(viewProjection * scene_.modelMatrix(k));
  if (++frame_ == 0) {  // the stamps wrapped around: forget them all
    for (VertexState& v : state_) v.frame = 0;
    frame_ = 1;
  }
}

void FaceTransformer::prepare(const std::vector<uint32_t>* faceOrder,
                              const std::vector<uint32_t>* batches) {
  const Mesh& mesh = *scene_.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  constexpr uint32_t kUnseen = ~0u;
  std::vector<uint32_t> slotOf(mesh.positions.size(), kUnseen);
  std::vector<uint8_t> visited(nf, 0);
  slotPositions_.clear();
  cornerSlots_.resize(mesh.corners.size());
  auto visitFace = [&](uint32_t f) {
    if (visited[f]) return;
    visited[f] = 1;
    for (uint32_t i = mesh.faceStart[f]; i < mesh.faceStart[f + 1]; ++i) {
      const size_t position = size_t(mesh.corners[i].position);
      if (slotOf[position] == kUnseen) {
        slotOf[position] = uint32_t(slotPositions_.size());
        slotPositions_.push_back(mesh.positions[position]);
      }
      cornerSlots_[i] = slotOf[position];
    }
  };
  // Faces of every instance: the first instance of a mesh face met decides.
  if (faceOrder && nf > 0)
    for (uint32_t id : *faceOrder) visitFace(id % nf);
  for (uint32_t f = 0; f < nf; ++f) visitFace(f);  // the rest, in file order
  prepared_ = true;

  // The box of the positions faces use, and what a wholly invisible instance counts.
  bounds_ = boundingBox(slotPositions_);
  instanceTriangles_ = 0;
  instanceDegenerate_ = 0;
  for (uint32_t f = 0; f < nf; ++f) {
    const uint32_t n = mesh.cornerCount(f);
    (n >= 3 ? instanceTriangles_ : instanceDegenerate_) += n >= 3 ? n - 2 : 1;
  }
  if (faceOrder && batches) prepareBatches(*faceOrder, *batches);
}

void FaceTransformer::prepareBatches(const std::vector<uint32_t>& faceOrder,
                                     const std::vector<uint32_t>& batches) {
  const Mesh& mesh = *scene_.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const size_t slots = slotPositions_.size();
  batchFaces_ = faceOrder;
  batchFaceStart_ = batches;
  batchFaceCorners_.resize(faceOrder.size());
  for (size_t i = 0; i < faceOrder.size(); ++i) {
    const uint32_t n = mesh.cornerCount(faceOrder[i] % nf);
    batchFaceCorners_[i] = uint8_t(n <= 255 ? n : 0);
  }
  batchVertexStart_.assign(1, 0);
  batchCornerStart_.assign(1, 0);
  batchVertexSlot_.clear();
  batchVertexInstance_.clear();
  batchCorners_.clear();
  // Local numbers of the vertices of the batch being built, by global vertex; `seen` tells
  // whether the entry belongs to this batch.
  std::vector<uint32_t> localOf(slots * scene_.instanceCount());
  std::vector<uint32_t> seen(localOf.size(), ~0u);
  for (size_t b = 0; b + 1 < batches.size(); ++b) {
    const uint32_t first = uint32_t(batchVertexSlot_.size());
    for (uint32_t i = batches[b]; i < batches[b + 1]; ++i) {
      const uint32_t id = faceOrder[i], k = id / nf, f = id % nf;
      for (uint32_t c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; ++c) {
        const size_t vertex = size_t(k) * slots + cornerSlots_[c];
        if (seen[vertex] != b) {
          seen[vertex] = uint32_t(b);
          localOf[vertex] = uint32_t(batchVertexSlot_.size()) - first;
          batchVertexSlot_.push_back(cornerSlots_[c]);
          batchVertexInstance_.push_back(k);
        }
        batchCorners_.push_back(localOf[vertex]);
      }
    }
    batchVertexStart_.push_back(uint32_t(batchVertexSlot_.size()));
    batchCornerStart_.push_back(uint32_t(batchCorners_.size()));
  }
}

Vec4 FaceTransformer::clipOf(size_t vertex) const {
  size_t slot = 0, instance = 0;
  if (view_.slot) {
    slot = view_.slot[vertex];
    instance = view_.instance[vertex];
  } else {
    const size_t slots = slotPositions_.size();
    slot = vertex % slots;
    instance = view_.firstInstance + vertex / slots;
  }
  const Vec3& p = slotPositions_[slot];
  return mvp_[instance] * Vec4(p[0], p[1], p[2], 1.0);
}

void FaceTransformer::computeVertex(const Mat4& mvp, const Vec3& position, size_t vertex) {
  // The same product as clipOf(vertex).
  projectVertex(mvp, position, viewport_, frame_, view_.state[vertex], view_.window[vertex]);
}

// Inline here: the per-face loop of transformInstance() runs it for most faces.
inline bool FaceTransformer::droppedBeforeDepths(const FixedPoint& a, const FixedPoint& b,
                                                 const FixedPoint& c, int64_t area,
                                                 FrameGeometry& out) const {
  TransformCounters& counters = out.counters;
  if (area == 0) {
    counters.degenerate += 1;
    return true;
  }
  // y points down in window space, so counter-clockwise in NDC is a negative area here.
  if (cull_ && area > 0) {
    counters.backfaceCulled += 1;
    return true;
  }
  // A face that covers no sample centre (far away, a seventh of crowd's front faces) would
  // be set up and stored to draw nothing, by every algorithm.
  const SampleRect r = sampleBounds(a, b, c, out.width, out.height);
  if (r.empty()) return true;
  // Where the instance's nearest depth is hidden, which needs no depth loaded: enough for a
  // face of an instance wholly behind what is drawn there.
  if (!hiddenTiles_.marked) return false;
  const int shift = hiddenTiles_.tileShift;
  const int x0 = r.minX >> shift, x1 = r.maxX >> shift, y0 = r.minY >> shift, y1 = r.maxY >> shift;
  if (x1 - x0 > 1 || y1 - y0 > 1) return false;
  const uint8_t* r0 = hiddenTiles_.marked + size_t(y0) * size_t(hiddenTiles_.tilesX);
  const uint8_t* r1 = hiddenTiles_.marked + size_t(y1) * size_t(hiddenTiles_.tilesX);
  if (!(r0[x0] & r0[x1] & r1[x0] & r1[x1])) return false;
  ++counters.filtered;
  return true;
}

// appendFace(), with its common case inline: a triangle whose corners all lie inside the view
// volume's planes and the guard band (most faces) takes appendTriangle()'s path here. Written
// out rather than calling an inline appendTriangle(): that measured 1.5 ms slower in the
// hierarchical transform on crowd (72.0 -> 73.4 ms, alternated runs).
inline void FaceTransformer::appendFaceInline(uint32_t faceId, FaceCorners corners, uint32_t n,
                                              FrameGeometry& out) {
  const VertexState* state = view_.state;
  if (n == 3 && (state[corners[0]].code | state[corners[1]].code | state[corners[2]].code) == 0) {
    const FixedPoint& a = state[corners[0]].snapped;
    const FixedPoint& b = state[corners[1]].snapped;
    const FixedPoint& c = state[corners[2]].snapped;
    const int64_t area = orient2d(a, b, c);
    if (!droppedBeforeDepths(a, b, c, area, out))
      appendTriangleDepths(faceId, corners, area < 0, out);
    return;
  }
  appendFace(faceId, corners, n, out);
}

void FaceTransformer::transformAll(FrameGeometry& out) {
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k) transformInstance(k, out);
}

FaceTransformer::InstanceView FaceTransformer::viewOfInstance(uint32_t instance) {
  if (!prepared_) prepare();
  InstanceView view;
  if (slotPositions_.empty()) return view;
  const Mat4& m = mvp_[instance];
  // Clip coordinates are affine in the position, so over the box they are bounded by its
  // corners. A vertex's own product rounds each of its four terms and three sums: within
  // 2^-50 of reach[i], the sum of the terms' magnitudes. A plane rejects the instance only when
  // every corner is beyond it by far more than that (1e-9 of the reach), so that every vertex's
  // outcode has that plane's bit whatever the rounding.
  double reach[4];
  for (int i = 0; i < 4; ++i) {
    reach[i] = std::abs(m(i, 3));
    for (int j = 0; j < 3; ++j)
      reach[i] += std::abs(m(i, j)) * std::max(std::abs(bounds_.lo[j]), std::abs(bounds_.hi[j]));
    if (!(reach[i] < 1e300)) return view;  // NaN or huge: leave it to the vertices
  }
  // Plane i: 2a + s beyond it, for coordinate a = i / 2 against w, on side s = i % 2.
  double beyond[6];
  for (double& b : beyond) b = HUGE_VAL;
  double minW = HUGE_VAL, minNdcZ = HUGE_VAL;
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;  // samples
  for (int c = 0; c < 8; ++c) {
    const Vec3 p((c & 1) ? bounds_.hi[0] : bounds_.lo[0], (c & 2) ? bounds_.hi[1] : bounds_.lo[1],
                 (c & 4) ? bounds_.hi[2] : bounds_.lo[2]);
    const Vec4 clip = m * Vec4(p[0], p[1], p[2], 1.0);
    for (int a = 0; a < 3; ++a) {
      beyond[2 * a] = std::min(beyond[2 * a], -(clip[a] + clip[3]));       // a < -w
      beyond[2 * a + 1] = std::min(beyond[2 * a + 1], clip[a] - clip[3]);  // a > w
    }
    minW = std::min(minW, clip[3]);
    minNdcZ = std::min(minNdcZ, clip[2] / clip[3]);
    const double x = (clip[0] / clip[3] + 1.0) * 0.5 * width_ * scale_;
    const double y = (1.0 - clip[1] / clip[3]) * 0.5 * height_ * scale_;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  for (int i = 0; i < 6; ++i)
    if (beyond[i] > 1e-9 * (reach[i / 2] + reach[3])) view.outside = true;
  // z / w over the box, where w > 0 throughout, is least at a corner (a ratio of affine
  // functions is monotonic along every line). Each vertex's z / w is within 2^-49 of
  // (reach[2] + |z / w| reach[3]) / w of its exact value, and so are the corners': 1e-9 of that
  // bounds both with room to spare. The window depth is (z / w + 1) / 2.
  if (minW > 1e-6 * reach[3] && std::isfinite(minNdcZ)) {
    const double slack = 1e-9 * (reach[2] + (std::abs(minNdcZ) + 1.0) * reach[3]) / minW;
    const double depth = (minNdcZ - slack + 1.0) * 0.5 - 1e-12;
    if (depth > 0.0) {
      float f = static_cast<float>(depth);
      if (double(f) > depth) f = nextFloatTowardZero(f);
      view.nearest = std::min(f, 1.0f);
      // The box's projection (w > 0 at every corner), widened for rounding and snapping.
      const double w = width_ * scale_ - 1.0, h = height_ * scale_ - 1.0;
      view.area.minX = int(std::min(std::max(std::floor(x0) - 2.0, 0.0), w));
      view.area.maxX = int(std::min(std::max(std::ceil(x1) + 2.0, 0.0), w));
      view.area.minY = int(std::min(std::max(std::floor(y0) - 2.0, 0.0), h));
      view.area.maxY = int(std::min(std::max(std::ceil(y1) + 2.0, 0.0), h));
    }
  }
  return view;
}

void FaceTransformer::transformInstance(uint32_t instance, FrameGeometry& out) {
  if (!prepared_) prepare();
  out.width = width_ * scale_;
  out.height = height_ * scale_;
  const InstanceView instanceView = viewOfInstance(instance);
  if (instanceView.outside) {
    // Every face would be clipped away (those of fewer than 3 corners: degenerate).
    out.counters.clippedAway += instanceTriangles_;
    out.counters.degenerate += instanceDegenerate_;
    return;
  }
  hiddenTiles_ = filter_ && instanceView.nearest > 0.0f
                     ? filter_->beginInstance(instanceView.nearest, instanceView.area)
                     : HiddenTiles();
  const Mesh& mesh = *scene_.mesh;
  const size_t slots = slotPositions_.size();
  instanceState_.resize(slots);
  instanceWindow_.resize(slots);
  view_ = VertexView{instanceState_.data(), instanceWindow_.data(), nullptr, nullptr, instance};
  const Mat4& mvp = mvp_[instance];
  size_t v = 0;
  if (avx2_) {
    for (; v + 4 <= slots; v += 4) {
      const Vec3* p = slotPositions_.data() + v;
      const Vec3* const positions[4] = {p, p + 1, p + 2, p + 3};
      projectVertices4Avx2(mvp, positions, viewport_, frame_, &instanceState_[v],
                           &instanceWindow_[v]);
    }
  }
  for (; v < slots; ++v) computeVertex(mvp, slotPositions_[v], v);
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t* faceStart = mesh.faceStart.data();
  for (uint32_t f = 0; f < nf; ++f) {
    const uint32_t first = faceStart[f];
    appendFaceInline(instance * nf + f, FaceCorners{cornerSlots_.data() + first, 0},
                     faceStart[f + 1] - first, out);
  }
}

void FaceTransformer::transformFace(uint32_t faceId, FrameGeometry& out) {
  if (!prepared_) prepare();
  const Mesh& mesh = *scene_.mesh;
  const size_t slots = slotPositions_.size();
  if (state_.size() != slots * scene_.instanceCount()) {
    state_.assign(slots * scene_.instanceCount(), VertexState());
    vertexWindow_.resize(slots * scene_.instanceCount());
  }
  view_ = VertexView{state_.data(), vertexWindow_.data(), nullptr, nullptr, 0};
  hiddenTiles_ = HiddenTiles();
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t k = faceId / nf, f = faceId % nf;
  out.width = width_ * scale_;
  out.height = height_ * scale_;
  const uint32_t n = mesh.cornerCount(f);
  const uint32_t* slot = cornerSlots_.data() + mesh.faceStart[f];
  const FaceCorners corners{slot, uint32_t(k * slots)};
  for (uint32_t i = 0; i < n; ++i)
    if (view_.state[corners[i]].frame != frame_)
      computeVertex(mvp_[k], slotPositions_[slot[i]], corners[i]);
  appendFace(faceId, corners, n, out);
}

void FaceTransformer::transformBatch(uint32_t batch, FrameGeometry& out) {
  const Mesh& mesh = *scene_.mesh;
  const uint32_t v0 = batchVertexStart_[batch], v1 = batchVertexStart_[batch + 1];
  const uint32_t count = v1 - v0;
  if (batchState_.size() < count) {
    batchState_.resize(count);
    batchWindow_.resize(count);
  }
  view_ = VertexView{batchState_.data(), batchWindow_.data(), batchVertexSlot_.data() + v0,
                     batchVertexInstance_.data() + v0, 0};
  hiddenTiles_ = HiddenTiles();
  const uint32_t* slot = view_.slot;
  const uint32_t* instance = view_.instance;
  uint32_t i = 0;
  if (avx2_) {
    // Four at a time while they belong to one instance (a leaf's faces usually do).
    for (; i + 4 <= count; i += 4) {
      if (instance[i] != instance[i + 3] || instance[i + 1] != instance[i] ||
          instance[i + 2] != instance[i]) {
        for (uint32_t j = i; j < i + 4; ++j)
          computeVertex(mvp_[instance[j]], slotPositions_[slot[j]], j);
        continue;
      }
      const Vec3* const positions[4] = {&slotPositions_[slot[i]], &slotPositions_[slot[i + 1]],
                                        &slotPositions_[slot[i + 2]], &slotPositions_[slot[i + 3]]};
      projectVertices4Avx2(mvp_[instance[i]], positions, viewport_, frame_, &view_.state[i],
                           &view_.window[i]);
    }
  }
  for (; i < count; ++i) computeVertex(mvp_[instance[i]], slotPositions_[slot[i]], i);
  out.width = width_ * scale_;
  out.height = height_ * scale_;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t* local = batchCorners_.data() + batchCornerStart_[batch];
  for (uint32_t f = batchFaceStart_[batch]; f < batchFaceStart_[batch + 1]; ++f) {
    const uint32_t faceId = batchFaces_[f];
    // The stored count spares a division on the face's path (0: too many to store).
    const uint32_t n = batchFaceCorners_[f] ? batchFaceCorners_[f] : mesh.cornerCount(faceId % nf);
    appendFaceInline(faceId, FaceCorners{local, 0}, n, out);
    local += n;
  }
}

namespace {

// Prefetches the cache lines of `count` elements from `first`.
template <typename T>
void prefetchRange(const T* first, size_t count) {
  const char* p = reinterpret_cast<const char*>(first);
  const char* end = reinterpret_cast<const char*>(first + count);
  for (; p < end; p += 64) __builtin_prefetch(p);
}

}  // namespace

void FaceTransformer::prefetchBatch(uint32_t batch) const {
  const uint32_t f0 = batchFaceStart_[batch], f1 = batchFaceStart_[batch + 1];
  const uint32_t v0 = batchVertexStart_[batch], v1 = batchVertexStart_[batch + 1];
  const uint32_t c0 = batchCornerStart_[batch], c1 = batchCornerStart_[batch + 1];
  prefetchRange(batchFaces_.data() + f0, f1 - f0);
  prefetchRange(batchFaceCorners_.data() + f0, f1 - f0);
  prefetchRange(batchVertexSlot_.data() + v0, v1 - v0);
  prefetchRange(batchVertexInstance_.data() + v0, v1 - v0);
  prefetchRange(batchCorners_.data() + c0, c1 - c0);
}

float nearestCornerDepth(const Vec3* window, uint32_t count) {
  double lo = window[0][2];
  for (uint32_t i = 1; i < count; ++i) lo = std::min(lo, window[i][2]);
  float flo = static_cast<float>(std::max(lo, 0.0));
  if (double(flo) > lo) flo = nextFloatTowardZero(flo);
  return std::max(flo, 0.0f);
}

namespace {

// Sets the plane's clamp range to the corners' depths, widened to the enclosing floats.
void setDepthRange(DepthPlane& plane, const Vec3* window, uint32_t count) {
  double hi = window[0][2];
  for (uint32_t i = 1; i < count; ++i) hi = std::max(hi, window[i][2]);
  float fhi = static_cast<float>(std::min(hi, 1.0));
  if (double(fhi) < hi) fhi = nextFloatTowardOne(fhi);
  plane.loBits = int32_t(floatBits(nearestCornerDepth(window, count)));
  plane.hiBits = int32_t(floatBits(std::min(fhi, 1.0f)));
}

// The plane with `normal` through `point` (samples, samples, depth), clamped to the depth
// range of the polygon `window`; `ok` is false when the plane is vertical on screen. Inline in
// every caller: as a call, its result went through the stack (crowd transform, alternated
// runs: zbuffer 108.9 -> 102.6 ms, octree 15.0 -> 14.0 ms).
[[gnu::always_inline]] inline DepthPlane planeThrough(const Vec3& normal, const Vec3& point,
                                                      const Vec3* window, uint32_t count,
                                                      bool& ok) {
  DepthPlane plane;
  ok = normal[2] != 0.0 && std::isfinite(normal[2]);
  if (!ok) return plane;
  plane.a = -normal[0] / normal[2];
  plane.b = -normal[1] / normal[2];
  plane.c = point[2] - plane.a * point[0] - plane.b * point[1];
  setDepthRange(plane, window, count);
  return plane;
}

// Appends a face (its snapped corners and positively oriented pieces) to the frame.
void pushFace(uint32_t faceId, const DepthPlane& plane, bool frontFacing, const FixedPoint* corners,
              uint32_t cornerCount, const std::array<uint32_t, 3>* pieces, uint32_t pieceCount,
              FrameGeometry& out) {
  ScreenFace face;
  face.id = faceId;
  face.firstVertex = uint32_t(out.vertices.size());
  face.vertexCount = cornerCount;
  face.firstTriangle = uint32_t(out.triangles.size());
  face.triangleCount = pieceCount;
  face.frontFacing = frontFacing;
  const uint32_t faceIndex = uint32_t(out.faces.size());
  // One by one: the range insert is a call, and faces have few corners.
  for (uint32_t i = 0; i < cornerCount; ++i) out.vertices.push_back(corners[i]);
  for (uint32_t i = 0; i < pieceCount; ++i) {
    const std::array<uint32_t, 3>& t = pieces[i];
    out.triangles.push_back(
        ScreenTriangle{{corners[t[0]], corners[t[1]], corners[t[2]]}, faceIndex, faceId, plane});
  }
  out.faces.push_back(face);
}

// Positive orientation (orient2d > 0) of a triangle's corners: y points down in window space,
// so a front face (counter-clockwise in NDC) has to be walked the other way round.
std::array<uint32_t, 3> orientedPiece(bool frontFacing) {
  return frontFacing ? std::array<uint32_t, 3>{0, 2, 1} : std::array<uint32_t, 3>{0, 1, 2};
}

}  // namespace

DepthPlane FaceTransformer::planeOf(const Vec3* window, uint32_t count, bool& ok) const {
  // Newell's normal of the window-space polygon (x, y in samples, z depth), through the
  // centroid: z = a x + b y + c. From the unsnapped positions.
  if (count == 3) {
    // A triangle's plane through its first corner: fewer operations than Newell's sum.
    const Vec3 p(window[0][0] * scale_, window[0][1] * scale_, window[0][2]);
    const Vec3 u(window[1][0] * scale_ - p[0], window[1][1] * scale_ - p[1], window[1][2] - p[2]);
    const Vec3 v(window[2][0] * scale_ - p[0], window[2][1] * scale_ - p[1], window[2][2] - p[2]);
    return planeThrough(u.cross(v), p, window, count, ok);
  }
  Vec3 normal(0, 0, 0), centre(0, 0, 0);
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3& pw = window[i];
    const Vec3& qw = window[i + 1 == count ? 0 : i + 1];
    const Vec3 p(pw[0] * scale_, pw[1] * scale_, pw[2]), q(qw[0] * scale_, qw[1] * scale_, qw[2]);
    normal += Vec3((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                   (p[0] - q[0]) * (p[1] + q[1]));
    centre += p;
  }
  centre *= 1.0 / count;
  return planeThrough(normal, centre, window, count, ok);
}

void FaceTransformer::appendFace(uint32_t faceId, FaceCorners corners, uint32_t n,
                                 FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  const uint64_t pieces = n >= 3 ? n - 2 : 1;  // counters are in triangles
  if (n < 3) {
    counters.degenerate += pieces;
    return;
  }
  uint32_t all = ~0u, any = 0;
  for (uint32_t i = 0; i < n; ++i) {
    all &= view_.state[corners[i]].code;
    any |= view_.state[corners[i]].code;
  }
  if (any & kNotFinite) {
    counters.degenerate += pieces;
    return;
  }
  if (all & 0x3F) {  // wholly beyond one plane of the view volume: covers nothing
    counters.clippedAway += pieces;
    return;
  }
  if (any & kNeedsClip) {
    appendClippedFace(faceId, corners, n, pieces, out);
    return;
  }
  if (n == 3) {
    appendTriangle(faceId, corners, out);
    return;
  }
  // Every corner inside near/far and the guard band, already snapped.
  snapped_.clear();
  for (uint32_t i = 0; i < n; ++i) {
    const FixedPoint& p = view_.state[corners[i]].snapped;
    if (snapped_.empty() || p != snapped_.back()) snapped_.push_back(p);
  }
  // Back faces are known from the snapped corners alone: decide before the plane's divisions.
  if (snapped_.size() == 3 && cull_) {
    const int64_t area = orient2d(snapped_[0], snapped_[1], snapped_[2]);
    if (area > 0) {  // clockwise in NDC (y points down here)
      counters.backfaceCulled += pieces;
      return;
    }
  }
  window_.resize(n);
  for (uint32_t i = 0; i < n; ++i) window_[i] = view_.window[corners[i]];
  bool ok = false;
  const DepthPlane plane = planeOf(window_.data(), n, ok);
  if (!ok) {
    counters.degenerate += pieces;
    return;
  }
  appendSnappedFace(faceId, plane, pieces, out);
}

void FaceTransformer::appendTriangle(uint32_t faceId, FaceCorners corners, FrameGeometry& out) {
  // The common case, kept short: a triangle inside near/far and the guard band. Same result
  // as appendSnappedFace() would give, without its scratch buffers.
  const FixedPoint& a = view_.state[corners[0]].snapped;
  const FixedPoint& b = view_.state[corners[1]].snapped;
  const FixedPoint& c = view_.state[corners[2]].snapped;
  const int64_t area = orient2d(a, b, c);
  if (droppedBeforeDepths(a, b, c, area, out)) return;
  appendTriangleDepths(faceId, corners, area < 0, out);
}

void FaceTransformer::appendTriangleDepths(uint32_t faceId, FaceCorners corners, bool frontFacing,
                                           FrameGeometry& out) {
  const FixedPoint points[3] = {view_.state[corners[0]].snapped, view_.state[corners[1]].snapped,
                                view_.state[corners[2]].snapped};
  const Vec3 window[3] = {view_.window[corners[0]], view_.window[corners[1]],
                          view_.window[corners[2]]};
  if (filter_ && filter_->hidden(points, nearestCornerDepth(window, 3), faceId)) return;
  bool ok = false;
  const DepthPlane plane = planeOf(window, 3, ok);
  if (!ok) {
    out.counters.degenerate += 1;
    return;
  }
  const std::array<uint32_t, 3> piece = orientedPiece(frontFacing);
  pushFace(faceId, plane, frontFacing, points, 3, &piece, 1, out);
}

void FaceTransformer::appendClippedFace(uint32_t faceId, FaceCorners corners, uint32_t n,
                                        uint64_t pieces, FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  faceClip_.resize(n);
  uint32_t any = 0;
  for (uint32_t i = 0; i < n; ++i) {
    faceClip_[i] = clipOf(corners[i]);
    any |= view_.state[corners[i]].code;
  }
  const Vec4* poly = faceClip_.data();
  uint32_t count = n;
  if (any & (kNear | kFar)) {
    clipped_.resize(clipNearFarCapacity(n));
    clipScratch_.resize(clipNearFarCapacity(n));
    count = uint32_t(clipNearFar(poly, n, clipped_.data(), clipScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    poly = clipped_.data();
  }
  window_.resize(count);
  for (uint32_t i = 0; i < count; ++i) window_[i] = clipToWindow(poly[i], width_, height_);

  // Keep snapped coordinates in range however far outside the image the face reaches.
  const double guard = kGuardBand / scale_;
  const Vec3* win = window_.data();
  bool outside = false;
  for (uint32_t i = 0; i < count; ++i)
    outside |= std::abs(win[i][0]) > guard || std::abs(win[i][1]) > guard;
  if (outside) {
    guarded_.resize(clipGuardBandCapacity(count));
    guardScratch_.resize(clipGuardBandCapacity(count));
    count = uint32_t(clipGuardBand(win, count, guard, guarded_.data(), guardScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    win = guarded_.data();
  }
  // The plane from the corners within the guard band: those of a face reaching 1e155 units
  // would overflow its normal (their cross product) and lose a face that covers the image.
  bool ok = false;
  const DepthPlane plane = planeOf(win, count, ok);
  if (!ok) {
    counters.degenerate += pieces;
    return;
  }
  snapped_.clear();
  for (uint32_t i = 0; i < count; ++i) {
    const FixedPoint p{snapToSubpixel(win[i][0]) * scale_, snapToSubpixel(win[i][1]) * scale_};
    if (snapped_.empty() || p != snapped_.back()) snapped_.push_back(p);
  }
  appendSnappedFace(faceId, plane, pieces, out);
}

void FaceTransformer::appendSnappedFace(uint32_t faceId, const DepthPlane& plane, uint64_t pieces,
                                        FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  while (snapped_.size() > 1 && snapped_.back() == snapped_.front()) snapped_.pop_back();
  if (snapped_.size() < 3) {
    counters.degenerate += pieces;
    return;
  }
  __int128 area = 0;
  for (size_t i = 0; i < snapped_.size(); ++i) {
    const FixedPoint& a = snapped_[i];
    const FixedPoint& b = snapped_[i + 1 == snapped_.size() ? 0 : i + 1];
    area += __int128(int64_t(a.x) * b.y - int64_t(b.x) * a.y);
  }
  if (area == 0) {
    counters.degenerate += pieces;
    return;
  }
  // y points down in window space, so counter-clockwise in NDC is a negative area here.
  const bool frontFacing = area < 0;
  if (cull_ && !frontFacing) {
    counters.backfaceCulled += pieces;
    return;
  }
  pieces_.clear();
  if (snapped_.size() == 3) {
    pieces_.push_back(orientedPiece(frontFacing));
  } else if (!triangulatePolygon(snapped_.data(), uint32_t(snapped_.size()), pieces_, ring_) ||
             pieces_.empty()) {
    counters.degenerate += pieces;
    return;
  }

  pushFace(faceId, plane, frontFacing, snapped_.data(), uint32_t(snapped_.size()), pieces_.data(),
           uint32_t(pieces_.size()), out);
}

}  // namespace zrender
