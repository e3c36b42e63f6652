#include "zrender/cli/BenchCommand.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "zrender/base/Error.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/cli/bench/BenchChart.hpp"
#include "zrender/cli/bench/BenchComparison.hpp"
#include "zrender/cli/bench/BenchFormats.hpp"
#include "zrender/cli/bench/BenchHtml.hpp"
#include "zrender/cli/bench/BenchResults.hpp"
#include "zrender/cli/bench/MachineProbe.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

// The z-buffer, the reference every algorithm is compared with, then the others asked for.
std::vector<std::string> benchAlgorithms(const BenchOptions& options) {
  std::vector<std::string> algorithms = {"zbuffer"};
  for (const auto& a : options.algorithms.empty() ? algorithmNames() : options.algorithms) {
    makeAlgorithm(a);  // an unknown name fails before any work
    if (std::find(algorithms.begin(), algorithms.end(), a) == algorithms.end())
      algorithms.push_back(a);
  }
  return algorithms;
}

// The scenes given, else those of the settings file with "bench": true.
std::vector<std::string> benchScenes(const BenchOptions& options, Warnings& warnings,
                                     std::ostream& err) {
  if (!options.scenes.empty()) return options.scenes;
  const fs::path path = options.settings ? *options.settings : defaultSettingsPath();
  if (path.empty()) throw InputError("bench: no settings.json found and no scene given");
  std::vector<std::string> scenes;
  for (const auto& [name, scene] : loadSettings(path, warnings).scenes)
    if (scene.bench) scenes.push_back(name);
  printWarnings(warnings, err);
  if (scenes.empty())
    throw InputError(path.string() + ": no scene has \"bench\": true and no scene was given");
  return scenes;
}

// RFC 4648 base64 of `bytes`: the picture's data: URI. Neither OpenCV nor jsoncpp exposes an
// encoder, and a picture needs no decoder (the URI is kept as it is).
std::string base64(const std::vector<unsigned char>& bytes) {
  static constexpr char digits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t left = bytes.size() - i;
    const uint32_t v = uint32_t(bytes[i]) << 16 | (left > 1 ? uint32_t(bytes[i + 1]) << 8 : 0) |
                       (left > 2 ? uint32_t(bytes[i + 2]) : 0);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += left > 1 ? digits[(v >> 6) & 63] : '=';
    out += left > 2 ? digits[v & 63] : '=';
  }
  return out;
}

// The scene's frame for the HTML report: the z-buffer's color image, at most 480 pixels a side,
// as a JPEG data: URI; "" when the codec plugin cannot make one (the page says so).
std::string pictureUri(const cv::Mat& color) {
  const double scale = std::min(1.0, 480.0 / std::max(color.cols, color.rows));
  cv::Mat small;
  cv::resize(color, small,
             cv::Size(std::max(1, int(color.cols * scale)), std::max(1, int(color.rows * scale))),
             0, 0, cv::INTER_AREA);
  std::vector<unsigned char> bytes;
  std::string error;
  if (!encodeImage(".jpg", small, bytes, error)) return "";
  return "data:image/jpeg;base64," + base64(bytes);
}

BenchPicture scenePicture(const Scene& scene, const Renderer& zbuffer) {
  BenchPicture p;
  p.key = BenchKey{scene.settings.name,
                   "zbuffer",
                   shadingModeName(scene.settings.shading),
                   scene.settings.width,
                   scene.settings.height,
                   scene.settings.msaa};
  p.imageUri = pictureUri(zbuffer.color());
  return p;
}

