#include "zrender/cli/RenderCommand.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <memory>

#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/io/ContactSheet.hpp"
#include "zrender/io/ImageCodecs.hpp"
#include "zrender/io/ImageOutput.hpp"
#include "zrender/io/SceneFiles.hpp"
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

}  // namespace

int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  const double start = nowMs();
  Warnings warnings;
  auto flushWarnings = [&] {
    for (const auto& w : warnings) err << "zrender: warning: " << w << "\n";
    warnings.clear();
  };

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

  const double loadStart = nowMs();
  const Threads loadThreads(options.threads);
  const Scene scene = loadScene(settings, warnings, &loadThreads);
  const double loadMs = nowMs() - loadStart;
  flushWarnings();

  // Every output is checked before the first frame, so that a run that fails writes nothing:
  // not the color image before a --depth that cannot be written, nor the first frames of a
  // turntable whose tenth is blocked. After the loading, whose errors are the common ones.
  const int frames = turntable ? options.turntable : 1;
  if (turntable && !isVideo(colorPath)) {
    for (int frame = 0; frame < frames; ++frame)
      checkWritable(framePath(colorPath.string(), frame));
  } else {
    checkWritable(colorPath);
  }
  for (const auto& path : {options.depth, options.ids, options.contactSheet})
    if (path) checkWritable(*path);

  Renderer renderer(scene, options.algorithm, options.threads);
  const Camera baseCamera = makeCamera(scene);
  const bool tty = isatty(STDERR_FILENO);

  // Video frames go to a temporary file renamed at the end: complete or not at all.
  std::unique_ptr<VideoFile> video;
  fs::path videoTmp;
  struct RemoveOnExit {  // the temporary video, unless it was renamed into place
    fs::path& path;
    ~RemoveOnExit() {
      std::error_code ec;
      if (!path.empty()) fs::remove(path, ec);
    }
  } removeTmp{videoTmp};
  if (turntable && isVideo(colorPath)) {
    std::error_code ec;
    if (!colorPath.parent_path().empty()) fs::create_directories(colorPath.parent_path(), ec);
    videoTmp = pathBeside(colorPath, "tmp");
    video = std::make_unique<VideoFile>(videoTmp, settings.width, settings.height, 30.0);
    if (!video->isOpen())
      throw InputError(colorPath.string() + ": cannot open a video writer for this format");
  }
  std::vector<cv::Mat> sheetFrames;

  for (int frame = 0; frame < frames; ++frame) {
    const Camera camera =
        turntable ? turntableCamera(baseCamera, 360.0 * frame / frames) : baseCamera;
    if (turntable && tty) err << "\rzrender: frame " << (frame + 1) << "/" << frames << std::flush;
    std::vector<double> transform, visibility, shade, raster, total;
    for (int i = 0; i < options.repeat; ++i) {
      const FrameTimings t = renderer.renderFrame(camera);
      transform.push_back(t.transformMs);
      visibility.push_back(t.visibilityMs);
      shade.push_back(t.shadeMs);
      raster.push_back(t.rasterMs());
      total.push_back(t.frameMs());
    }
    FrameTimings medians;
    medians.transformMs = median(transform);
    medians.visibilityMs = median(visibility);
    medians.shadeMs = median(shade);

    const double writeStart = nowMs();
    if (video) {
      video->write(renderer.color());
    } else {
      const fs::path path = turntable ? fs::path(framePath(colorPath.string(), frame)) : colorPath;
      writeImageAtomically(path, renderer.color(), &renderer.threadPool());
    }
    if (options.contactSheet) sheetFrames.push_back(renderer.color().clone());
    if (options.depth) {
      writeImageAtomically(*options.depth,
                           depthImage(renderer.buffer(), renderer.sampleScale(),
                                      lowerExtension(*options.depth) == ".png"),
                           &renderer.threadPool());
    }
    if (options.ids)
      writeImageAtomically(*options.ids, idImage(renderer.buffer(), renderer.sampleScale()),
                           &renderer.threadPool());
    const double writeMs = nowMs() - writeStart;

    if (options.json) {
      Json::Value j(Json::objectValue);
      j["scene"] = settings.name;
      j["algorithm"] = renderer.algorithm().name();
      j["threads"] = renderer.threads();
      if (turntable) j["frame"] = frame;
      j["width"] = settings.width;
      j["height"] = settings.height;
      j["msaa"] = settings.msaa;
      j["faces"] = Json::UInt64(scene.faceCount());
      j["triangles"] = Json::UInt64(triangleCount(scene));
      j["repeat"] = options.repeat;
      j["load_ms"] = loadMs;
      j["prepare_ms"] = renderer.prepareMs();
      j["transform_ms"] = medians.transformMs;
      j["visibility_ms"] = medians.visibilityMs;
      j["shade_ms"] = medians.shadeMs;
      j["raster_ms"] = median(raster);
      j["raster_ms_min"] = *std::min_element(raster.begin(), raster.end());
      j["frame_ms"] = median(total);
      j["frame_ms_min"] = *std::min_element(total.begin(), total.end());
      j["write_ms"] = writeMs;
      j["total_ms"] = nowMs() - start;
      j["peak_rss_mb"] = peakRssMb();
      j["stats"] = statsToJson(renderer.stats());
      out << toJsonLine(j) << "\n";
    }
    if (options.stats) printStats(renderer.stats(), medians, options.json ? err : out);
  }
  if (turntable && tty) err << "\r" << std::string(40, ' ') << "\r";

  if (video) {
    video->close();
    std::error_code ec;
    fs::rename(videoTmp, colorPath, ec);
    if (ec) throw InputError(colorPath.string() + ": cannot write file: " + ec.message());
    videoTmp.clear();
  }
  if (options.contactSheet)
    writeImageAtomically(*options.contactSheet, contactSheet(sheetFrames), &renderer.threadPool());
  return 0;
}

}  // namespace zrender
