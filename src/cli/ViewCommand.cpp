#include "zrender/cli/ViewCommand.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/base/Error.hpp"
#include "zrender/cli/Report.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/Drawing.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/view/ViewWindow.hpp"
#include "zrender/view/Viewer.hpp"

namespace zrender {

int runView(const ViewOptions& options, std::ostream& out, std::ostream& err) {
  Warnings warnings;
  // Outputs are checked before the window opens, so a typo costs nothing and writes nothing.
  const auto checkExtension = [](const std::filesystem::path& path,
                                 std::initializer_list<const char*> allowed, const char* option) {
    try {
      checkOutputExtension(path, allowed, "image");
    } catch (const InputError& e) {
      throw InputError("command line: " + std::string(option) + ": " + e.what());
    }
  };
  if (options.saveLast) checkExtension(*options.saveLast, colorExtensions(), "--save-last");
  if (options.contactSheet) checkExtension(*options.contactSheet, {".png"}, "--contact-sheet");

  SceneOverrides overrides = options.overrides;
  if (!overrides.width && !overrides.height) {
    // A window no bigger than most screens: the scene's size scaled down, aspect kept.
    Warnings ignored;
    const SceneSettings s = resolveScene(options.scene, options.settings, overrides, ignored);
    const double scale = std::min(1.0, double(kViewMaxSide) / std::max(s.width, s.height));
    overrides.width = std::max(1, int(std::lround(s.width * scale)));
    overrides.height = std::max(1, int(std::lround(s.height * scale)));
  }
  const SceneSettings settings = resolveScene(options.scene, options.settings, overrides, warnings);
  printWarnings(warnings, err);
  std::vector<NamedOutput> outputs;
  if (options.saveLast) outputs.push_back({"--save-last", *options.saveLast});
  if (options.contactSheet) outputs.push_back({"--contact-sheet", *options.contactSheet});
  checkDistinctOutputs(outputs);
  for (const NamedOutput& output : outputs) checkWritable(output.path);

  // Before the model loads: without a display the error comes at once.
  const std::unique_ptr<ViewWindow> window =
      openViewWindow("zrender view: " + settings.name, "view");
  const Scene scene = loadScene(settings, warnings);
  printWarnings(warnings, err);

  ViewerOptions viewer;
  viewer.scene = options.scene;
  viewer.settingsFile = options.settings;
  viewer.algorithm = options.algorithm;
  viewer.threads = options.threads;
  viewer.keys = options.keys;
  viewer.keyInterval = options.keyInterval;
  viewer.frames = options.frames;
  viewer.collectSheet = options.contactSheet.has_value();
  Viewer view(scene, viewer, out);
  view.run(*window);

  if (options.saveLast) writeImageAtomically(*options.saveLast, view.lastFrame());
  if (options.contactSheet) writeImageAtomically(*options.contactSheet, contactSheet(view.sheet()));
  out << "zrender view: " << view.framesShown() << " frames; the last one is "
      << view.lastFrameCommand() << std::endl;
  return 0;
}

}  // namespace zrender
