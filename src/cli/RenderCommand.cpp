#include "zrender/cli/RenderCommand.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "zrender/base/Error.hpp"
#include "zrender/base/InOrderPipeline.hpp"
#include "zrender/base/SideBySide.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/io/Drawing.hpp"
#include "zrender/io/ImageCodecs.hpp"
#include "zrender/io/ImageOutput.hpp"
#include "zrender/io/OutputFile.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/VideoContainer.hpp"
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

bool isVideo(const fs::path& p) {
  const std::string ext = lowerExtension(p);
  return ext == ".mp4" || ext == ".avi";
}

// A turntable's -o pattern must hold exactly one integer directive (%d, %03d, ...) so that
// snprintf with one int argument is safe; "%%" stands for a literal percent sign.
void checkFramePattern(const std::string& pattern) {
  int directives = 0;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') ++j;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
    if (j >= pattern.size() || pattern[j] != 'd' || j - i > 4)
      throw InputError(
          "command line: -o: turntable frames need a pattern with one %d "
          "(like frames/%03d.png) or a .mp4/.avi file, got '" +
          pattern + "'");
    ++directives;
    i = j;
  }
  if (directives != 1)
    throw InputError(
        "command line: -o: turntable frames need a pattern with one %d (like "
        "frames/%03d.png) or a .mp4/.avi file, got '" +
        pattern + "'");
}

std::string framePath(const std::string& pattern, int frame) {
  std::vector<char> buf(pattern.size() + 32);
  std::snprintf(buf.data(), buf.size(), pattern.c_str(), frame);
  return buf.data();
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

}  // namespace

