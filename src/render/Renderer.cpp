#include "zrender/render/Renderer.hpp"

#include <algorithm>

#include "zrender/transform/FaceTransformer.hpp"

namespace zrender {

bool identicalFrames(const FrameBuffer& a, const cv::Mat& colorA, const FrameBuffer& b,
                     const cv::Mat& colorB) {
  if (!(a == b) || colorA.size() != colorB.size() || colorA.type() != colorB.type()) return false;
  return cv::countNonZero(cv::Mat(colorA != colorB).reshape(1)) == 0;
}

Renderer::Renderer(const Scene& scene, const std::string& algorithm)
    : Renderer(scene, makeAlgorithm(algorithm)) {}

Renderer::Renderer(const Scene& scene, std::unique_ptr<VisibilityAlgorithm> algorithm)
    : scene_(scene),
      algorithm_(std::move(algorithm)),
      shader_(scene, scene.settings.shading),
      sampleScale_(scene.settings.msaa == 4 ? 2 : 1),
      transformer_(scene, sampleScale_, scene.settings.cull) {
  const double t0 = nowMs();
  algorithm_->prepare(scene);
  transformer_.prepare(algorithm_->faceOrder(), algorithm_->faceBatches());
  prepareMs_ = nowMs() - t0;
}

FrameTimings Renderer::renderFrame(const Camera& camera) {
  FrameTimings timings;
  stats_ = RenderStats();
  geometry_.clear();
  geometry_.width = camera.width * sampleScale_;
  geometry_.height = camera.height * sampleScale_;

  const double t0 = nowMs();
  transformer_.beginFrame(camera);
  if (algorithm_->transformsAll()) transformer_.transformAll(geometry_);
  const double t1 = nowMs();
  std::vector<ScreenTriangle>& triangles = geometry_.triangles;
  if (keepTriangle_)  // not timed: a measurement's own step (CullingBound)
    triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                   [this](const ScreenTriangle& t) { return !keepTriangle_(t); }),
                    triangles.end());
  const double t2 = nowMs();

  buffer_.resize(geometry_.width, geometry_.height);
  shader_.begin(buffer_, camera, sampleScale_, color_, &geometry_);
  FrameInput input{scene_, camera, transformer_, geometry_,
                   [this](int rows) { shader_.rowsFinal(rows); }};
  algorithm_->render(input, buffer_, stats_);
  shader_.finish();
  const double t3 = nowMs();

  // Lazy algorithms transform inside render(); book that time as transform.
  timings.transformMs = (t1 - t0) + stats_.lazyTransformMs;
  timings.rasterMs = (t3 - t2) - stats_.lazyTransformMs;
  stats_.trianglesBackfaceCulled = geometry_.counters.backfaceCulled;
  stats_.trianglesClippedAway = geometry_.counters.clippedAway;
  stats_.trianglesDegenerate = geometry_.counters.degenerate;
  return timings;
}

}  // namespace zrender
