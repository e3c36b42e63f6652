// zrender-culling-bound SCENE... [--repeat N] [--leaf-faces N] [--settings FILE]: how fast exact
// culling could make each scene at best (CullingBound.hpp), as two Markdown tables on stdout: the
// z-buffer given only the visible faces, and the octree given only the leaves that hold one. A
// developer's measurement, run by hand; not part of `zrender` or of CI.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zrender/CommandLine.hpp"
#include "zrender/CullingBound.hpp"
#include "zrender/Error.hpp"
#include "zrender/ObjLoader.hpp"

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
    for (const std::string& name : scenes) {
      Warnings warnings;
      const SceneSettings s = resolveScene(name, settings, SceneOverrides(), warnings);
      auto mesh = std::make_shared<const Mesh>(loadObj(s.modelPath, warnings));
      const Scene scene = makeScene(s, mesh, warnings);
      for (const std::string& w : warnings)
        std::cerr << "zrender-culling-bound: warning: " << w << "\n";
      rows.push_back(Row{name, s.width, s.height,
                         measureCullingBound(scene, makeCamera(scene), repeat, leafFaces)});
    }
    char line[512];
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
  }
  return 0;
}
