#include "zrender/cli/CommandLine.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/cli/BenchCommand.hpp"
#include "zrender/cli/RenderCommand.hpp"
#include "zrender/cli/SceneResolution.hpp"
#include "zrender/cli/ViewCommand.hpp"
#include "zrender/io/models/ModelFormats.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

// More threads than any machine has: a typo rather than a request.
constexpr int kMaxThreads = 4096;

// "x,y,z" options land in a vector; converted after parsing.
struct VectorOptions {
  std::vector<double> eye, target, up, axis;
};

void addVector(CLI::App& app, const char* name, std::vector<double>& v, const char* help) {
  app.add_option(name, v, help)->delimiter(',')->expected(3)->type_name("X,Y,Z");
}

void addSceneOptions(CLI::App& app, SceneOverrides& o, VectorOptions& v,
                     std::optional<fs::path>& settings) {
  // The fallback, when there is one, is named: a user who did not name a settings file can
  // find the one that is read.
  const fs::path fallback = defaultSettingsPath();
  app.add_option("--settings", settings,
                 "settings file (default: ./settings.json" +
                     (fallback.empty() || fallback == "settings.json"
                          ? std::string(")")
                          : ", else " + fallback.string() + ", of the build tree)"));
  app.add_option("--width", o.width, "image width in pixels, 1..16384");
  app.add_option("--height", o.height, "image height in pixels, 1..16384");
  addVector(app, "--eye", v.eye, "camera position");
  addVector(app, "--target", v.target, "point looked at");
  addVector(app, "--up", v.up, "up direction");
  app.add_option("--fov", o.fov, "vertical field of view, degrees");
  app.add_option("--aspect", o.aspect, "aspect ratio (0: width/height)");
  app.add_option("--near", o.near, "near plane distance");
  app.add_option("--far", o.far, "far plane distance");
  app.add_option("--angle", o.angle, "model rotation, degrees");
  addVector(app, "--axis", v.axis, "model rotation axis");
  CLI::Option* fit = app.add_flag("--fit", o.fit, "frame the model automatically");
  app.add_flag("--no-fit", o.noFit, "a model file: no automatic framing (give --eye)")
      ->excludes(fit);
  app.add_option("--shading", o.shading, "normal flat phong random texture id depth");
  app.add_option("--msaa", o.msaa, "samples per pixel: 1 or 4");
  CLI::Option* noCull = app.add_flag("--no-cull", o.noCull, "draw back faces too");
  app.add_flag("--cull", o.cull, "cull back faces, whatever the scene says")->excludes(noCull);
}

void finishVectors(const VectorOptions& v, SceneOverrides& o) {
  auto set = [](const std::vector<double>& in, std::optional<Vec3>& out) {
    if (in.size() == 3) out = Vec3(in[0], in[1], in[2]);
  };
  set(v.eye, o.eye);
  set(v.target, o.target);
  set(v.up, o.up);
  set(v.axis, o.axis);
}

// Throws InputError naming `option` unless `name` is one of the algorithms.
void checkAlgorithm(const std::string& name, const char* option) {
  try {
    makeAlgorithm(name);
  } catch (const InputError& e) {
    throw InputError("command line: " + std::string(option) + ": " + e.what());
  }
}

// Parses argv into `app`'s options. False when help or the version was asked for (and
// printed); a bad option is an InputError.
// What --formats prints: a line per format, its extensions and what it holds.
std::string modelFormatsText() {
  std::string text = "zrender reads these model formats, chosen by the file's extension:\n";
  for (const ModelFormatInfo& info : modelFormats()) {
    std::string extensions;
    for (const char* e : info.extensions)
      extensions += (extensions.empty() ? "" : " ") + std::string(e);
    extensions.resize(std::max<size_t>(extensions.size(), 12), ' ');
    text += "  " + extensions + "  " + info.description + "\n";
  }
  return text;
}

// The exit statuses, as --help prints them (docs/bench.md, Exit statuses).
std::string exitStatusHelp() {
  return "\nExit status: 0 success, 1 internal error, 2 bad input, 3 a slowdown beyond\n"
         "--max-slowdown (or an image unlike --reference's), 4 algorithms disagree.";
}

// The files a bench run is written as, and the baseline it is compared with.
void addBenchOutputOptions(CLI::App& app, BenchOutputs& o) {
  app.add_option("--json", o.json, "write the results file (every sample; docs/bench.md)");
  app.add_option("--markdown", o.markdown, "append the table as markdown to FILE (- : stdout)");
  app.add_option("--csv", o.csv, "write a line per cell as CSV");
  app.add_option("--junit", o.junit, "write JUnit XML, a test case per cell");
  app.add_option("--benchmark-action", o.benchmarkAction,
                 "write github-action-benchmark's customSmallerIsBetter JSON");
  app.add_option("--chart", o.chart, "write a bar chart (.svg or .png)");
  app.add_option("--html", o.html, "write a self-contained HTML report (docs/bench.md)");
  app.add_option("--baseline", o.baseline, "compare with a results file (bench --json)");
  app.add_option("--max-slowdown", o.maxSlowdownPct,
                 "exit 3 when a cell is slower than the baseline by more than PCT percent, "
                 "significantly")
      ->check(CLI::Range(0.0, 1e6));
}