int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  const double start = nowMs();
  Warnings warnings;
  auto flushWarnings = [&] {
    for (const auto& w : warnings) err << "zrender: warning: " << messageLine(w) << "\n";
    warnings.clear();
  };

  // The loading's threads, then the frames': started at once, to be running when the loading's
  // first loop comes (the settings are read and the outputs checked meanwhile).
  const Threads threads(options.threads);
  const ThreadsStart threadsStart(threads);

  makeAlgorithm(options.algorithm);  // an unknown name fails before any loading
  SceneSettings settings =
      resolveScene(options.scene, options.settings, options.overrides, warnings);
  flushWarnings();

  // Check every output name before the work, so a typo costs nothing and writes nothing.
  const bool turntable = options.turntable > 0;
  const fs::path colorPath = options.output
                                 ? *options.output
                                 : fs::path(settings.name + (turntable ? "-%03d.png" : ".png"));
  if (turntable && !isVideo(colorPath)) checkFramePattern(colorPath.string());
  if (!turntable || !isVideo(colorPath))
    checkOutputExtension(colorPath, colorExtensions(), "image");
  if (turntable && (options.depth || options.ids))
    throw InputError("command line: --depth and --ids write one image; not with --turntable");
  if (!turntable && options.contactSheet)
    throw InputError("command line: --contact-sheet needs --turntable");
  if (options.contactSheet) checkOutputExtension(*options.contactSheet, {".png"}, "image");
  if (options.depth)
    checkOutputExtension(*options.depth, {".tif", ".tiff", ".exr", ".png"}, "depth");
  if (options.ids) checkOutputExtension(*options.ids, {".png"}, "id image");
  {
    std::vector<NamedOutput> outputs;
    if (turntable && !isVideo(colorPath)) {
      for (int frame = 0; frame < options.turntable; ++frame)
        outputs.push_back({"-o", framePath(colorPath.string(), frame)});
    } else {
      outputs.push_back({"-o", colorPath});
    }
    if (options.depth) outputs.push_back({"--depth", *options.depth});
    if (options.ids) outputs.push_back({"--ids", *options.ids});
    if (options.contactSheet) outputs.push_back({"--contact-sheet", *options.contactSheet});
    checkDistinctOutputs(outputs);
  }

  const double loadStart = nowMs();
  // A turntable with at least as many frames as threads renders whole frames at once, each on
  // one thread by a renderer of one thread, rather than one frame after another split over the
  // threads: no slower, and up to a fifth faster where a frame splits worst (measured:
  // docs/performance.md, Turntables on several threads).
  const int frames = turntable ? options.turntable : 1;
  const bool framesAtOnce = turntable && threads.parallel() && frames >= threads.count();
  const Scene scene = loadScene(settings, warnings, &threads);
  const double loadMs = nowMs() - loadStart;
  flushWarnings();

  // Every output is checked before the first frame, so that a run that fails writes nothing:
  // not the color image before a --depth that cannot be written, nor the first frames of a
  // turntable whose tenth is blocked. After the loading, whose errors are the common ones.
  if (turntable && !isVideo(colorPath)) {
    for (int frame = 0; frame < frames; ++frame)
      checkWritable(framePath(colorPath.string(), frame));
  } else {
    checkWritable(colorPath);
  }
  for (const auto& path : {options.depth, options.ids, options.contactSheet})
    if (path) checkWritable(*path);

  // Frames at once: one renderer per frame in flight, reused by the frames that follow (and
  // its buffers with them); each is built by its first frame, on that frame's thread, so that
  // their prepares (an octree each) run at once too.
  const size_t slots = framesAtOnce ? size_t(threads.count()) : 1;
  const int rendererThreads = framesAtOnce ? 1 : threads.count();
  std::vector<std::unique_ptr<Renderer>> renderers(slots);
  std::vector<FrameReport> reports(slots);
  const Camera baseCamera = makeCamera(scene);
  const bool tty = isatty(STDERR_FILENO);

  // Video frames go to an OutputFile renamed over the target at the end, once the container
  // is known to be finished: complete or not at all.
  std::unique_ptr<OutputFile> videoFile;
  std::unique_ptr<VideoFile> video;
  if (turntable && isVideo(colorPath)) {
    videoFile = std::make_unique<OutputFile>(colorPath);
    video = std::make_unique<VideoFile>(videoFile->pathForLibrary(), settings.width,
                                        settings.height, 30.0);
    if (!video->isOpen()) {
      const std::string full = videoFile->diskFullNote();
      videoFile->fail(full.empty() ? "cannot open a video writer for this format"
                                   : "cannot write file: the video writer could not start" + full);
    }
  }
  std::vector<cv::Mat> sheetFrames(options.contactSheet ? size_t(frames) : 0);

  // Renders a frame and writes its own files: on any thread, several frames at once.
  const auto render = [&](size_t frame, size_t slot) {
    if (!renderers[slot])
      renderers[slot] = std::make_unique<Renderer>(scene, options.algorithm, rendererThreads);
    Renderer& renderer = *renderers[slot];
    const Camera camera =
        turntable ? turntableCamera(baseCamera, 360.0 * frame / frames) : baseCamera;
    FrameReport& report = reports[slot];
    report = renderRepeated(renderer, camera, options.repeat);

    const double writeStart = nowMs();
    if (!video) {
      const fs::path path =
          turntable ? fs::path(framePath(colorPath.string(), int(frame))) : colorPath;
      writeImageAtomically(path, renderer.color(), &renderer.threadPool());
    }
    if (options.contactSheet) sheetFrames[frame] = renderer.color().clone();
    if (options.depth) {
      writeImageAtomically(*options.depth,
                           depthImage(renderer.buffer(), renderer.sampleScale(),
                                      lowerExtension(*options.depth) == ".png"),
                           &renderer.threadPool());
    }
    if (options.ids)
      writeImageAtomically(*options.ids, idImage(renderer.buffer(), renderer.sampleScale()),
                           &renderer.threadPool());
    report.writeMs = nowMs() - writeStart;
  };

  // What must come in frame order: the video, the JSON lines, the statistics, the progress.
  const auto finish = [&](size_t frame, size_t slot) {
    const Renderer& renderer = *renderers[slot];
    FrameReport& report = reports[slot];
    if (video) {
      const double writeStart = nowMs();
      video->write(renderer.color());
      report.writeMs += nowMs() - writeStart;
    }
    if (options.json) {
      Json::Value j(Json::objectValue);
      j["scene"] = settings.name;
      j["algorithm"] = renderer.algorithm().name();
      j["threads"] = threads.count();
      if (turntable) j["frame"] = Json::UInt64(frame);
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
      j["total_ms"] = nowMs() - start;
      j["peak_rss_mb"] = peakRssMb();
      j["stats"] = statsToJson(renderer.stats());
      out << toJsonLine(j) << "\n";
    }
    if (options.stats) printStats(renderer.stats(), report.medians, options.json ? err : out);
    if (turntable && tty) err << "\rzrender: frame " << (frame + 1) << "/" << frames << std::flush;
  };

  // One renderer on several threads: its buffers' pages are faulted in beside its prepare,
  // which runs on one thread, in parts that the threads share once it is done, instead of by
  // the first frame (docs/design.md, Threads).
  if (threads.parallel() && !framesAtOnce) {
    FrameMemory memory(settings.width, settings.height, settings.msaa);
    sideBySide(&threads, 1 + memory.parts(), [&](size_t job) {
      if (job == 0)
        renderers[0] = std::make_unique<Renderer>(scene, options.algorithm, rendererThreads);
      else
        memory.touchPart(job - 1);
    });
    renderers[0]->adoptMemory(std::move(memory));
  }
  pipelineInOrder(threads, size_t(frames), slots, render, finish);
  if (turntable && tty) err << "\r" << std::string(40, ' ') << "\r";

  if (video) {
    video->close();
    const std::string problem = videoContainerProblem(videoFile->pathForLibrary());
    if (!problem.empty())
      videoFile->fail("cannot write file: " + problem + videoFile->diskFullNote());
    videoFile->commit();
  }
  if (options.contactSheet)
    writeImageAtomically(*options.contactSheet, contactSheet(sheetFrames), &threads);
  return 0;
}

}  // namespace zrender