// One scene's cells, an algorithm each. Every algorithm is prepared first, then the frames go
// round the algorithms, so that a burst of load on the machine falls on all of them alike
// rather than on one algorithm's frames, and the ratios of one run stay comparable. With more
// than one thread, each algorithm also renders on one, alternated the same way, for the
// speed-up and to check that its buffers do not depend on the threads. The warm-up frames
// (the first touches of the buffers, the caches) are rendered the same way and not timed. The
// machine-speed probe runs between frames (MachineProbe.hpp).
std::vector<BenchCell> benchScene(const Scene& scene, const std::vector<std::string>& algorithms,
                                  const BenchOptions& options, std::ostream& err, bool tty,
                                  std::vector<BenchPicture>* pictures) {
  const Camera camera = makeCamera(scene);
  const bool perThread = options.threads > 1;
  std::vector<std::unique_ptr<Renderer>> renderers, oneThread;
  for (const std::string& algorithm : algorithms) {
    renderers.push_back(std::make_unique<Renderer>(scene, algorithm, options.threads));
    if (perThread) oneThread.push_back(std::make_unique<Renderer>(scene, algorithm, 1));
  }
  const size_t n = algorithms.size();
  std::vector<std::vector<double>> transform(n), visibility(n), shade(n), raster(n), frame(n);
  std::vector<std::vector<double>> oneThreadFrame(n), probed(n);
  MachineProbe probe;
  double probeBefore = probe.runMs();
  for (int i = -options.warmup; i < options.repeat; ++i) {
    if (tty && i >= 0)
      err << "\rbench: " << scene.settings.name << " round " << (i + 1) << "/" << options.repeat
          << "   " << std::flush;
    for (size_t k = 0; k < n; ++k) {
      const FrameTimings t = renderers[k]->renderFrame(camera);
      const double one = perThread ? oneThread[k]->renderFrame(camera).frameMs() : 0;
      // The machine's speed during the frame: the faster of the probes just before and after
      // it (each probe is the one after a frame and the one before the next); a probe that
      // another process interrupted is slower, never faster.
      const double probeAfter = probe.runMs();
      const double probeMs = std::min(probeBefore, probeAfter);
      probeBefore = probeAfter;
      if (i < 0) continue;
      transform[k].push_back(t.transformMs);
      visibility[k].push_back(t.visibilityMs);
      shade[k].push_back(t.shadeMs);
      raster[k].push_back(t.rasterMs());
      frame[k].push_back(t.frameMs());
      probed[k].push_back(probeMs);
      if (perThread) oneThreadFrame[k].push_back(one);
    }
  }
  const Renderer& reference = *renderers[0];  // zbuffer
  if (pictures) pictures->push_back(scenePicture(scene, reference));
  std::vector<BenchCell> cells;
  for (size_t k = 0; k < n; ++k) {
    const Renderer& renderer = *renderers[k];
    BenchCell cell;
    cell.key.scene = scene.settings.name;
    cell.key.algorithm = algorithms[k];
    cell.key.width = scene.settings.width;
    cell.key.height = scene.settings.height;
    cell.key.msaa = scene.settings.msaa;
    cell.key.shading = shadingModeName(scene.settings.shading);
    cell.faces = scene.faceCount();
    cell.prepareMs = roundedMs(renderer.prepareMs());
    cell.transform = TimingSummary::of(transform[k]);
    cell.visibility = TimingSummary::of(visibility[k]);
    cell.shade = TimingSummary::of(shade[k]);
    cell.raster = TimingSummary::of(raster[k]);
    cell.frame = TimingSummary::of(frame[k]);
    cell.probe = TimingSummary::of(probed[k]);
    cell.stats = statsToJson(renderer.stats());
    if (k > 0)
      cell.identical = identicalFrames(renderer.buffer(), renderer.color(), reference.buffer(),
                                       reference.color());
    if (perThread) {
      cell.oneThreadFrame = TimingSummary::of(oneThreadFrame[k]);
      cell.identical =
          cell.identical && identicalFrames(renderer.buffer(), renderer.color(),
                                            oneThread[k]->buffer(), oneThread[k]->color());
    }
    cells.push_back(cell);
  }
  return cells;
}

// The outputs' names, checked before any work: a bench can run for minutes, so an output that
// cannot be written, or a baseline that cannot be read, fails before it starts.
std::optional<BenchRun> checkOutputs(const BenchOutputs& o) {
  if (o.chart) checkOutputExtension(*o.chart, {".png", ".svg"}, "chart");
  std::vector<NamedOutput> outputs;
  const bool markdownToStdout = o.markdown && *o.markdown == "-";
  if (o.markdown && !markdownToStdout) outputs.push_back({"--markdown", *o.markdown});
  if (o.json) outputs.push_back({"--json", *o.json});
  if (o.csv) outputs.push_back({"--csv", *o.csv});
  if (o.junit) outputs.push_back({"--junit", *o.junit});
  if (o.benchmarkAction) outputs.push_back({"--benchmark-action", *o.benchmarkAction});
  if (o.chart) outputs.push_back({"--chart", *o.chart});
  if (o.html) outputs.push_back({"--html", *o.html});
  checkDistinctOutputs(outputs);
  for (const NamedOutput& output : outputs) checkWritable(output.path);
  if (o.maxSlowdownPct && !o.baseline)
    throw InputError("command line: --max-slowdown needs --baseline");
  if (o.baseline) return readBenchRun(*o.baseline);
  return std::nullopt;
}

