#include "zrender/render/Renderer.hpp"

#include <cstring>

#include "zrender/transform/FaceTransformer.hpp"

namespace zrender {

bool samePixels(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  const size_t bytes = size_t(a.cols) * a.elemSize();
  for (int y = 0; y < a.rows; ++y)
    if (std::memcmp(a.ptr(y), b.ptr(y), bytes) != 0) return false;
  return true;
}

bool identicalFrames(const FrameBuffer& a, const cv::Mat& colorA, const FrameBuffer& b,
                     const cv::Mat& colorB) {
  return a == b && samePixels(colorA, colorB);
}

namespace {

// Rows the algorithm reports are shaded at once, while their keys are still in cache. That
// time is shading time, not the algorithm's; with several threads, each thread's share of it
// counts (docs/design.md, Timings and JSON).
class ShadingSink final : public RowSink {
 public:
  ShadingSink(Shader& shader, ShadingFrame& frame, const Threads& threads, double& shadeMs,
              std::vector<double>& threadShadeMs)
      : shader_(shader),
        frame_(frame),
        threads_(threads),
        shadeMs_(shadeMs),
        threadShadeMs_(threadShadeMs) {}

  void facesGathered(const FaceParts& faces) override {
    ScopedTimer shading(shadeMs_);
    shader_.facesGathered(frame_, faces);
  }
  void rowsDone(int first, int end) override {
    ScopedTimer shading(threads_.parallel() ? threadShadeMs_[size_t(threads_.slot())] : shadeMs_);
    shader_.rowsDone(frame_, first, end);
  }

 private:
  Shader& shader_;
  ShadingFrame& frame_;
  const Threads& threads_;
  double& shadeMs_;
  std::vector<double>& threadShadeMs_;
};

}  // namespace

Renderer::Renderer(const Scene& scene, const std::string& algorithm, int threads)
    : Renderer(scene, makeAlgorithm(algorithm), nullptr, threads) {}

Renderer::Renderer(const Scene& scene, std::unique_ptr<VisibilityAlgorithm> algorithm,
                   const SourceWrapper& wrap, int threads)
    : scene_(scene),
      threads_(threads),
      algorithm_(std::move(algorithm)),
      shader_(scene, scene.settings.shading),
      sampleScale_(sampleScaleOf(scene.settings.msaa)) {
  ScopedTimer timer(prepareMs_);
  const FaceBatches batches = algorithm_->prepare(scene);
  transformer_ =
      std::make_unique<FaceTransformer>(scene, sampleScale_, scene.settings.cull, batches);
  transformer_->setThreads(&threads_);
  bandShadeMs_.assign(size_t(threads_.count()), 0.0);
  source_ = transformer_.get();
  if (wrap) {
    wrapper_ = wrap(*transformer_, batches);
    source_ = wrapper_.get();
  }
}

FrameTimings Renderer::renderFrame(const Camera& camera) {
  stats_ = RenderStats();
  geometry_.clear();
  geometry_.width = camera.width * sampleScale_;
  geometry_.height = camera.height * sampleScale_;
  double frameMs = 0.0, shadeMs = 0.0;
  {
    ScopedTimer timer(frameMs);
    source_->beginFrame(camera);
    FrameBuffer& buffer = memory_.buffer;
    if (buffer.resize(geometry_.width, geometry_.height) && threads_.parallel()) {
      // New memory is zeroed by the kernel at its first write, a huge page (2 MiB) at a time:
      // written first in one contiguous part per thread, the pages are zeroed in parallel, not
      // one after another as the bands of the algorithms, a few rows each, would reach them.
      const size_t parts = size_t(threads_.count());
      threads_.forEach(parts, [&](size_t i) { buffer.clearPart(i, parts); });
    }
    memory_.color.resize(camera.width, camera.height);  // the shader writes every pixel
    {
      ScopedTimer shading(shadeMs);
      shader_.begin(shading_, buffer, camera, sampleScale_, memory_.color.image(),
                    algorithm_->gathersFaces(threads_.parallel()) ? &geometry_ : nullptr,
                    &threads_);
    }
    std::fill(bandShadeMs_.begin(), bandShadeMs_.end(), 0.0);
    ShadingSink sink(shader_, shading_, threads_, shadeMs, bandShadeMs_);
    FrameInput input{scene_, camera, *source_, geometry_, &threads_, &sink};
    algorithm_->render(input, buffer, stats_);
    ScopedTimer shading(shadeMs);
    shader_.finish(shading_);
  }
  for (double ms : bandShadeMs_) shadeMs += ms / threads_.count();
  FrameTimings timings;
  timings.transformMs = source_->transformMs();
  timings.shadeMs = shadeMs;
  timings.visibilityMs = frameMs - timings.transformMs - shadeMs;
  stats_.trianglesBackfaceCulled = geometry_.counters.backfaceCulled;
  stats_.trianglesClippedAway = geometry_.counters.clippedAway;
  stats_.trianglesDegenerate = geometry_.counters.degenerate;
  return timings;
}

}  // namespace zrender