bool parseArguments(CLI::App& app, int argc, char** argv, std::ostream& out) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return false;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << '\n';
    return false;
  } catch (const CLI::Success&) {  // --formats, printed by its callback
    return false;
  } catch (const CLI::ParseError& e) {
    throw InputError("command line: " + messageLine(e.what()));
  }
  return true;
}

int parseAndRun(int argc, char** argv, std::ostream& out, std::ostream& err) {
  const bool bench = argc > 1 && std::strcmp(argv[1], "bench") == 0;
  VectorOptions vectors;
  if (bench) {
    CLI::App app{
        "Time every algorithm on every scene and check that they agree.\n" + exitStatusHelp(),
        "zrender bench"};
    BenchOptions options;
    std::string algs;
    app.add_option("scenes", options.scenes, "scenes (default: those with \"bench\": true)");
    app.add_option("--algs,--alg", algs, "comma-separated algorithms (default: all)");
    app.add_option("--repeat", options.repeat, "timed frames per measurement (median)")
        ->check(CLI::Range(1, 100000));
    app.add_option("--warmup", options.warmup, "untimed frames first (default 1)")
        ->check(CLI::Range(0, 100000));
    app.add_option("--threads", options.threads,
                   "threads per frame (default 1; more adds a speed-up column)")
        ->check(CLI::Range(1, kMaxThreads));
    addBenchOutputOptions(app, options.outputs);
    addSceneOptions(app, options.overrides, vectors, options.settings);
    if (!parseArguments(app, argc - 1, argv + 1, out)) return 0;
    finishVectors(vectors, options.overrides);
    size_t start = 0;
    while (!algs.empty() && start <= algs.size()) {
      const size_t comma = std::min(algs.find(',', start), algs.size());
      options.algorithms.push_back(algs.substr(start, comma - start));
      checkAlgorithm(options.algorithms.back(), "--algs");
      start = comma + 1;
    }
    options.command.assign(argv, argv + argc);
    return runBench(options, out, err);
  }

  if (argc > 1 && std::strcmp(argv[1], "bench-report") == 0) {
    CLI::App app{"Print and write a saved bench run (bench --json) again, without rendering.\n" +
                     exitStatusHelp(),
                 "zrender bench-report"};
    std::string results;
    BenchOutputs outputs;
    app.add_option("results", results, "a results file written by zrender bench --json")
        ->required();
    addBenchOutputOptions(app, outputs);
    if (!parseArguments(app, argc - 1, argv + 1, out)) return 0;
    return runBenchReport(results, outputs, out, err);
  }

  if (argc > 1 && std::strcmp(argv[1], "view") == 0) {
    CLI::App app{
        "Show the scene in a window as it renders, the camera orbiting the target.\n\n"
        "Keys:\n" +
            viewKeysHelp(),
        "zrender view"};
    ViewOptions options;
    std::string keys;
    app.add_option("scene", options.scene, "a scene of settings.json, or a model file")->required();
    app.add_option("-a,--alg", options.algorithm,
                   "the first algorithm: zbuffer scanline interval hierarchical octree");
    app.add_option("--keys", keys, "keys pressed one per frame (e.g. space,w,m,t,q)");
    app.add_option("--key-interval", options.keyInterval, "frames between two --keys keys")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--frames", options.frames, "stop after N frames")
        ->check(CLI::Range(1, 1000000000));
    app.add_option("--save-last", options.saveLast, "write the last frame, without the overlay");
    app.add_option("--contact-sheet", options.contactSheet,
                   "tile the frames shown at key presses and the last into one PNG");
    options.threads = hardwareThreads();
    app.add_option("--threads", options.threads, "threads per frame (default: the machine's)")
        ->check(CLI::Range(1, kMaxThreads));
    addSceneOptions(app, options.overrides, vectors, options.settings);
    if (!parseArguments(app, argc - 1, argv + 1, out)) return 0;
    finishVectors(vectors, options.overrides);
    checkAlgorithm(options.algorithm, "--alg");
    if (app.count("--keys")) options.keys = parseViewKeys(keys, "--keys");
    return runView(options, out, err);
  }

  CLI::App app{
      "zrender: render a scene with one of five hidden-surface algorithms.\n"
      "  zrender SCENE [options]\n  zrender bench [SCENE...] [options]\n"
      "  zrender bench-report RESULTS.json [options]\n"
      "  zrender view SCENE [options]\n" +
          exitStatusHelp(),
      "zrender"};
  RenderOptions options;
  app.set_version_flag("--version", "zrender " ZRENDER_VERSION);
  app.add_flag_callback(
      "--formats",
      [&out] {
        out << modelFormatsText();
        throw CLI::Success();
      },
      "list the model formats zrender reads");
  std::vector<std::string> scenes;
  app.add_option("scene", scenes,
                 "a scene of settings.json, or model files (several: one scene of them all)")
      ->required();
  app.add_option("-a,--alg", options.algorithm, "zbuffer scanline interval hierarchical octree");
  app.add_option("-o,--output", options.output,
                 "color image (.png .jpg .bmp .ppm .tif); names take {scene} {alg} {shading} "
                 "{view} {view:03}");
  app.add_option("--depth", options.depth, "depth image (.tif/.exr 32-bit float, .png 16-bit)");
  app.add_option("--ids", options.ids, "face-id image (.png)");
  app.add_option("--reference", options.reference,
                 "compare the color image with REF (exit 3 when it differs)")
      ->type_name("REF");
  app.add_option("--reference-depth", options.referenceDepth,
                 "compare the --depth image with REF (16-bit .png, float .tif/.exr)")
      ->type_name("REF");
  app.add_option("--reference-ids", options.referenceIds, "compare the --ids image with REF")
      ->type_name("REF");
  app.add_option("--reference-tolerance", options.referenceTolerance,
                 "pixels that may differ from a reference (default 0)")
      ->check(CLI::Range(0LL, 16384LL * 16384LL));  // the largest image's pixels
  app.add_option("--repeat", options.repeat, "render N times; timings are the median")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--json", options.json, "print one JSON object per image on stdout");
  app.add_flag("--stats", options.stats, "print the culling statistics");
  app.add_option("--normals", options.normals,
                 "view-space normals (.exr/.tif 32-bit float, .png 16-bit)");
  app.add_flag("-q,--quiet", options.quiet, "no summary line, warnings or progress on stderr");
  CLI::Option* turntable =
      app.add_option("--turntable", options.turntable, "N frames turning the model once")
          ->check(CLI::Range(1, 1000000));
  app.add_option("--orbit", options.orbit, "N views around the up axis")
      ->check(CLI::Range(1, 1000000))
      ->excludes(turntable);
  app.add_option("--orbit-elevations", options.orbitElevations,
                 "one ring of --orbit views per elevation, degrees")
      ->delimiter(',')
      ->type_name("A,B,...")
      ->check(CLI::Range(-1e6, 1e6));
  app.add_option("--azimuth", options.azimuth, "turn the eye about the up axis, degrees")
      ->check(CLI::Range(-1e6, 1e6));
  app.add_option("--elevation", options.elevation, "raise the eye toward the up axis, degrees")
      ->check(CLI::Range(-1e6, 1e6));
  app.add_option("--zoom", options.zoom, "magnify the view by F (the focal length times F)")
      ->check(CLI::Range(1e-6, 1e6));
  app.add_option("--frames", options.frames, "render views A to B-1 only")->type_name("A:B");
  app.add_option("--shard", options.shard, "render the I-th of N parts of the views (from 0)")
      ->type_name("I/N");
  app.add_flag("--skip-existing", options.skipExisting, "leave out views whose files all exist");
  app.add_option("--cameras", options.cameras,
                 "write every view's camera and files (transforms.json form)");
  app.add_flag("--cameras-only", options.camerasOnly, "write --cameras, render nothing");
  app.add_option("--progress", options.progress, "auto bar lines none (default auto)")
      ->check(CLI::IsMember({"auto", "bar", "lines", "none"}));
  app.add_option("--contact-sheet", options.contactSheet, "tile the views into one PNG");
  options.threads = hardwareThreads();
  app.add_option("--threads", options.threads,
                 "threads (default: the machine's); several views run at once")
      ->check(CLI::Range(1, kMaxThreads));
  addSceneOptions(app, options.overrides, vectors, options.settings);
  if (!parseArguments(app, argc, argv, out)) return 0;
  options.scene = scenes.front();
  options.moreModels.assign(scenes.begin() + 1, scenes.end());
  finishVectors(vectors, options.overrides);
  checkAlgorithm(options.algorithm, "--alg");
  return runRender(options, out, err);
}

}  // namespace

int runCommandLine(int argc, char** argv, std::ostream& out, std::ostream& err) {
  try {
    return parseAndRun(argc, argv, out, err);
  } catch (const InputError& e) {
    err << "zrender: error: " << messageLine(e.what()) << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    err << "zrender: error: out of memory\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    err << "zrender: internal error: " << messageLine(e.what()) << "\n";
    return kExitInternalError;
  }
}

}  // namespace zrender
