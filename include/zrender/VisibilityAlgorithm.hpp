#pragma once

#include <memory>
#include <string>
#include <vector>

#include "zrender/Camera.hpp"
#include "zrender/FaceTransformer.hpp"
#include "zrender/FrameBuffer.hpp"
#include "zrender/FrameGeometry.hpp"
#include "zrender/RenderStats.hpp"
#include "zrender/Scene.hpp"

namespace zrender {

// What an algorithm gets for one frame.
struct FrameInput {
  const Scene& scene;
  const Camera& camera;
  FaceTransformer& transformer;
  // Every face transformed, in id order, when the algorithm asked for it (transformsAll());
  // otherwise empty and the algorithm calls transformer.transformFace() as it goes.
  FrameGeometry& geometry;
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
  // `fb` is sized to geometry's sample size but not cleared: clearing is part of the work.
  virtual void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) = 0;
};

// The names --alg accepts, in SPEC §1 order (only those implemented).
const std::vector<std::string>& algorithmNames();

// Throws InputError "unknown algorithm 'x' (choose from: zbuffer, ...)".
std::unique_ptr<VisibilityAlgorithm> makeAlgorithm(const std::string& name);

}  // namespace zrender
