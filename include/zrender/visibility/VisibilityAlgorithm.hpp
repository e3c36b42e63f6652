#pragma once

#include <functional>
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
  // Called by algorithms that finish rows in order (top to bottom), with n when sample rows
  // [0, n) hold their final keys, so that they are shaded while still in cache instead of
  // read back from memory afterwards. Optional both ways: may be empty, and an algorithm need
  // not call it.
  std::function<void(int)> onRowsFinal = nullptr;
  // The threads the algorithm may use (null: one). With more than one, it renders in
  // parallel however suits it, filling the same buffer as with one (docs/design.md, Threads),
  // and calls rowsReady() instead of rowsFinal(); rows it does not report are shaded after it.
  const Threads* threads = nullptr;
  // With several threads: sample rows [first, end) hold their final keys, so that they are
  // shaded by the thread that drew them while still in its cache. Any thread may call it; the
  // rows of different calls never overlap. May be empty. Rows are shaded then only if the
  // algorithm said before, from the thread that called render(), where the frame's faces are
  // (onFacesReady), so that their colors are prepared ahead.
  std::function<void(int, int)> onRowsReady = nullptr;
  // The argument: the parts that hold every face of the frame, valid until the frame's end
  // (empty: the faces are not gathered).
  std::function<void(const FaceParts&)> onFacesReady = nullptr;

  bool parallel() const { return threads != nullptr && threads->parallel(); }
  void rowsReady(int first, int end) const {
    if (onRowsReady) onRowsReady(first, end);
  }
  void facesReady(const FaceParts& parts) const {
    if (onFacesReady) onFacesReady(parts);
  }
  void rowsFinal(int rows) const {
    if (onRowsFinal) onRowsFinal(rows);
  }
  // For algorithms that finish one row at a time: reports rows 32 at a time (a call per row
  // would cost more than it saves).
  void rowFinished(int y) const {
    if (((y + 1) & 31) == 0) rowsFinal(y + 1);
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
  // the batches the algorithm pulls (GeometrySource::pullBatch), if any: views of its own
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
