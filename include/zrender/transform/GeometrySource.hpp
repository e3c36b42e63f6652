#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/transform/InstanceView.hpp"

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
  // Before the faces of an instance, none of which has a sample nearer than window depth
  // `nearestDepth` (> 0), and whose samples lie in `area` (as far as rounding allows: a hint of
  // where to look, inside the image): the tiles where that bound is already hidden. A face
  // whose sample bounds lie in at most 2 x 2 of them is then dropped before its depths are
  // loaded (and counted in TransformCounters::filtered). Valid until the next call.
  virtual HiddenTiles beginInstance(float /*nearestDepth*/, const SampleRect& /*area*/) {
    return HiddenTiles();
  }
  // Then, for a triangle face still kept: `v`, its snapped corners (samples, either winding),
  // and `nearestDepth`, the least window depth of its corners exactly as the face's
  // DepthPlane::minDepth() will be. True drops the face. A transform on several threads asks
  // from all of them at once.
  virtual bool hidden(const FixedPoint* v, float nearestDepth, uint32_t faceId) = 0;
  // Whether hidden() is asked at all (false: only beginInstance()'s tiles drop faces, and the
  // transform spares each face the call and its nearest depth).
  virtual bool asksFaces() const { return true; }
};

// The groups of faces an algorithm pulls one at a time (FaceRequest::batch): batch b is the face
// ids (*faces)[(*starts)[b], (*starts)[b + 1]) (starts ascending, from 0 to faces->size()).
// Views of the algorithm's own arrays, valid while it lives; null: none.
struct FaceBatches {
  const std::vector<uint32_t>* faces = nullptr;
  const std::vector<uint32_t>* starts = nullptr;
  bool empty() const { return faces == nullptr || starts == nullptr; }
};

// The faces a pull asks for, in the grain the algorithm draws by: every face of the frame, those
// of one grid instance, or those of one of the batches its prepare() returned.
struct FaceRequest {
  enum class Scope : uint8_t { Frame, Instance, Batch };
  Scope scope = Scope::Frame;
  uint32_t index = 0;  // the instance or the batch
  // Instance only: triangle faces it proves hidden are left out (counted in
  // TransformCounters::filtered, or dropped uncounted by hidden()).
  TriangleFilter* filter = nullptr;

  static FaceRequest frame() { return FaceRequest(); }
  static FaceRequest instance(uint32_t k, TriangleFilter* filter = nullptr) {
    return FaceRequest{Scope::Instance, k, filter};
  }
  static FaceRequest batch(uint32_t b) { return FaceRequest{Scope::Batch, b, nullptr}; }
};

// Where a visibility algorithm gets the frame's faces in window space (docs/design.md, The
// transform), without knowing how they are computed. A face is pulled at most once a frame.
// The time spent in pulls is the frame's transform time.
class GeometrySource {
 public:
  virtual ~GeometrySource() = default;

  // Starts a frame seen by `camera`: what the previous frame computed is forgotten, and the
  // transform time starts again from 0.
  virtual void beginFrame(const Camera& camera) = 0;

  // Appends the faces `request` asks for to `out`, in face id order, with their triangles and
  // counters, and sets out.width and out.height (samples).
  //
  // With `parts` (Frame and Instance requests), the faces are left in parts instead, each a
  // geometry with indices of its own, in face id order part after part: `parts` is resized to
  // their number and each part cleared and filled, counters included; `out` gets only the
  // counters. For algorithms that read them on several threads: joining a big frame's parts is
  // a copy of all its triangles.
  //
  // A transform given several threads spreads a Frame or Instance pull over them, and takes
  // Batch pulls from all of them at once (each into its own `out`).
  virtual void pull(const FaceRequest& request, FrameGeometry& out,
                    std::vector<FrameGeometry>* parts = nullptr) = 0;
  // A hint: `request` comes soon (its data can be fetched into cache meanwhile).
  virtual void prefetch(const FaceRequest& /*request*/) const {}

  // What the box of an instance's positions tells about it in this frame (where it may be on
  // screen, its nearest depth), as an Instance pull sees it before its faces.
  virtual InstanceView viewOfInstance(uint32_t instance) const = 0;

  // Milliseconds spent in beginFrame() and the pulls since beginFrame().
  virtual double transformMs() const = 0;
};

}  // namespace zrender
