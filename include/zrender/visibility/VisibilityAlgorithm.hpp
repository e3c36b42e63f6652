#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/transform/FaceTransformer.hpp"

namespace zrender {

// What an algorithm gets for one frame.
struct FrameInput {
  const Scene& scene;
  const Camera& camera;
  FaceTransformer& transformer;
  // Every face transformed, in id order, when the algorithm asked for it (transformsAll());
  // otherwise empty and the algorithm transforms faces as it goes (transformer.transformBatch()
  // or transformFace()), timing that in RenderStats::lazyTransformMs. After render(), the
  // renderer reads only geometry.faces (the shader's face colors); an algorithm may drop
  // triangles it has drawn (the octree does, leaf by leaf).
  FrameGeometry& geometry;
  // Called by algorithms that finish rows in order (top to bottom), with n when sample rows
  // [0, n) hold their final keys, so that they are shaded while still in cache instead of
  // read back from memory afterwards. Optional both ways: may be empty, and an algorithm need
  // not call it.
  std::function<void(int)> onRowsFinal = nullptr;

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
  // Work that depends on the model only, done once for all frames (timed as prepare_ms).
  virtual void prepare(const Scene& /*scene*/) {}
  // True when the renderer should transform every face before render() (timed as
  // transform_ms); false for algorithms that transform lazily.
  virtual bool transformsAll() const { return true; }
  // After prepare(): the order in which the algorithm usually transforms faces (global face
  // ids), for the transformer to lay vertices out by; null for face id order.
  virtual const std::vector<uint32_t>* faceOrder() const { return nullptr; }
  // With faceOrder(): the groups in which the algorithm transforms faces
  // (FaceTransformer::transformBatch), as offsets into faceOrder(); null for none.
  virtual const std::vector<uint32_t>* faceBatches() const { return nullptr; }
  // `fb` is sized to geometry's sample size but not cleared: clearing is part of the work.
  virtual void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) = 0;
};

// The names --alg accepts, in SPEC §1 order (only those implemented).
const std::vector<std::string>& algorithmNames();

// Throws InputError "unknown algorithm 'x' (choose from: zbuffer, ...)".
std::unique_ptr<VisibilityAlgorithm> makeAlgorithm(const std::string& name);

}  // namespace zrender
