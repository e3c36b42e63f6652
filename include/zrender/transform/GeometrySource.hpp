#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/scene/Camera.hpp"

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

// Jobs of the caller's that a pull runs among its own tasks (GeometrySource::pullInstanceParts):
// run(j) for every j in [0, count), on any of the threads, at the same time as each other and as
// the pull's work after its TriangleFilter::beginInstance().
struct SideJobs {
  size_t count = 0;
  std::function<void(size_t)> run;
};

// The groups of faces an algorithm pulls one at a time (GeometrySource::pullBatch): batch b is
// the face ids (*faces)[(*starts)[b], (*starts)[b + 1]) (starts ascending, from 0 to
// faces->size()). Views of the algorithm's own arrays, valid while it lives; null: none.
struct FaceBatches {
  const std::vector<uint32_t>* faces = nullptr;
  const std::vector<uint32_t>* starts = nullptr;
  bool empty() const { return faces == nullptr || starts == nullptr; }
};

// Where a visibility algorithm gets the frame's faces in window space (docs/design.md, The
// transform): it pulls them in the grain it draws by, all at once, one grid instance at a
// time, or one of its batches at a time, without knowing how they are computed. Each pull
// appends faces and their triangles to `out` (and sets out.width and out.height, in samples);
// a face is pulled at most once a frame. The time spent in pulls is the frame's transform
// time.
class GeometrySource {
 public:
  virtual ~GeometrySource() = default;

  // Starts a frame seen by `camera`: what the previous frame computed is forgotten, and the
  // transform time starts again from 0.
  virtual void beginFrame(const Camera& camera) = 0;

  // Every face of every instance, in face id order.
  virtual void pullAll(FrameGeometry& out) = 0;
  // The same, but the faces may be left in parts (geometries with indices of their own, in
  // face id order part after part) rather than joined into `out`, which then gets only the
  // counters: joining a big frame's parts is a copy of all its triangles. For algorithms that
  // read them on several threads. By default one part, `out` itself after pullAll().
  virtual void pullAllParts(FrameGeometry& out, std::vector<const FrameGeometry*>& parts) {
    pullAll(out);
    parts.assign(1, &out);
  }
  // Every face of one grid instance, in face id order. With `filter`, triangle faces it proves
  // hidden are left out (counted in out.counters.filtered, or dropped uncounted by hidden()).
  virtual void pullInstance(uint32_t instance, FrameGeometry& out,
                            TriangleFilter* filter = nullptr) = 0;
  // The same, but the faces left in parts, as pullAllParts() leaves them, rather than appended
  // to one geometry: `parts` is resized to their number and each part cleared and filled, its
  // counters included. For algorithms that draw instance after instance on several threads,
  // which keep each instance's parts: the join would be a copy of every face, vertex and
  // triangle. `alongside` runs among the pull's tasks (the previous instance's drawing), and
  // its time is not transform time. By default one part, filled by pullInstance() after the
  // side jobs, one after another.
  virtual void pullInstanceParts(uint32_t instance, std::vector<FrameGeometry>& parts,
                                 TriangleFilter* filter, const SideJobs& alongside = SideJobs()) {
    for (size_t j = 0; j < alongside.count; ++j) alongside.run(j);
    parts.resize(1);
    parts[0].clear();
    pullInstance(instance, parts[0], filter);
  }
  // The faces of batch `batch` of the FaceBatches the algorithm's prepare() returned, in order.
  // A transform given several threads takes pulls of batches from all of them at once (each
  // into its own `out`), and counts their time divided by the threads' number.
  virtual void pullBatch(uint32_t batch, FrameGeometry& out) = 0;
  // A hint: batch `batch` comes soon (its data can be fetched into cache meanwhile).
  virtual void prefetchBatch(uint32_t /*batch*/) const {}

  // Milliseconds spent in beginFrame() and the pulls since beginFrame().
  virtual double transformMs() const = 0;
};

}  // namespace zrender
