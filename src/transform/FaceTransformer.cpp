#include "zrender/transform/FaceTransformer.hpp"

#include <algorithm>
#include <array>

#include "zrender/base/Clock.hpp"
#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

FaceTransformer::FaceTransformer(const Scene& scene, int sampleScale, bool cull,
                                 FaceBatches batches)
    : scene_(scene), layout_(scene, batches), assembler_(sampleScale, cull), avx2_(cpuHasAvx2()) {
  viewport_.scale = sampleScale;
}

FaceTransformer::FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale,
                                 bool cull)
    : FaceTransformer(scene, sampleScale, cull) {
  beginFrame(camera);
}

void FaceTransformer::beginFrame(const Camera& camera) {
  transformMs_ = 0.0;
  ScopedTimer timer(transformMs_);
  viewport_.width = camera.width;
  viewport_.height = camera.height;
  const Mat4 viewProjection = camera.projection * camera.view;
  mvp_.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    mvp_.push_back(viewProjection * scene_.modelMatrix(k));
  ++frame_;
  assembler_.beginFrame(camera.width, camera.height, layout_.slotPositions(), mvp_);
  if (threads_ && threads_->parallel()) {
    if (workers_.size() != size_t(threads_->count()))
      workers_.assign(size_t(threads_->count()), Worker{assembler_, {}, {}, 0.0});
    for (Worker& w : workers_) {
      w.assembler.beginFrame(camera.width, camera.height, layout_.slotPositions(), mvp_);
      w.batchMs = 0.0;
    }
  }
}

double FaceTransformer::transformMs() const {
  double ms = transformMs_;
  for (const Worker& w : workers_) ms += w.batchMs / double(workers_.size());
  return ms;
}

InstanceView FaceTransformer::viewOfInstance(uint32_t instance) const {
  const MeshLayout::Part& part = layout_.part(scene_.instances[instance].part);
  if (part.slotBegin == part.slotEnd) return InstanceView();
  return zrender::viewOfInstance(mvp_[instance], part.bounds, viewport_);
}

const MeshLayout::Part& FaceTransformer::partOf(uint32_t instance) const {
  return layout_.part(scene_.instances[instance].part);
}

void FaceTransformer::pull(const FaceRequest& request, FrameGeometry& out,
                           std::vector<FrameGeometry>* parts) {
  if (request.scope == FaceRequest::Scope::Batch) {
    pullBatch(request.index, out);
    return;
  }
  const bool instance = request.scope == FaceRequest::Scope::Instance;
  if (threads_ && threads_->parallel()) {
    pullParallel(instance ? int64_t(request.index) : -1, out, request.filter, parts);
    return;
  }
  // One thread: one part, if parts are asked for.
  FrameGeometry* into = &out;
  if (parts) {
    parts->resize(1);
    into = &parts->front();
    into->clear();
  }
  if (instance)
    pullInstance(request.index, *into, request.filter);
  else
    pullAll(*into);
  if (parts) {
    out.counters += into->counters;
    out.width = into->width;
    out.height = into->height;
  }
}

void FaceTransformer::pullAll(FrameGeometry& out) {
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k) pullInstance(k, out, nullptr);
}

void FaceTransformer::projectSlots(uint32_t instance, size_t begin, size_t end, VertexState* state,
                                   Vec3* window) const {
  const std::vector<Vec3>& positions = layout_.slotPositions();
  const Mat4& mvp = mvp_[instance];
  size_t v = begin;
  if (avx2_) {
    for (; v + 4 <= end; v += 4) {
      const Vec3* p = positions.data() + v;
      const Vec3* const four[4] = {p, p + 1, p + 2, p + 3};
      projectVertices4Avx2(mvp, four, viewport_, frame_, state + v, window + v);
    }
  }
  for (; v < end; ++v) projectVertex(mvp, positions[v], viewport_, frame_, state[v], window[v]);
}

void FaceTransformer::projectInstance(uint32_t instance) {
  const size_t slots = layout_.slotPositions().size();
  instanceState_.resize(slots);
  instanceWindow_.resize(slots);
  const MeshLayout::Part& part = partOf(instance);
  projectSlots(instance, part.slotBegin, part.slotEnd, instanceState_.data(),
               instanceWindow_.data());
}

