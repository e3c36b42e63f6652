#include "zrender/cli/BenchCommand.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>

#include "zrender/base/Error.hpp"
#include "zrender/cli/BenchCommand.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/Drawing.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

struct BenchRow {
  std::string scene, algorithm;
  int width = 0, height = 0, msaa = 1;
  uint64_t faces = 0;
  double prepareMs = 0, transformMs = 0, visibilityMs = 0, shadeMs = 0, rasterMs = 0;
  double rasterMinMs = 0, frameMs = 0;
  double rasterSpeedup = 0, frameSpeedup = 0;
  int threads = 1;
  double oneThreadFrameMs = 0, threadSpeedup = 0;  // with more than one thread
  RenderStats stats;
  bool identical = true;  // to the z-buffer's, and to its own with one thread
};

std::string machineName() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) {
        std::string name = line.substr(colon + 1);
        name.erase(0, name.find_first_not_of(' '));
        return name + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores";
      }
    }
  }
  return "unknown machine";
}

std::string today() {
  char buf[32];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string markdownTable(const std::vector<BenchRow>& rows, int repeat, int threads) {
  std::ostringstream md;
  const bool perThread = threads > 1;
  md << "zrender bench: median of " << repeat << " frames, "
     << (perThread ? std::to_string(threads) + " threads" : std::string("one thread")) << ", "
     << machineName() << ", " << today() << "\n\n";
  md << "| scene | size | algorithm | visibility ms | raster ms | frame ms | raster speed-up | "
        "frame speed-up | "
     << (perThread ? "one thread: frame ms | speed-up over one thread | " : "")
     << "prepare ms | triangles culled by HZB | octree nodes culled | identical |\n";
  md << "|---|---|---|---:|---:|---:|---:|---:|" << (perThread ? "---:|---:|" : "")
     << "---:|---:|---:|---|\n";
  for (const BenchRow& r : rows) {
    md << "| " << r.scene << " | " << r.width << "x" << r.height << (r.msaa == 4 ? " MSAA4" : "")
       << " | " << r.algorithm << " | " << fixed(r.visibilityMs, 2) << " | " << fixed(r.rasterMs, 2)
       << " | " << fixed(r.frameMs, 2) << " | " << fixed(r.rasterSpeedup, 2) << "x | "
       << fixed(r.frameSpeedup, 2) << "x | ";
    if (perThread)
      md << fixed(r.oneThreadFrameMs, 2) << " | " << fixed(r.threadSpeedup, 2) << "x | ";
    md << fixed(r.prepareMs, 1) << " | " << r.stats.trianglesHzbCulled << " | "
       << r.stats.octreeNodesCulled << "/" << r.stats.octreeNodesVisited << " | "
       << (r.identical ? "yes" : "**NO**") << " |\n";
  }
  return md.str();
}

Json::Value rowToJson(const BenchRow& r) {
  Json::Value j(Json::objectValue);
  j["scene"] = r.scene;
  j["algorithm"] = r.algorithm;
  j["width"] = r.width;
  j["height"] = r.height;
  j["msaa"] = r.msaa;
  j["faces"] = Json::UInt64(r.faces);
  j["prepare_ms"] = r.prepareMs;
  j["transform_ms"] = r.transformMs;
  j["visibility_ms"] = r.visibilityMs;
  j["shade_ms"] = r.shadeMs;
  j["raster_ms"] = r.rasterMs;
  j["raster_ms_min"] = r.rasterMinMs;
  j["frame_ms"] = r.frameMs;
  j["raster_speedup"] = r.rasterSpeedup;
  j["frame_speedup"] = r.frameSpeedup;
  j["threads"] = r.threads;
  if (r.threads > 1) {
    j["one_thread_frame_ms"] = r.oneThreadFrameMs;
    j["thread_speedup"] = r.threadSpeedup;
  }
  j["identical"] = r.identical;
  j["stats"] = statsToJson(r.stats);
  return j;
}

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

// One scene's rows, an algorithm each. Every algorithm is prepared first, then the frames go
// round the algorithms, so that a burst of load on the machine falls on all of them alike
// rather than on one algorithm's frames, and the ratios of one run stay comparable. With more
// than one thread, each algorithm also renders on one, alternated the same way, for the
// speed-up and to check that its buffers do not depend on the threads.
std::vector<BenchRow> benchScene(const Scene& scene, const std::vector<std::string>& algorithms,
                                 const BenchOptions& options, std::ostream& err, bool tty) {
  const Camera camera = makeCamera(scene);
  const bool perThread = options.threads > 1;
  std::vector<std::unique_ptr<Renderer>> renderers, oneThread;
  for (const std::string& algorithm : algorithms) {
    renderers.push_back(std::make_unique<Renderer>(scene, algorithm, options.threads));
    if (perThread) oneThread.push_back(std::make_unique<Renderer>(scene, algorithm, 1));
  }
  const size_t n = algorithms.size();
  std::vector<std::vector<double>> transform(n), visibility(n), shade(n), raster(n), frame(n);
  std::vector<std::vector<double>> oneThreadFrame(n);
  for (int i = 0; i < options.repeat; ++i) {
    if (tty)
      err << "\rbench: " << scene.settings.name << " round " << (i + 1) << "/" << options.repeat
          << "   " << std::flush;
    for (size_t k = 0; k < n; ++k) {
      const FrameTimings t = renderers[k]->renderFrame(camera);
      transform[k].push_back(t.transformMs);
      visibility[k].push_back(t.visibilityMs);
      shade[k].push_back(t.shadeMs);
      raster[k].push_back(t.rasterMs());
      frame[k].push_back(t.frameMs());
      if (perThread) oneThreadFrame[k].push_back(oneThread[k]->renderFrame(camera).frameMs());
    }
  }
  const Renderer& reference = *renderers[0];  // zbuffer
  const double referenceRaster = median(raster[0]), referenceFrame = median(frame[0]);
  std::vector<BenchRow> rows;
  for (size_t k = 0; k < n; ++k) {
    const Renderer& renderer = *renderers[k];
    BenchRow row;
    row.scene = scene.settings.name;
    row.algorithm = algorithms[k];
    row.width = scene.settings.width;
    row.height = scene.settings.height;
    row.msaa = scene.settings.msaa;
    row.faces = scene.faceCount();
    row.prepareMs = renderer.prepareMs();
    row.transformMs = median(transform[k]);
    row.visibilityMs = median(visibility[k]);
    row.shadeMs = median(shade[k]);
    row.rasterMs = median(raster[k]);
    row.rasterMinMs = *std::min_element(raster[k].begin(), raster[k].end());
    row.frameMs = median(frame[k]);
    row.stats = renderer.stats();
    if (k > 0)
      row.identical = identicalFrames(renderer.buffer(), renderer.color(), reference.buffer(),
                                      reference.color());
    row.threads = options.threads;
    if (perThread) {
      row.oneThreadFrameMs = median(oneThreadFrame[k]);
      row.threadSpeedup = row.frameMs > 0 ? row.oneThreadFrameMs / row.frameMs : 0;
      row.identical =
          row.identical && identicalFrames(renderer.buffer(), renderer.color(),
                                           oneThread[k]->buffer(), oneThread[k]->color());
    }
    row.rasterSpeedup = row.rasterMs > 0 ? referenceRaster / row.rasterMs : 0;
    row.frameSpeedup = row.frameMs > 0 ? referenceFrame / row.frameMs : 0;
    rows.push_back(row);
  }
  return rows;
}

// --json FILE: the rows as a JSON array.
std::string rowsJson(const std::vector<BenchRow>& rows) {
  Json::Value all(Json::arrayValue);
  for (const BenchRow& r : rows) all.append(rowToJson(r));
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 3;
  builder["precisionType"] = "decimal";
  return Json::writeString(builder, all) + "\n";
}

// --chart FILE.png: a group of bars per scene, a bar per algorithm.
cv::Mat rowsChart(const std::vector<BenchRow>& rows) {
  std::vector<ChartGroup> groups;
  for (const BenchRow& r : rows) {
    if (groups.empty() || groups.back().caption.rfind(r.scene, 0) != 0)
      groups.push_back(ChartGroup{
          r.scene + " (" + std::to_string(r.width) + "x" + std::to_string(r.height) + ", frame ms)",
          {}});
    groups.back().bars.push_back(ChartBar{r.algorithm, r.frameMs, r.visibilityMs});
  }
  return drawBarChart("zrender bench: median frame ms (dark: the algorithm's own visibility ms)",
                      groups);
}

}  // namespace