// The table on stdout and the files, then the one-line summary on stderr; the exit status.
int reportRun(const BenchRun& run, const std::optional<BenchRun>& baseline, const BenchOutputs& o,
              std::ostream& out, std::ostream& err) {
  std::optional<BenchComparison> comparison;
  if (baseline) comparison = compareRuns(run, *baseline, o.baseline->string(), o.maxSlowdownPct);
  const BenchComparison* cmp = comparison ? &*comparison : nullptr;
  const std::string markdown = benchMarkdown(run, cmp);
  out << markdown;
  if (o.markdown && *o.markdown != "-") appendFileAtomically(*o.markdown, markdown);
  if (o.json) writeFileAtomically(*o.json, benchRunText(run));
  if (o.csv) writeFileAtomically(*o.csv, benchCsv(run, cmp));
  if (o.junit) writeFileAtomically(*o.junit, benchJunit(run, cmp));
  if (o.benchmarkAction) writeFileAtomically(*o.benchmarkAction, benchActionJson(run));
  if (o.html) writeFileAtomically(*o.html, benchHtml(run, baseline ? &*baseline : nullptr, cmp));
  if (o.chart) {
    const ChartPicture chart = benchChart(run, cmp);
    if (lowerExtension(*o.chart) == ".svg")
      writeFileAtomically(*o.chart, chartSvg(chart));
    else
      writeImageAtomically(*o.chart, chartImage(chart));
  }

  std::vector<std::string> scenes, algorithms;
  for (const BenchCell& c : run.cells) {
    if (std::find(scenes.begin(), scenes.end(), c.key.scene) == scenes.end())
      scenes.push_back(c.key.scene);
    if (std::find(algorithms.begin(), algorithms.end(), c.key.algorithm) == algorithms.end())
      algorithms.push_back(c.key.algorithm);
  }
  const size_t disagreements = size_t(std::count_if(
      run.cells.begin(), run.cells.end(), [](const BenchCell& c) { return !c.identical; }));
  err << "bench: " << scenes.size() << " scene(s) x " << algorithms.size() << " algorithm(s): "
      << (disagreements ? std::to_string(disagreements) + " disagree with zbuffer"
                        : std::string("all identical to zbuffer"));
  if (cmp) {
    err << "; against " << cmp->baselineFile << ": " << cmp->count(Verdict::Slower) << " slower, "
        << cmp->count(Verdict::Faster) << " faster, " << cmp->count(Verdict::NoChange)
        << " no change";
    if (cmp->maxSlowdownPct)
      err << ", " << cmp->failures() << " slower beyond " << *cmp->maxSlowdownPct << "%";
  }
  err << "\n";
  if (disagreements) return kExitDisagree;
  if (cmp && cmp->failures()) return kExitCheckFailed;
  return kExitSuccess;
}

}  // namespace

int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  Warnings warnings;
  const std::vector<std::string> algorithms = benchAlgorithms(options);
  const std::optional<BenchRun> baseline = checkOutputs(options.outputs);
  const std::vector<std::string> scenes = benchScenes(options, warnings, err);

  BenchRun run = BenchRun::describingThisProcess();
  run.threads = options.threads;
  run.repeat = options.repeat;
  run.warmup = options.warmup;
  run.command = options.command;
  const bool tty = isatty(STDERR_FILENO);
  for (const std::string& sceneName : scenes) {
    const SceneSettings settings =
        resolveScene(sceneName, options.settings, options.overrides, warnings);
    const Scene scene = loadScene(settings, warnings);
    printWarnings(warnings, err);
    // The pictures are for the results file and the HTML page; made only when one is written,
    // since encoding one loads the codec plugin.
    const bool pictures = options.outputs.json || options.outputs.html;
    for (BenchCell& cell :
         benchScene(scene, algorithms, options, err, tty, pictures ? &run.pictures : nullptr))
      run.cells.push_back(std::move(cell));
  }
  if (tty) err << "\r" << std::string(60, ' ') << "\r";
  return reportRun(run, baseline, options.outputs, out, err);
}

int runBenchReport(const fs::path& results, const BenchOutputs& outputs, std::ostream& out,
                   std::ostream& err) {
  const std::optional<BenchRun> baseline = checkOutputs(outputs);
  const BenchRun run = readBenchRun(results);
  return reportRun(run, baseline, outputs, out, err);
}

}  // namespace zrender