void FaceTransformer::assembleFaces(uint32_t instance, uint32_t faceBegin, uint32_t faceEnd,
                                    const VertexView& vertices, FaceAssembler& assembler,
                                    FrameGeometry& out) const {
  out.width = viewport_.width * viewport_.scale;
  out.height = viewport_.height * viewport_.scale;
  assembler.setVertices(vertices);
  const uint32_t* faceStart = scene_.mesh->faceStart.data();
  const uint32_t* cornerSlots = layout_.cornerSlots().data();
  // Face f of the mesh is this instance's id firstId + (f - its model's first face).
  const uint32_t idOffset = scene_.instances[instance].firstId - scene_.modelOf(instance).faceBegin;
  for (uint32_t f = faceBegin; f < faceEnd; ++f) {
    const uint32_t first = faceStart[f];
    assembler.append(idOffset + f, FaceCorners{cornerSlots + first, 0}, faceStart[f + 1] - first,
                     out);
  }
}

namespace {

// Faces per chunk of pullParallel() when one instance is cut into chunks: enough for a
// chunk's work to dwarf a task's cost, few enough for the chunks to balance.
constexpr uint32_t kChunkFaces = 4096;

// Appends `chunk` to `out`, its indices moved by what `out` held before (`base`: its vertex,
// face and triangle counts then).
void appendChunk(const FrameGeometry& chunk, const size_t base[3], FrameGeometry& out) {
  std::copy(chunk.vertices.begin(), chunk.vertices.end(), out.vertices.begin() + base[0]);
  ScreenFace* faces = out.faces.data() + base[1];
  for (size_t i = 0; i < chunk.faces.size(); ++i) {
    faces[i] = chunk.faces[i];
    faces[i].firstVertex += uint32_t(base[0]);
    faces[i].firstTriangle += uint32_t(base[2]);
  }
  ScreenTriangle* triangles = out.triangles.data() + base[2];
  for (size_t i = 0; i < chunk.triangles.size(); ++i) {
    triangles[i] = chunk.triangles[i];
    triangles[i].face += uint32_t(base[1]);
  }
}

}  // namespace

uint32_t FaceTransformer::transformChunks(int64_t instance, TriangleFilter* filter,
                                          std::vector<FrameGeometry>& chunks) {
  const Threads& threads = *threads_;
  // Several instances: one chunk per instance, each projecting its own vertices. One instance:
  // its vertices projected by all threads, then its faces in chunks.
  const bool single = instance >= 0 || scene_.instanceCount() == 1;
  const uint32_t only = instance >= 0 ? uint32_t(instance) : 0;
  const SceneModel& onlyModel = scene_.modelOf(only);
  const uint32_t onlyFaces = onlyModel.faceEnd - onlyModel.faceBegin;
  const uint32_t count =
      single ? (onlyFaces + kChunkFaces - 1) / kChunkFaces : scene_.instanceCount();
  if (chunks.size() < count) chunks.resize(count);
  const InstanceView onlyView = viewOfInstance(only);
  HiddenTiles hidden;
  if (single && !onlyView.outside) {
    if (filter && onlyView.nearest > 0.0f)
      hidden = filter->beginInstance(onlyView.nearest, onlyView.area);
    const size_t slots = layout_.slotPositions().size();
    instanceState_.resize(slots);
    instanceWindow_.resize(slots);
    const MeshLayout::Part& part = partOf(only);
    threads.forRanges(part.slotEnd - part.slotBegin, 4096, [&](size_t begin, size_t end) {
      projectSlots(only, part.slotBegin + begin, part.slotBegin + end, instanceState_.data(),
                   instanceWindow_.data());
    });
  }
  threads.forEach(count, [&](size_t c) {
    Worker& w = workers_[size_t(threads.slot())];
    FrameGeometry& chunk = chunks[c];
    chunk.clear();
    const uint32_t k = single ? only : uint32_t(c);
    const InstanceView view = single ? onlyView : viewOfInstance(k);
    if (view.outside) {
      // Every face would be clipped away (those of fewer than 3 corners: degenerate).
      if (single && c > 0) return;
      chunk.counters.clippedAway += partOf(k).triangles;
      chunk.counters.degenerate += partOf(k).degenerate;
      return;
    }
    if (single) {
      const uint32_t begin = onlyModel.faceBegin + uint32_t(c) * kChunkFaces;
      w.assembler.setFilter(filter, hidden);
      assembleFaces(
          only, begin, std::min(onlyModel.faceEnd, begin + kChunkFaces),
          VertexView{instanceState_.data(), instanceWindow_.data(), nullptr, nullptr, only},
          w.assembler, chunk);
      w.assembler.setFilter(nullptr, HiddenTiles());
      return;
    }
    const size_t slots = layout_.slotPositions().size();
    w.state.resize(slots);
    w.window.resize(slots);
    const MeshLayout::Part& part = partOf(k);
    projectSlots(k, part.slotBegin, part.slotEnd, w.state.data(), w.window.data());
    const SceneModel& model = scene_.modelOf(k);
    assembleFaces(k, model.faceBegin, model.faceEnd,
                  VertexView{w.state.data(), w.window.data(), nullptr, nullptr, k}, w.assembler,
                  chunk);
  });
  return count;
}