int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  Warnings warnings;
  const std::vector<std::string> algorithms = benchAlgorithms(options);
  if (options.chart) checkOutputExtension(*options.chart, {".png"}, "chart");
  // A bench can run for minutes: an output that cannot be written fails before it starts.
  std::vector<NamedOutput> outputs;
  if (options.markdown) outputs.push_back({"--markdown", *options.markdown});
  if (options.json) outputs.push_back({"--json", *options.json});
  if (options.chart) outputs.push_back({"--chart", *options.chart});
  checkDistinctOutputs(outputs);
  for (const NamedOutput& output : outputs) checkWritable(output.path);
  const std::vector<std::string> scenes = benchScenes(options, warnings, err);

  const bool tty = isatty(STDERR_FILENO);
  std::vector<BenchRow> rows;
  for (const std::string& sceneName : scenes) {
    const SceneSettings settings =
        resolveScene(sceneName, options.settings, options.overrides, warnings);
    const Scene scene = loadScene(settings, warnings);
    printWarnings(warnings, err);
    for (const BenchRow& row : benchScene(scene, algorithms, options, err, tty))
      rows.push_back(row);
  }
  if (tty) err << "\r" << std::string(60, ' ') << "\r";

  const std::string table = markdownTable(rows, options.repeat, options.threads);
  out << table;
  if (options.markdown) writeFileAtomically(*options.markdown, table);
  if (options.json) writeFileAtomically(*options.json, rowsJson(rows));
  if (options.chart) writeImageAtomically(*options.chart, rowsChart(rows));
  const size_t disagreements = size_t(
      std::count_if(rows.begin(), rows.end(), [](const BenchRow& r) { return !r.identical; }));
  err << "bench: " << scenes.size() << " scene(s) x " << algorithms.size() << " algorithm(s): "
      << (disagreements ? std::to_string(disagreements) + " disagree with zbuffer"
                        : std::string("all identical to zbuffer"))
      << "\n";
  return disagreements ? 1 : 0;
}

}  // namespace zrender
