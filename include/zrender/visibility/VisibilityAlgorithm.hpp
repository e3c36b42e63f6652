#pragma once

#include <memory>
#include <string>
#include <vector>

#include "zrender/base/Threads.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/transform/GeometrySource.hpp"

namespace zrender {

// Where an algorithm reports its progress through a frame, so that finished rows are shaded
// while their keys are still in cache instead of read back from memory afterwards
// (docs/design.md, The algorithms). An algorithm need not report anything: rows it does not report
// are shaded after it.
class RowSink {
 public:
  virtual ~RowSink() = default;
  // With several threads, from the thread that called render() and before rowsDone(): the
  // parts that hold every face that may be in the buffer (empty: the faces are not gathered),
  // so that their colors are prepared ahead. With several threads, rows are shaded early only
  // after this call.
  virtual void facesGathered(const FaceParts& faces) = 0;
  // Sample rows [first, end) hold their final keys. With one thread, top to bottom, each call's
  // `first` the previous one's `end` (from 0); with several, from any thread, the rows of
  // different calls never overlapping.
  virtual void rowsDone(int first, int end) = 0;
};

// What an algorithm gets for one frame.
struct FrameInput {
  const Scene& scene;
  const Camera& camera;
  // Where the algorithm pulls the frame's faces from, in the grain it draws by (all at once,
  // by instance, or by the batches its prepare() returned), into `geometry`. After render(),
  // the renderer reads only geometry.faces (the shader's face colors); an algorithm may drop
  // triangles it has drawn (the octree does, leaf by leaf).
  GeometrySource& source;
  FrameGeometry& geometry;
  // The threads the algorithm may use (null: one). With more than one, it renders in
  // parallel however suits it, filling the same buffer as with one (docs/design.md, Threads).
  const Threads* threads = nullptr;
  // Where finished rows go; null: nowhere.
  RowSink* rows = nullptr;

  bool parallel() const { return threads != nullptr && threads->parallel(); }
  void facesGathered(const FaceParts& parts) const {
    if (rows) rows->facesGathered(parts);
  }
  void rowsDone(int first, int end) const {
    if (rows) rows->rowsDone(first, end);
  }
  // For algorithms that finish one row at a time: with one thread, reports rows 32 at a time
  // (a call per row would cost more than it saves); with several, nothing (a band's rows are
  // reported when the band is done, and rows above it may not be).
  void rowFinished(int y) const {
    if (!parallel() && ((y + 1) & 31) == 0) rowsDone(y - 31, y + 1);
  }
};

// A hidden-surface algorithm: fills a FrameBuffer with the nearest (depth, id) key of every
// sample, following the rules of RasterRules.hpp exactly, so all implementations agree bit
// for bit.
class VisibilityAlgorithm {
 public:
  virtual ~VisibilityAlgorithm() = default;
  virtual std::string name() const = 0;
  // Work that depends on the model only, done once for all frames (timed as prepare_ms). Returns
  // the batches the algorithm pulls (FaceRequest::batch), if any: views of its own
  // arrays, valid while it lives.
  virtual FaceBatches prepare(const Scene& /*scene*/) { return FaceBatches(); }
  // `fb` is sized to geometry's sample size but not cleared: clearing is part of the work.
  virtual void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) = 0;
  // Whether input.geometry holds every face that may be in the buffer by the time rows are
  // shaded (the shader prepares only those faces' colors), when rendering on several threads
  // (`parallel`) or on one.
  virtual bool gathersFaces(bool /*parallel*/) const { return true; }
};

// The names --alg accepts, in the order of docs/design.md, The algorithms (only those implemented).
const std::vector<std::string>& algorithmNames();

// Throws InputError "unknown algorithm 'x' (choose from: zbuffer, ...)".
std::unique_ptr<VisibilityAlgorithm> makeAlgorithm(const std::string& name);

}  // namespace zrender
