#include <filesystem>
#include <memory>

#include "zrender/Camera.hpp"
#include "zrender/CommandLine.hpp"
#include "zrender/Error.hpp"
#include "zrender/ImageOutput.hpp"
#include "zrender/ObjLoader.hpp"
#include "zrender/Renderer.hpp"
#include "zrender/Report.hpp"

namespace zrender {

namespace fs = std::filesystem;

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
  if (options.turntable > 0) throw InputError("command line: --turntable: not implemented yet");

  // Check every output name before the work, so a typo costs nothing and writes nothing.
  const fs::path colorPath = options.output ? *options.output : fs::path(settings.name + ".png");
  checkOutputExtension(colorPath, colorExtensions(), "image");
  if (options.depth)
    checkOutputExtension(*options.depth, {".tif", ".tiff", ".exr", ".png"}, "depth");
  if (options.ids) checkOutputExtension(*options.ids, {".png"}, "id image");

  const double loadStart = nowMs();
  auto mesh = std::make_shared<const Mesh>(loadObj(settings.modelPath, warnings));
  const Scene scene = makeScene(settings, mesh, warnings);
  const double loadMs = nowMs() - loadStart;
  flushWarnings();

  Renderer renderer(scene, options.algorithm);
  const Camera camera = makeCamera(scene);
  std::vector<double> transform, raster, frame;
  for (int i = 0; i < options.repeat; ++i) {
    const FrameTimings t = renderer.renderFrame(camera);
    transform.push_back(t.transformMs);
    raster.push_back(t.rasterMs);
    frame.push_back(t.frameMs());
  }

  const double writeStart = nowMs();
  writeImageAtomically(colorPath, renderer.color());
  if (options.depth) {
    const bool png = options.depth->extension() == ".png" || options.depth->extension() == ".PNG";
    writeImageAtomically(*options.depth,
                         depthImage(renderer.buffer(), renderer.sampleScale(), png));
  }
  if (options.ids)
    writeImageAtomically(*options.ids, idImage(renderer.buffer(), renderer.sampleScale()));
  const double writeMs = nowMs() - writeStart;

  if (options.json) {
    Json::Value j(Json::objectValue);
    j["scene"] = settings.name;
    j["algorithm"] = renderer.algorithm().name();
    j["width"] = settings.width;
    j["height"] = settings.height;
    j["msaa"] = settings.msaa;
    j["faces"] = Json::UInt64(scene.faceCount());
    j["triangles"] = Json::UInt64(triangleCount(scene));
    j["repeat"] = options.repeat;
    j["load_ms"] = loadMs;
    j["prepare_ms"] = renderer.prepareMs();
    j["transform_ms"] = median(transform);
    j["raster_ms"] = median(raster);
    j["raster_ms_min"] = *std::min_element(raster.begin(), raster.end());
    j["frame_ms"] = median(frame);
    j["frame_ms_min"] = *std::min_element(frame.begin(), frame.end());
    j["write_ms"] = writeMs;
    j["total_ms"] = nowMs() - start;
    j["peak_rss_mb"] = peakRssMb();
    j["stats"] = statsToJson(renderer.stats());
    out << toJsonLine(j) << "\n";
  }
  if (options.stats) printStats(renderer.stats(), options.json ? err : out);
  return 0;
}

}  // namespace zrender