void FaceTransformer::pullParallel(int64_t instance, FrameGeometry& out, TriangleFilter* filter,
                                   std::vector<FrameGeometry>* parts) {
  ScopedTimer timer(transformMs_);
  // Left in parts for the algorithms that read them so (and the shader, which reads the faces'
  // ids): joining them would be a copy of every vertex, face and triangle.
  std::vector<FrameGeometry>& chunks = parts ? *parts : chunks_;
  const uint32_t count = transformChunks(instance, filter, chunks);
  for (uint32_t c = 0; c < count; ++c) out.counters += chunks[c].counters;
  out.width = viewport_.width * viewport_.scale;
  out.height = viewport_.height * viewport_.scale;
  if (parts) {
    parts->resize(count);
    return;
  }
  // Joined in chunk order, which is face id order: the geometry of one thread exactly.
  std::vector<std::array<size_t, 3>> base(count);
  size_t sizes[3] = {out.vertices.size(), out.faces.size(), out.triangles.size()};
  for (uint32_t c = 0; c < count; ++c) {
    base[c] = {sizes[0], sizes[1], sizes[2]};
    sizes[0] += chunks[c].vertices.size();
    sizes[1] += chunks[c].faces.size();
    sizes[2] += chunks[c].triangles.size();
  }
  out.vertices.resize(sizes[0]);
  out.faces.resize(sizes[1]);
  out.triangles.resize(sizes[2]);
  threads_->forEach(count, [&](size_t c) { appendChunk(chunks[c], base[c].data(), out); });
}

void FaceTransformer::pullInstance(uint32_t instance, FrameGeometry& out, TriangleFilter* filter) {
  ScopedTimer timer(transformMs_);
  out.width = viewport_.width * viewport_.scale;
  out.height = viewport_.height * viewport_.scale;
  const InstanceView view = viewOfInstance(instance);
  if (view.outside) {
    // Every face would be clipped away (those of fewer than 3 corners: degenerate).
    out.counters.clippedAway += partOf(instance).triangles;
    out.counters.degenerate += partOf(instance).degenerate;
    return;
  }
  assembler_.setFilter(filter, filter && view.nearest > 0.0f
                                   ? filter->beginInstance(view.nearest, view.area)
                                   : HiddenTiles());
  projectInstance(instance);
  assembler_.setVertices(
      VertexView{instanceState_.data(), instanceWindow_.data(), nullptr, nullptr, instance});
  const Mesh& mesh = *scene_.mesh;
  const SceneModel& model = scene_.modelOf(instance);
  const uint32_t idOffset = scene_.instances[instance].firstId - model.faceBegin;
  const uint32_t* faceStart = mesh.faceStart.data();
  const uint32_t* cornerSlots = layout_.cornerSlots().data();
  for (uint32_t f = model.faceBegin; f < model.faceEnd; ++f) {
    const uint32_t first = faceStart[f];
    assembler_.append(idOffset + f, FaceCorners{cornerSlots + first, 0}, faceStart[f + 1] - first,
                      out);
  }
  assembler_.setFilter(nullptr, HiddenTiles());
}

