#pragma once

#include <array>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/transform/VertexProjection.hpp"

namespace zrender {

// Screen tiles where every face of the instance being transformed is proved hidden.
struct HiddenTiles {
  const uint8_t* marked = nullptr;  // per tile, row by row, nonzero when hidden; null: none
  int tileShift = 0;                // tiles of 2^tileShift x 2^tileShift samples
  int tilesX = 0;                   // tiles per row
};

// A test the transform asks about a triangle face before setting up its depth plane and
// storing it, for algorithms that can prove it hidden from its corners alone (the z-pyramid):
// such faces then cost little more than a back face.
class TriangleFilter {
 public:
  virtual ~TriangleFilter() = default;
  // Before the faces of an instance (transformInstance()), none of which has a sample nearer
  // than window depth `nearestDepth` (> 0), and whose samples lie in `area` (as far as
  // rounding allows: a hint of where to look, inside the image): the tiles where that bound
  // is already hidden. A face whose sample bounds lie in at most 2 x 2 of them is then dropped
  // before its depths are loaded (and counted in TransformCounters::filtered). Valid until
  // the next call.
  virtual HiddenTiles beginInstance(float /*nearestDepth*/, const SampleRect& /*area*/) {
    return HiddenTiles();
  }
  // Then, for a triangle face still kept: `v`, its snapped corners (samples, either winding),
  // and `nearestDepth`, the least window depth of its corners exactly as the face's
  // DepthPlane::minDepth() will be. True drops the face.
  virtual bool hidden(const FixedPoint* v, float nearestDepth, uint32_t faceId) = 0;
};

// The least corner depth of a face as DepthPlane::minDepth() holds it: the greatest float not
// above the least of `window[i][2]`, clamped to [0, 1].
float nearestCornerDepth(const Vec3* window, uint32_t count);

// Vertices to window coordinates, near/far clipping, snapping, back-face culling and window
// space triangulation: the transform stage of SPEC §4–5, shared by every algorithm. A triangle
// face that needs no clipping and covers no sample centre is left out (it could not change any
// buffer).
class FaceTransformer {
 public:
  // sampleScale: 1, or 2 for MSAA 4 (the four samples of a pixel are a 2 x 2 grid of samples).
  // Call beginFrame() before transforming faces.
  FaceTransformer(const Scene& scene, int sampleScale, bool cull);
  // The same, ready for one frame seen by `camera`.
  FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale, bool cull);

  // Model-only set-up (done on first use if not called): the vertices in the order faces first
  // use them, the faces taken in `faceOrder` (global face ids) when given, else in file order.
  // Nothing drawn depends on that order, but faces read their vertices by it: in first-use
  // order consecutive faces find theirs in cache (scanned models such as the bunny list
  // vertices in an order unrelated to their faces).
  // With `batches` too (ascending offsets into faceOrder, first 0, last its size): batch b is
  // faces (*faceOrder)[batches[b], batches[b + 1]), for transformBatch().
  void prepare(const std::vector<uint32_t>* faceOrder = nullptr,
               const std::vector<uint32_t>* batches = nullptr);

  // Takes the frame's camera and forgets the vertices of the previous frame. The per-vertex
  // storage is kept from frame to frame: for a model of millions of vertices, allocating and
  // initialising it again per frame cost more than the lazy transform saves.
  void beginFrame(const Camera& camera);

  // Every face of every instance, in face id order (transformInstance() for each).
  void transformAll(FrameGeometry& out);

  // Every face of one instance, in face id order. The instance's vertices are computed first,
  // into arrays reused from instance to instance: they stay in cache while its faces read them
  // (for a grid, the whole model's would not).
  // An instance whose box (of the positions faces use) lies wholly beyond one plane of the
  // view volume, with margin, is only counted: every face of it would be clipped away.
  void transformInstance(uint32_t instance, FrameGeometry& out);

  // What the box of an instance's positions tells, for certain, about all its vertices in this
  // frame (after beginFrame()): whether they are all outside one and the same plane of the view
  // volume, and a window depth none of them is nearer than (0 when the box reaches the eye
  // plane).
  struct InstanceView {
    bool outside = false;
    float nearest = 0.0f;
    SampleRect area;  // with nearest > 0: the box's samples in the image, widened by 2
  };
  InstanceView viewOfInstance(uint32_t instance);

  // One face (global id); its vertices are transformed on first use in this frame, into
  // per-vertex state for the whole model. For callers that pick faces one at a time; the octree
  // uses transformBatch(), whose tests check it against this. Gives the same result as
  // transformAll() for that face.
  void transformFace(uint32_t faceId, FrameGeometry& out);

  // The faces of one batch of prepare(), in order, with the same result as transformFace() for
  // each. The batch computes its own vertices into a small local array, so faces find them in
  // cache whatever the size of the model; a vertex shared by two batches is computed twice.
  // For algorithms that draw a model in spatially compact groups (the octree's leaves).
  void transformBatch(uint32_t batch, FrameGeometry& out);

