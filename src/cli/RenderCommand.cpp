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
#include "zrender/cli/CameraManifest.hpp"
#include "zrender/cli/Progress.hpp"
#include "zrender/cli/ReferenceCheck.hpp"
#include "zrender/cli/RenderOutputs.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/cli/ViewPlan.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/images/Drawing.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/render/FrameMemory.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/shading/NormalImage.hpp"

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

// One --json line: the frame's scene, sizes, counts, times and files (docs/design.md, Timings
// and JSON). `view` is given for runs of several views.
Json::Value frameJson(const Scene& scene, const Renderer& renderer, const FrameReport& report,
                      const RenderOptions& options, int threads, const size_t* view,
                      const ViewFiles& files, double loadMs, double startMs) {
  const SceneSettings& settings = scene.settings;
  Json::Value j(Json::objectValue);
  j["scene"] = settings.name;
  j["algorithm"] = renderer.algorithm().name();
  j["threads"] = threads;
  if (view) {
    j["view"] = Json::UInt64(*view);
    if (options.turntable > 0) j["frame"] = Json::UInt64(*view);
  }
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
  Json::Value written(Json::objectValue);
  if (!files.color.empty()) written["color"] = files.color.string();
  if (files.depth) written["depth"] = files.depth->string();
  if (files.ids) written["ids"] = files.ids->string();
  if (files.normals) written["normals"] = files.normals->string();
  j["files"] = written;
  return j;
}

// A view's own files: its color image (unless the views make a video), depth, ids, normals
// (by `normals`, given when the view has them). The images written are kept in `kept` when
// given, for the references to be compared with.
void writeViewFiles(const ViewFiles& files, const Camera& camera, const Renderer& renderer,
                    NormalImage* normals, RenderedImages* kept) {
  const Threads* threads = &renderer.threadPool();
  if (!files.color.empty()) writeImageAtomically(files.color, renderer.color(), threads);
  RenderedImages images;
  images.color = renderer.color();
  if (files.depth) {
    const bool sixteenBit = lowerExtension(*files.depth) == ".png";
    images.depth = depthImage(renderer.buffer(), renderer.sampleScale(), sixteenBit);
    writeImageAtomically(*files.depth, images.depth, threads);
  }
  if (files.ids) {
    images.ids = idImage(renderer.buffer(), renderer.sampleScale());
    writeImageAtomically(*files.ids, images.ids, threads);
  }
  if (kept) *kept = std::move(images);
  if (files.normals) {
    const cv::Mat image = normals->render(renderer.buffer(), camera, renderer.sampleScale());
    writeImageAtomically(*files.normals,
                         lowerExtension(*files.normals) == ".png" ? normalImage16(image) : image,
                         threads);
  }
}

// A line on stderr at most this often with --progress lines, milliseconds.
constexpr double kProgressIntervalMs = 5000.0;

// Whether every file of a view is there (--skip-existing): each is written whole or not at
// all, so one that exists is complete.
bool viewWritten(const ViewFiles& files) {
  std::error_code ec;
  for (const NamedOutput& n : files.named())
    if (!std::filesystem::is_regular_file(n.path, ec)) return false;
  return true;
}

// The names in a summary: the files of one view, or the patterns of several.
std::string outputNames(const RenderOutputs& outputs, bool multi, const ViewFiles& one) {
  std::vector<std::string> names;
  if (outputs.video || !multi) {
    if (outputs.video) names.push_back(outputs.color.pattern());
    for (const NamedOutput& n : one.named()) names.push_back(n.path.string());
  } else {
    names.push_back(outputs.color.pattern());
    for (const auto& t : {outputs.depth, outputs.ids, outputs.normals})
      if (t) names.push_back(t->pattern());
  }
  if (outputs.contactSheet) names.push_back(outputs.contactSheet->string());
  if (outputs.cameras) names.push_back(outputs.cameras->string());
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return text;
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
    normalImages.resize(renderers.size());
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
  // The normal images of the slot's frames, made by its first frame that writes one.
  NormalImage& normalImage(size_t slot) {
    if (!normalImages[slot]) normalImages[slot] = std::make_unique<NormalImage>(scene_);
    return *normalImages[slot];
  }

  std::vector<std::unique_ptr<Renderer>> renderers;
  std::vector<std::unique_ptr<NormalImage>> normalImages;
  std::vector<FrameReport> reports;

 private:
  const Scene& scene_;
  const std::string& algorithm_;
  const Threads& threads_;
  int rendererThreads_ = 1;
};

