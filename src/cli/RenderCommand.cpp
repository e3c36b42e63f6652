#include "zrender/cli/RenderCommand.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/base/InOrderPipeline.hpp"
#include "zrender/base/SideBySide.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/cli/RenderOutputs.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/images/Drawing.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/render/FrameMemory.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

// Peak resident set size of this process, MB.
double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// One frame's times, milliseconds: with --repeat, the medians (and least) of its renders.
struct FrameReport {
  FrameTimings medians;
  double rasterMs = 0.0, rasterMsMin = 0.0, frameMs = 0.0, frameMsMin = 0.0;
  double writeMs = 0.0;
};

// Renders the frame `repeat` times; the renderer holds the last render's results.
FrameReport renderRepeated(Renderer& renderer, const Camera& camera, int repeat) {
  std::vector<double> transform, visibility, shade, raster, total;
  for (int i = 0; i < repeat; ++i) {
    const FrameTimings t = renderer.renderFrame(camera);
    transform.push_back(t.transformMs);
    visibility.push_back(t.visibilityMs);
    shade.push_back(t.shadeMs);
    raster.push_back(t.rasterMs());
    total.push_back(t.frameMs());
  }
  FrameReport report;
  report.medians.transformMs = median(transform);
  report.medians.visibilityMs = median(visibility);
  report.medians.shadeMs = median(shade);
  report.rasterMs = median(raster);
  report.rasterMsMin = *std::min_element(raster.begin(), raster.end());
  report.frameMs = median(total);
  report.frameMsMin = *std::min_element(total.begin(), total.end());
  return report;
}

// One --json line: the frame's scene, sizes, counts and times (docs/design.md, Timings and JSON).
// `frame` is given for a turntable's frames only.
Json::Value frameJson(const Scene& scene, const Renderer& renderer, const FrameReport& report,
                      const RenderOptions& options, int threads, const size_t* frame, double loadMs,
                      double startMs) {
  const SceneSettings& settings = scene.settings;
  Json::Value j(Json::objectValue);
  j["scene"] = settings.name;
  j["algorithm"] = renderer.algorithm().name();
  j["threads"] = threads;
  if (frame) j["frame"] = Json::UInt64(*frame);
  j["width"] = settings.width;
  j["height"] = settings.height;
  j["msaa"] = settings.msaa;
  j["faces"] = Json::UInt64(scene.faceCount());
  j["triangles"] = Json::UInt64(triangleCount(scene));
  j["repeat"] = options.repeat;
  j["load_ms"] = loadMs;
  j["prepare_ms"] = renderer.prepareMs();
  j["transform_ms"] = report.medians.transformMs;
  j["visibility_ms"] = report.medians.visibilityMs;
  j["shade_ms"] = report.medians.shadeMs;
  j["raster_ms"] = report.rasterMs;
  j["raster_ms_min"] = report.rasterMsMin;
  j["frame_ms"] = report.frameMs;
  j["frame_ms_min"] = report.frameMsMin;
  j["write_ms"] = report.writeMs;
  j["total_ms"] = nowMs() - startMs;
  j["peak_rss_mb"] = peakRssMb();
  j["stats"] = statsToJson(renderer.stats());
  return j;
}

// A frame's own files: its color image (unless the frames make a video), depth and ids.
void writeFrameFiles(const RenderOutputs& outputs, const Renderer& renderer, int frame) {
  const Threads* threads = &renderer.threadPool();
  if (!outputs.video) writeImageAtomically(outputs.colorOf(frame), renderer.color(), threads);
  if (outputs.depth) {
    const bool sixteenBit = lowerExtension(*outputs.depth) == ".png";
    writeImageAtomically(
        *outputs.depth, depthImage(renderer.buffer(), renderer.sampleScale(), sixteenBit), threads);
  }
  if (outputs.ids)
    writeImageAtomically(*outputs.ids, idImage(renderer.buffer(), renderer.sampleScale()), threads);
}