  // Asks the cache for the per-batch data transformBatch(batch) will read: a batch's arrays
  // lie at an unrelated place in memory from the previous one's.
  void prefetchBatch(uint32_t batch) const;

  // Asked about every triangle face inside near/far and the guard band (most faces) that
  // covers a sample centre, from now on; null for none. The filter must outlive its use.
  void setFilter(TriangleFilter* filter) { filter_ = filter; }

  const Mat4& modelViewProjection(uint32_t instance) const { return mvp_[instance]; }
  int sampleScale() const { return scale_; }

 private:
  // The vertices faces read: the whole model's or one instance's (numbered instance-major from
  // `firstInstance`: index = (instance - firstInstance) * slots + slot; `slot` and `instance`
  // null) or one batch's (local numbers, with their slot and instance).
  struct VertexView {
    VertexState* state;
    Vec3* window;
    const uint32_t* slot;
    const uint32_t* instance;
    uint32_t firstInstance;
  };

  void prepareBatches(const std::vector<uint32_t>& faceOrder, const std::vector<uint32_t>& batches);
  // Clip coordinates, recomputed for the rare faces that need clipping (VertexState keeps
  // only what the others read).
  Vec4 clipOf(size_t vertex) const;
  void computeVertex(const Mat4& mvp, const Vec3& position, size_t vertex);
  // The vertices of a face's corners in view_: the mesh's slots plus its instance's first
  // vertex, or a batch's local numbers (base 0).
  struct FaceCorners {
    const uint32_t* slots;
    uint32_t base;
    uint32_t operator[](uint32_t i) const { return base + slots[i]; }
  };
  void appendFace(uint32_t faceId, FaceCorners corners, uint32_t count, FrameGeometry& out);
  void appendFaceInline(uint32_t faceId, FaceCorners corners, uint32_t count, FrameGeometry& out);
  void appendTriangle(uint32_t faceId, FaceCorners corners, FrameGeometry& out);
  // appendTriangle() in two steps: the checks that need only the snapped corners (degenerate,
  // back face: counted; no sample centre covered: not counted, as no set-up ever counted it;
  // hidden tiles: counted; true when the face goes no further), then the rest.
  bool droppedBeforeDepths(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c,
                           int64_t area, FrameGeometry& out) const;
  void appendTriangleDepths(uint32_t faceId, FaceCorners corners, bool frontFacing,
                            FrameGeometry& out);
  void appendClippedFace(uint32_t faceId, FaceCorners corners, uint32_t count, uint64_t pieces,
                         FrameGeometry& out);
  void appendSnappedFace(uint32_t faceId, const DepthPlane& plane, uint64_t pieces,
                         FrameGeometry& out);
  DepthPlane planeOf(const Vec3* window, uint32_t count, bool& ok) const;

  const Scene& scene_;
  int width_ = 0, height_ = 0;  // pixels
  int scale_;
  VertexViewport viewport_;
  bool avx2_;  // vertices four at a time (projectVertices4Avx2)
  bool cull_;
  TriangleFilter* filter_ = nullptr;
  std::vector<Mat4> mvp_;  // per instance, model to clip space
  bool prepared_ = false;
  std::vector<Vec3> slotPositions_;    // model space: the positions faces use, by first use
  std::vector<uint32_t> cornerSlots_;  // per mesh corner: its position's slot
  std::vector<VertexState> state_;     // per vertex
  std::vector<Vec3> vertexWindow_;     // per vertex: pixels and depth (read by faces that survive)
  Box3 bounds_;                        // model space: box of slotPositions_
  uint64_t instanceTriangles_ = 0;     // per instance: triangles of its faces of 3+ corners
  uint64_t instanceDegenerate_ = 0;    // per instance: its faces of fewer than 3 corners
  HiddenTiles hiddenTiles_;            // what the filter marked for the instance being transformed
  std::vector<VertexState> instanceState_;  // transformInstance(): per slot, for one instance
  std::vector<Vec3> instanceWindow_;
  uint32_t frame_ = 0;
  VertexView view_{nullptr, nullptr, nullptr, nullptr, 0};
  // Batches (prepareBatches): per batch b, faces batchFaces_[batchFaceStart_[b], ...[b + 1]),
  // their vertices (slot and instance) from batchVertexStart_[b], and their corners' local
  // vertex numbers, face after face, from batchCornerStart_[b].
  std::vector<uint32_t> batchFaces_, batchFaceStart_, batchVertexStart_, batchCornerStart_;
  std::vector<uint32_t> batchVertexSlot_, batchVertexInstance_, batchCorners_;
  std::vector<uint8_t> batchFaceCorners_;  // per batch face: its corner count, 0 if > 255
  std::vector<VertexState> batchState_;    // the batch being transformed, by local number
  std::vector<Vec3> batchWindow_;
  // Scratch buffers reused face after face.
  std::vector<Vec4> faceClip_, clipped_, clipScratch_;
  std::vector<Vec3> window_, guarded_, guardScratch_;
  std::vector<FixedPoint> snapped_;
  std::vector<std::array<uint32_t, 3>> pieces_;
  std::vector<uint32_t> ring_;
};

}  // namespace zrender
