// zrender-culling-bound SCENE... [--repeat N] [--leaf-faces N] [--settings FILE]: how fast exact
// culling could make each scene at best (CullingBound.hpp), as two Markdown tables on stdout: the
// z-buffer given only the visible faces, and the octree given only the leaves that hold one. A
// developer's measurement, run by hand; not part of `zrender` or of CI. With --rows it prints
// instead, for grid scenes, how much of each row the rows in front of it hide (RowOcclusion.hpp).
// --eye and --target move the camera as in zrender.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/cli/SceneResolution.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/measure/CullingBound.hpp"
#include "zrender/measure/RowOcclusion.hpp"

int main(int argc, char** argv) {
  using namespace zrender;
  CLI::App app(
      "The z-buffer given only the faces that end up visible: a lower bound for the "
      "raster time of exact culling.");
  std::vector<std::string> scenes;
  int repeat = 9;
  uint32_t leafFaces = Octree::kLeafFaces;
  std::optional<std::filesystem::path> settings;
  app.add_option("scene", scenes, "scenes of settings.json, or model files")->required();
  app.add_option("--repeat", repeat, "frames of each kind, alternated (median)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--leaf-faces", leafFaces,
                 "octree leaf size, faces (zrender: " + std::to_string(Octree::kLeafFaces) + ")")
      ->check(CLI::Range(1, 1 << 20));
  app.add_option("--settings", settings, "settings file (default: ./settings.json)");
  bool rowsOnly = false;
  app.add_flag("--rows", rowsOnly, "print how much of each grid row the rows in front hide");
  std::vector<double> eye, target;
  app.add_option("--eye", eye, "camera position")->delimiter(',')->expected(3);
  app.add_option("--target", target, "point looked at")->delimiter(',')->expected(3);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // bad input, as for zrender
  }
  try {
    struct Row {
      std::string name;
      int width, height;
      CullingBound bound;
    };
    std::vector<Row> rows;
    SceneOverrides overrides;
    if (!eye.empty()) overrides.eye = Vec3(eye[0], eye[1], eye[2]);
    if (!target.empty()) overrides.target = Vec3(target[0], target[1], target[2]);
    char line[512];
    for (const std::string& name : scenes) {
      Warnings warnings;
      const SceneSettings s = resolveScene(name, settings, overrides, warnings);
      const Scene scene = loadScene(s, warnings);
      for (const std::string& w : warnings)
        std::cerr << "zrender-culling-bound: warning: " << w << "\n";
      if (!rowsOnly) {
        rows.push_back(Row{name, s.width, s.height,
                           measureCullingBound(scene, makeCamera(scene), repeat, leafFaces)});
        continue;
      }
      const std::vector<RowOcclusion> occlusion = measureRowOcclusion(scene, makeCamera(scene));
      if (&name == &scenes.front())  // after the first scene loaded: no table for bad input
        std::cout << "| scene | row, nearest first | z offset | samples alone | samples visible "
                     "| hidden by the rows in front |\n|---|---:|---:|---:|---:|---:|\n";
      for (size_t r = 0; r < occlusion.size(); ++r) {
        const RowOcclusion& o = occlusion[r];
        std::snprintf(line, sizeof line, "| %s | %zu | %.3f | %zu | %zu | %.1f%% |\n", name.c_str(),
                      r + 1, o.offsetZ, o.samplesAlone, o.samplesVisible,
                      o.samplesAlone
                          ? 100.0 * (1.0 - double(o.samplesVisible) / double(o.samplesAlone))
                          : 0.0);
        std::cout << line;
      }
    }
    if (rowsOnly) return 0;
    std::cout << "| scene | size | triangles | visible faces (their triangles) "
                 "| zbuffer frame ms | zbuffer raster ms | visible faces only, raster ms "
                 "| raster bound | frame bound | identical |\n"
                 "|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const Row& r : rows) {
      const CullingBound& b = r.bound;
      std::snprintf(line, sizeof line,
                    "| %s | %dx%d | %zu | %zu (%zu) | %.2f | %.2f | %.2f | %.3fx | %.3fx | %s |\n",
                    r.name.c_str(), r.width, r.height, b.triangles, b.visibleFaces,
                    b.visibleTriangles, b.frameMs, b.rasterMs, b.visibleRasterMs,
                    b.visibleRasterMs / b.rasterMs, b.visibleRasterMs / b.frameMs,
                    b.identical ? "yes" : "NO");
      std::cout << line;
    }
    std::cout << "\nOctree leaves of at most " << leafFaces << " faces.\n";
    std::cout << "\n| scene | octree leaves drawn | leaves with a visible face | octree frame ms "
                 "| only those leaves: transform ms | raster ms | frame ms | octree / zbuffer "
                 "frame | leaf bound / zbuffer frame | identical |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    bool identical = true;
    for (const Row& r : rows) {
      const CullingBound& b = r.bound;
      std::snprintf(line, sizeof line,
                    "| %s | %zu | %zu | %.2f | %.2f | %.2f | %.2f | %.3fx | %.3fx | %s |\n",
                    r.name.c_str(), b.octreeLeavesDrawn, b.visibleLeaves, b.octreeFrameMs,
                    b.leafBoundTransformMs, b.leafBoundRasterMs, b.leafBoundFrameMs,
                    b.octreeFrameMs / b.frameMs, b.leafBoundFrameMs / b.frameMs,
                    b.leafBoundIdentical ? "yes" : "NO");
      std::cout << line;
      identical = identical && b.identical && b.leafBoundIdentical;
    }
    if (!identical) return 1;
  } catch (const InputError& e) {
    std::cerr << "zrender-culling-bound: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // out of memory, or a broken invariant: no abort
    std::cerr << "zrender-culling-bound: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