// The renderers of a run, one per frame in flight. A turntable with at least as many frames as
// threads renders whole frames at once, each by a renderer of one thread, rather than one frame
// after another split over the threads: no slower, and up to a fifth faster where a frame splits
// worst (docs/performance.md, Turntables on several threads).
struct FrameSlots {
  FrameSlots(const Scene& scene, const std::string& algorithm, const Threads& threads, int frames)
      : scene_(scene), algorithm_(algorithm), threads_(threads) {
    const bool atOnce = frames > 1 && threads.parallel() && frames >= threads.count();
    rendererThreads_ = atOnce ? 1 : threads.count();
    renderers.resize(atOnce ? size_t(threads.count()) : 1);
    reports.resize(renderers.size());
  }
  // Before the first frame. One renderer on several threads: its buffers' pages are faulted
  // in beside its prepare, which runs on one thread, in parts that the threads share once it
  // is done, instead of by the first frame (docs/design.md, Threads). Frames at once: each
  // renderer is built by its first frame, on that frame's thread, so that their prepares run at
  // once too.
  void prepare() {
    if (!threads_.parallel() || renderers.size() > 1) return;
    const SceneSettings& s = scene_.settings;
    FrameMemory memory(s.width, s.height, s.msaa);
    sideBySide(&threads_, 1 + memory.parts(), [&](size_t job) {
      if (job == 0)
        renderers[0] = std::make_unique<Renderer>(scene_, algorithm_, rendererThreads_);
      else
        memory.touchPart(job - 1);
    });
    renderers[0]->adoptMemory(std::move(memory));
  }
  Renderer& renderer(size_t slot) {
    if (!renderers[slot])
      renderers[slot] = std::make_unique<Renderer>(scene_, algorithm_, rendererThreads_);
    return *renderers[slot];
  }

  std::vector<std::unique_ptr<Renderer>> renderers;
  std::vector<FrameReport> reports;

 private:
  const Scene& scene_;
  const std::string& algorithm_;
  const Threads& threads_;
  int rendererThreads_ = 1;
};

}  // namespace

int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  const double start = nowMs();
  Warnings warnings;
  // The loading's threads, then the frames': started at once, to be running when the loading's
  // first loop comes (the settings are read and the outputs named meanwhile).
  const Threads threads(options.threads);
  const ThreadsStart threadsStart(threads);
  makeAlgorithm(options.algorithm);  // an unknown name fails before any loading
  const SceneSettings settings = resolveScene(options.scene, options.settings, options.overrides,
                                              warnings, options.moreModels);
  printWarnings(warnings, err);
  const RenderOutputs outputs = planOutputs(options, settings.name);

  const double loadStart = nowMs();
  const Scene scene = loadScene(settings, warnings, &threads);
  const double loadMs = nowMs() - loadStart;
  printWarnings(warnings, err);
  checkWritable(outputs);

  FrameSlots slots(scene, options.algorithm, threads, outputs.frames);
  std::unique_ptr<VideoOutput> video;
  if (outputs.video)
    video = std::make_unique<VideoOutput>(outputs.color, settings.width, settings.height);
  std::vector<cv::Mat> sheet(outputs.contactSheet ? size_t(outputs.frames) : 0);
  const Camera baseCamera = makeCamera(scene);
  const bool progress = outputs.turntable && isatty(STDERR_FILENO);

  // Renders a frame and writes its own files: on any thread, several frames at once.
  const auto render = [&](size_t frame, size_t slot) {
    Renderer& renderer = slots.renderer(slot);
    const Camera camera = outputs.turntable
                              ? turntableCamera(baseCamera, 360.0 * frame / outputs.frames)
                              : baseCamera;
    FrameReport& report = slots.reports[slot];
    report = renderRepeated(renderer, camera, options.repeat);
    const double writeStart = nowMs();
    writeFrameFiles(outputs, renderer, int(frame));
    if (outputs.contactSheet) sheet[frame] = renderer.color().clone();
    report.writeMs = nowMs() - writeStart;
  };
  // What must come in frame order: the video, the JSON lines, the statistics, the progress.
  const auto finish = [&](size_t frame, size_t slot) {
    const Renderer& renderer = *slots.renderers[slot];
    FrameReport& report = slots.reports[slot];
    if (video) {
      const double writeStart = nowMs();
      video->add(renderer.color());
      report.writeMs += nowMs() - writeStart;
    }
    if (options.json) {
      out << toJsonLine(frameJson(scene, renderer, report, options, threads.count(),
                                  outputs.turntable ? &frame : nullptr, loadMs, start))
          << "\n";
    }
    if (options.stats) printStats(renderer.stats(), report.medians, options.json ? err : out);
    if (progress) err << "\rzrender: frame " << (frame + 1) << "/" << outputs.frames << std::flush;
  };
  slots.prepare();
  pipelineInOrder(threads, size_t(outputs.frames), slots.renderers.size(), render, finish);
  if (progress) err << "\r" << std::string(40, ' ') << "\r";

  if (video) video->finish();
  if (outputs.contactSheet)
    writeImageAtomically(*outputs.contactSheet, contactSheet(sheet), &threads);
  return 0;
}

}  // namespace zrender