void FaceTransformer::projectBatch(uint32_t batch, std::vector<VertexState>& state,
                                   std::vector<Vec3>& window) const {
  const MeshLayout::Batches& b = layout_.batches();
  const std::vector<Vec3>& positions = layout_.slotPositions();
  const uint32_t v0 = b.vertexStart[batch], count = b.vertexStart[batch + 1] - v0;
  if (state.size() < count) {
    state.resize(count);
    window.resize(count);
  }
  const uint32_t* slot = b.vertexSlot.data() + v0;
  const uint32_t* instance = b.vertexInstance.data() + v0;
  uint32_t i = 0;
  if (avx2_) {
    // Four at a time while they belong to one instance (a leaf's faces usually do).
    for (; i + 4 <= count; i += 4) {
      if (instance[i] != instance[i + 3] || instance[i + 1] != instance[i] ||
          instance[i + 2] != instance[i]) {
        for (uint32_t j = i; j < i + 4; ++j)
          projectVertex(mvp_[instance[j]], positions[slot[j]], viewport_, frame_, state[j],
                        window[j]);
        continue;
      }
      const Vec3* const four[4] = {&positions[slot[i]], &positions[slot[i + 1]],
                                   &positions[slot[i + 2]], &positions[slot[i + 3]]};
      projectVertices4Avx2(mvp_[instance[i]], four, viewport_, frame_, &state[i], &window[i]);
    }
  }
  for (; i < count; ++i)
    projectVertex(mvp_[instance[i]], positions[slot[i]], viewport_, frame_, state[i], window[i]);
}

void FaceTransformer::pullBatch(uint32_t batch, FrameGeometry& out) {
  // With several threads, each its own scratch and clock (transformMs()).
  const bool shared = threads_ && threads_->parallel();
  Worker* w = shared ? &workers_[size_t(threads_->slot())] : nullptr;
  ScopedTimer timer(shared ? w->batchMs : transformMs_);
  std::vector<VertexState>& batchState = shared ? w->state : batchState_;
  std::vector<Vec3>& batchWindow = shared ? w->window : batchWindow_;
  FaceAssembler& assembler = shared ? w->assembler : assembler_;
  const MeshLayout::Batches& b = layout_.batches();
  projectBatch(batch, batchState, batchWindow);
  const uint32_t v0 = b.vertexStart[batch];
  assembler.setVertices(VertexView{batchState.data(), batchWindow.data(), b.vertexSlot.data() + v0,
                                   b.vertexInstance.data() + v0, 0});
  out.width = viewport_.width * viewport_.scale;
  out.height = viewport_.height * viewport_.scale;
  const Mesh& mesh = *scene_.mesh;
  const uint32_t* local = b.corners.data() + b.cornerStart[batch];
  for (uint32_t f = b.faceStart[batch]; f < b.faceStart[batch + 1]; ++f) {
    const uint32_t faceId = b.faces[f];
    // The stored count spares a look-up on the face's path (0: too many to store).
    const uint32_t n =
        b.faceCorners[f] ? b.faceCorners[f] : mesh.cornerCount(scene_.locate(faceId).meshFace);
    assembler.append(faceId, FaceCorners{local, 0}, n, out);
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

void FaceTransformer::prefetch(const FaceRequest& request) const {
  if (request.scope != FaceRequest::Scope::Batch) return;
  const uint32_t batch = request.index;
  const MeshLayout::Batches& b = layout_.batches();
  const uint32_t f0 = b.faceStart[batch], f1 = b.faceStart[batch + 1];
  const uint32_t v0 = b.vertexStart[batch], v1 = b.vertexStart[batch + 1];
  const uint32_t c0 = b.cornerStart[batch], c1 = b.cornerStart[batch + 1];
  prefetchRange(b.faces.data() + f0, f1 - f0);
  prefetchRange(b.faceCorners.data() + f0, f1 - f0);
  prefetchRange(b.vertexSlot.data() + v0, v1 - v0);
  prefetchRange(b.vertexInstance.data() + v0, v1 - v0);
  prefetchRange(b.corners.data() + c0, c1 - c0);
}

}  // namespace zrender
