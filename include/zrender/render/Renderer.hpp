#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/base/Clock.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/render/FrameMemory.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/shading/Shader.hpp"
#include "zrender/transform/FaceTransformer.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// Timings of one frame, milliseconds (docs/design.md, Timings and JSON).
struct FrameTimings {
  double transformMs = 0.0;   // vertices to window-space faces, culling, clipping
  double visibilityMs = 0.0;  // window-space faces to the key buffer: the algorithm's own work
  double shadeMs = 0.0;       // the key buffer to colors
  double rasterMs() const { return visibilityMs + shadeMs; }
  double frameMs() const { return transformMs + rasterMs(); }
};

// Renders frames of one scene with one algorithm: the transform (a FaceTransformer, which the
// algorithm pulls faces from), visibility, then shading. Model-only work (the algorithm's
// prepare and the transform's layout) happens once in the constructor; buffers are reused
// from frame to frame.
class Renderer {
 public:
  // Builds what the algorithm pulls from, given the transform and the algorithm's batches: a
  // GeometrySource between the two (measurements: one that leaves faces out). Its transformMs()
  // is the frame's transform time.
  using SourceWrapper =
      std::function<std::unique_ptr<GeometrySource>(GeometrySource& transform, FaceBatches)>;

  // `threads`: how many threads each frame may use (1: the calling thread alone).
  Renderer(const Scene& scene, const std::string& algorithm, int threads = 1);
  // With an algorithm object built by the caller (measurements: an octree of another leaf
  // size), and optionally a source between the transform and the algorithm.
  Renderer(const Scene& scene, std::unique_ptr<VisibilityAlgorithm> algorithm,
           const SourceWrapper& wrap = nullptr, int threads = 1);

  // Buffers made ahead (firstTouchedFrameMemory), for the frames to come: used as they are when
  // a frame has their size.
  void adoptMemory(FrameMemory&& memory) { memory_ = std::move(memory); }
  // Renders one frame; the results stay valid until the next call.
  FrameTimings renderFrame(const Camera& camera);

  double prepareMs() const { return prepareMs_; }
  int threads() const { return threads_.count(); }
  // The threads themselves, for work on the frame after it is rendered (encoding its image).
  const Threads& threadPool() const { return threads_; }
  int sampleScale() const { return sampleScale_; }
  const FrameBuffer& buffer() const { return memory_.buffer; }
  const cv::Mat& color() const { return memory_.color.image(); }
  const RenderStats& stats() const { return stats_; }
  // The faces the last frame transformed and kept (algorithms that cull early keep fewer);
  // their triangles only where the algorithm keeps them (not the octree: FrameInput).
  const FrameGeometry& geometry() const { return geometry_; }
  const VisibilityAlgorithm& algorithm() const { return *algorithm_; }

 private:
  const Scene& scene_;
  Threads threads_;
  std::unique_ptr<VisibilityAlgorithm> algorithm_;
  Shader shader_;
  ShadingFrame shading_;
  int sampleScale_;
  double prepareMs_ = 0.0;
  std::unique_ptr<FaceTransformer> transformer_;
  std::unique_ptr<GeometrySource> wrapper_;
  GeometrySource* source_ = nullptr;  // the wrapper, else the transformer
  FrameMemory memory_;
  FrameGeometry geometry_;
  std::vector<double> bandShadeMs_;  // per thread: shading inside the algorithm's tasks
  RenderStats stats_;
};

// Whether two images have the same size, type and pixels (padding between rows aside).
bool samePixels(const cv::Mat& a, const cv::Mat& b);

// Whether two frames agree bit for bit: keys (so depth and face ids) and colors. What
// `zrender bench` checks every algorithm against the z-buffer with.
bool identicalFrames(const FrameBuffer& a, const cv::Mat& colorA, const FrameBuffer& b,
                     const cv::Mat& colorB);

}  // namespace zrender