// The line a successful run ends with: what it wrote, the image, the algorithm and the frame
// time (docs/design.md, Views: what the terminal shows).
std::string summaryLine(const RenderOutputs& outputs, const ViewPlan& plan,
                        const std::vector<size_t>& views, size_t skipped,
                        const std::vector<double>& frameMs, const SceneSettings& settings,
                        double renderMs) {
  char text[160];
  std::string line = "zrender: ";
  if (views.empty()) {
    line += outputs.cameras ? "wrote " + outputs.cameras->string() : std::string("wrote nothing");
    std::snprintf(text, sizeof text, " (%zu views; %zu of views %zu-%zu already written)",
                  plan.views.size(), skipped, plan.first, plan.end - 1);
    return line + (skipped ? text : " (" + std::to_string(plan.views.size()) + " views)");
  }
  const bool multi = plan.multiView;
  if (multi) {
    std::snprintf(text, sizeof text, "wrote %zu view%s", views.size(),
                  views.size() == 1 ? "" : "s");
    line += text;
    if (!plan.whole() || skipped) {
      std::snprintf(text, sizeof text, " of %zu-%zu", plan.first, plan.end - 1);
      line += text;
    }
    if (skipped) line += " (" + std::to_string(skipped) + " already written)";
    line += " to ";
  } else {
    line += "wrote ";
  }
  line += outputNames(outputs, multi, outputs.filesOf(views.front()));
  std::snprintf(text, sizeof text, " (%dx%d, %s, ", settings.width, settings.height,
                outputs.fields.algorithm.c_str());
  line += text;
  if (multi) {
    std::snprintf(text, sizeof text, "frame %.1f ms median, %.1f views/s)", median(frameMs),
                  1000.0 * double(views.size()) / renderMs);
  } else {
    std::snprintf(text, sizeof text, "frame %.1f ms)", frameMs.front());
  }
  return line + text;
}

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
  if (options.quiet) warnings.clear();
  printWarnings(warnings, err);
  const ViewPlan plan = planViews(options, settings);
  const RenderOutputs outputs = planOutputs(options, plan, settings);
  // Before the loading: a missing reference is found at once, and nothing is written.
  const std::vector<ReferenceImage> references = readReferences(options, plan, outputs);
  const long long tolerance = options.referenceTolerance.value_or(0);

  const double loadStart = nowMs();
  const Scene scene = loadScene(settings, warnings, &threads);
  const double loadMs = nowMs() - loadStart;
  if (options.quiet) warnings.clear();
  printWarnings(warnings, err);

  // Every view's camera, so that a bad one fails before any frame and the manifest holds all.
  const Camera baseCamera = makeCamera(scene);
  std::vector<Camera> cameras;
  cameras.reserve(plan.views.size());
  for (size_t v = 0; v < plan.views.size(); ++v)
    cameras.push_back(viewCamera(scene, baseCamera, plan.views[v], plan.origins[v]));

  // This run's views: its part, less those already written with --skip-existing.
  std::vector<size_t> views;
  size_t skipped = 0;
  if (!options.camerasOnly) {
    for (size_t v = plan.first; v < plan.end; ++v) {
      if (options.skipExisting && viewWritten(outputs.filesOf(v)))
        ++skipped;
      else
        views.push_back(v);
    }
  }
  checkWritable(outputs, views);
  checkDiffsWritable(references);

  const bool multi = plan.multiView;
  FrameSlots slots(scene, options.algorithm, threads, int(views.size()));
  std::unique_ptr<VideoOutput> video;
  if (outputs.video && !views.empty())
    video = std::make_unique<VideoOutput>(outputs.color.pattern(), settings.width, settings.height);
  std::vector<cv::Mat> sheet(outputs.contactSheet ? views.size() : 0);
  std::vector<double> frameMs(views.size());
  Progress progress(err,
                    options.quiet
                        ? ProgressMode::None
                        : progressMode(options.progress, isatty(STDERR_FILENO), views.size()),
                    views.size(), kProgressIntervalMs, nowMs);
  // The references' comparisons, of the run's one view.
  RenderedImages kept;
  std::vector<ReferenceResult> referenceResults;

  // Renders a view and writes its own files: on any thread, several views at once.
  const auto render = [&](size_t i, size_t slot) {
    Renderer& renderer = slots.renderer(slot);
    const Camera& camera = cameras[views[i]];
    FrameReport& report = slots.reports[slot];
    report = renderRepeated(renderer, camera, options.repeat);
    const double writeStart = nowMs();
    const ViewFiles files = outputs.filesOf(views[i]);
    writeViewFiles(files, camera, renderer, files.normals ? &slots.normalImage(slot) : nullptr,
                   references.empty() ? nullptr : &kept);
    if (outputs.contactSheet) sheet[i] = renderer.color().clone();
    report.writeMs = nowMs() - writeStart;
    if (!references.empty())
      referenceResults = compareReferences(references, kept, tolerance, &renderer.threadPool());
  };
  // What must come in view order: the video, the JSON lines, the statistics, the progress.
  const auto finish = [&](size_t i, size_t slot) {
    const Renderer& renderer = *slots.renderers[slot];
    FrameReport& report = slots.reports[slot];
    if (video) {
      const double writeStart = nowMs();
      video->add(renderer.color());
      report.writeMs += nowMs() - writeStart;
    }
    frameMs[i] = report.frameMs;
    if (options.json) {
      Json::Value j =
          frameJson(scene, renderer, report, options, threads.count(), multi ? &views[i] : nullptr,
                    outputs.filesOf(views[i]), loadMs, start);
      if (!references.empty()) j["reference"] = referenceJson(referenceResults, tolerance);
      out << toJsonLine(j) << "\n";
    }
    if (options.stats) printStats(renderer.stats(), report.medians, options.json ? err : out);
    progress.viewDone();
  };
  if (!views.empty()) slots.prepare();
  const double renderStart = nowMs();
  pipelineInOrder(threads, views.size(), slots.renderers.size(), render, finish);
  progress.finish();

  if (video) video->finish();
  if (outputs.contactSheet)
    writeImageAtomically(*outputs.contactSheet, contactSheet(sheet), &threads);
  if (outputs.cameras) {
    writeFileAtomically(*outputs.cameras, manifestText(cameraManifest(
                                              cameras, outputs, *outputs.cameras, settings.msaa)));
  }
  // A reference's line before the summary, which stays the last; -q keeps those that fail.
  bool referencesPassed = true;
  for (const ReferenceResult& result : referenceResults) {
    referencesPassed = referencesPassed && result.passed;
    if (!options.quiet || !result.passed) err << referenceLine(result);
  }
  if (!options.quiet)
    err << summaryLine(outputs, plan, views, skipped, frameMs, settings, nowMs() - renderStart)
        << "\n";
  return referencesPassed ? kExitSuccess : kExitCheckFailed;
}

}  // namespace zrender
