#pragma once

#include <cstdint>
#include <vector>

#include "zrender/base/Threads.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/transform/FaceAssembler.hpp"
#include "zrender/transform/GeometrySource.hpp"
#include "zrender/transform/InstanceView.hpp"
#include "zrender/transform/MeshLayout.hpp"
#include "zrender/transform/VertexProjection.hpp"

namespace zrender {

// The transform stage (docs/design.md, The transform): the GeometrySource of a scene. A pull
// projects the vertices it needs (VertexProjection: four at a time with AVX2) into arrays
// reused from pull to pull, which stay in cache while its faces read them, then hands the
// faces to a FaceAssembler. An instance computes all its vertices first (for a grid, the whole
// model's would not stay in cache: a bunny's are 1.4 MB, crowd's 140 MB); a batch computes its
// own vertex list (MeshLayout). An instance whose box lies wholly beyond one plane of the view
// volume, with margin, is only counted: every face of it would be clipped away.
class FaceTransformer : public GeometrySource {
 public:
  // sampleScale: 1, or 2 for MSAA 4. `batches`: what Batch requests number (the algorithm's
  // prepare()); the model-only set-up is done here (prepare_ms).
  FaceTransformer(const Scene& scene, int sampleScale, bool cull,
                  FaceBatches batches = FaceBatches());
  // The same, with beginFrame(camera) done.
  FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale, bool cull);

  // The threads a pull may spread its work over (null or one: the calling thread alone); its
  // geometry is the same whatever their number.
  void setThreads(const Threads* threads) { threads_ = threads; }

  void beginFrame(const Camera& camera) override;
  // On several threads, a Frame or Instance pull's parts are its chunks.
  void pull(const FaceRequest& request, FrameGeometry& out,
            std::vector<FrameGeometry>* parts = nullptr) override;
  void prefetch(const FaceRequest& request) const override;
  InstanceView viewOfInstance(uint32_t instance) const override;
  // With several threads, the time of the batches they pulled at once counts divided by their
  // number (docs/design.md, Timings and JSON).
  double transformMs() const override;

  const MeshLayout& layout() const { return layout_; }
  int sampleScale() const { return viewport_.scale; }
  const Mat4& modelViewProjection(uint32_t instance) const { return mvp_[instance]; }

 private:
  void pullAll(FrameGeometry& out);
  void pullInstance(uint32_t instance, FrameGeometry& out, TriangleFilter* filter);
  void pullBatch(uint32_t batch, FrameGeometry& out);
  void projectInstance(uint32_t instance);
  void projectBatch(uint32_t batch, std::vector<VertexState>& state,
                    std::vector<Vec3>& window) const;
  // A Frame (`instance` -1) or Instance pull on several threads: the faces in chunks, each
  // into geometry of its own, then joined in face id order into `out`, or left in `parts`.
  // `filter` is asked from every thread at once.
  void pullParallel(int64_t instance, FrameGeometry& out, TriangleFilter* filter,
                    std::vector<FrameGeometry>* parts);
  // The chunks of pullParallel(), into `chunks` (grown as needed; the first ones used, each
  // cleared first); returns their number.
  uint32_t transformChunks(int64_t instance, TriangleFilter* filter,
                           std::vector<FrameGeometry>& chunks);
  // The layout of `instance`'s model: its slots, bounds and counts.
  const MeshLayout::Part& partOf(uint32_t instance) const;
  // A chunk's part of pullParallel: mesh faces [faceBegin, faceEnd) of `instance`, whose vertices
  // `vertices` holds, by `assembler`.
  void assembleFaces(uint32_t instance, uint32_t faceBegin, uint32_t faceEnd,
                     const VertexView& vertices, FaceAssembler& assembler,
                     FrameGeometry& out) const;
  // Projects the vertices of slots [begin, end) of `instance` into state and window.
  void projectSlots(uint32_t instance, size_t begin, size_t end, VertexState* state,
                    Vec3* window) const;

  const Scene& scene_;
  MeshLayout layout_;
  FaceAssembler assembler_;
  VertexViewport viewport_;
  bool avx2_;              // vertices four at a time (projectVertices4Avx2)
  std::vector<Mat4> mvp_;  // per instance, model to clip space
  uint32_t frame_ = 0;     // stamps the vertices computed in this frame
  double transformMs_ = 0.0;
  std::vector<VertexState> instanceState_, batchState_;  // the vertices of the last pull
  std::vector<Vec3> instanceWindow_, batchWindow_;

  // With several threads: the threads, each one's assembler, vertices and batch time, and each
  // chunk's geometry (pullParallel).
  const Threads* threads_ = nullptr;
  struct Worker {
    FaceAssembler assembler;
    std::vector<VertexState> state;
    std::vector<Vec3> window;
    double batchMs = 0.0;
  };
  std::vector<Worker> workers_;
  std::vector<FrameGeometry> chunks_;
};

}  // namespace zrender
