#include "zrender/cli/RenderOutputs.hpp"

#include <set>

#include "zrender/base/Error.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/io/images/VideoContainer.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

bool isVideo(const fs::path& p) {
  const std::string ext = lowerExtension(p);
  return ext == ".mp4" || ext == ".avi";
}

// Several views need {view} in a name that each view writes.
void checkViewField(const NameTemplate& name, const std::string& option, const char* example) {
  if (name.hasView()) return;
  throw InputError("command line: " + option + ": several views need {view} in the name (like " +
                   example + "), got '" + name.pattern() + "'");
}

}  // namespace

std::vector<NamedOutput> ViewFiles::named() const {
  std::vector<NamedOutput> out;
  if (!color.empty()) out.push_back({"-o", color});
  if (depth) out.push_back({"--depth", *depth});
  if (ids) out.push_back({"--ids", *ids});
  if (normals) out.push_back({"--normals", *normals});
  return out;
}

ViewFiles RenderOutputs::filesOf(size_t view) const {
  NameFields f = fields;
  f.view = view;
  ViewFiles files;
  if (!video) files.color = color.expand(f);
  if (depth) files.depth = depth->expand(f);
  if (ids) files.ids = ids->expand(f);
  if (normals) files.normals = normals->expand(f);
  return files;
}

RenderOutputs planOutputs(const RenderOptions& options, const ViewPlan& plan,
                          const SceneSettings& settings) {
  RenderOutputs o;
  const bool multi = plan.multiView;
  o.fields.scene = settings.name;
  o.fields.algorithm = options.algorithm;
  o.fields.shading = shadingModeName(settings.shading);
  const std::string color =
      options.output ? options.output->string() : (multi ? "{scene}-{view:03}.png" : "{scene}.png");
  o.color = NameTemplate(color, "-o", multi);
  o.video = multi && isVideo(o.color.pattern());
  if (options.depth) o.depth = NameTemplate(options.depth->string(), "--depth", multi);
  if (options.ids) o.ids = NameTemplate(options.ids->string(), "--ids", multi);
  if (options.normals) o.normals = NameTemplate(options.normals->string(), "--normals", multi);
  o.contactSheet = options.contactSheet;
  o.cameras = options.cameras;

  if (multi) {
    if (!o.video) checkViewField(o.color, "-o", "frames/{scene}-{view:03}.png, or a .mp4 file");
    if (o.depth) checkViewField(*o.depth, "--depth", "depth/{view:03}.exr");
    if (o.ids) checkViewField(*o.ids, "--ids", "ids/{view:03}.png");
    if (o.normals) checkViewField(*o.normals, "--normals", "normals/{view:03}.exr");
  }
  const bool part = !plan.whole() || options.skipExisting;
  if (o.video && part)
    throw InputError(
        "command line: a video holds every view: not with --frames, --shard or "
        "--skip-existing");
  if (!multi && o.contactSheet)
    throw InputError("command line: --contact-sheet needs several views (--orbit, --turntable)");
  if (o.contactSheet && part)
    throw InputError(
        "command line: --contact-sheet holds every view: not with --frames, "
        "--shard or --skip-existing");
  if (o.cameras && o.video)
    throw InputError("command line: --cameras names each view's image: not with a video");
  if (options.camerasOnly && !o.cameras)
    throw InputError("command line: --cameras-only needs --cameras FILE");

  const ViewFiles first = o.filesOf(0);
  if (!o.video) checkOutputExtension(first.color, colorExtensions(), "image");
  if (o.contactSheet) checkOutputExtension(*o.contactSheet, {".png"}, "image");
  if (first.depth) checkOutputExtension(*first.depth, {".tif", ".tiff", ".exr", ".png"}, "depth");
  if (first.ids) checkOutputExtension(*first.ids, {".png"}, "id image");
  if (first.normals)
    checkOutputExtension(*first.normals, {".exr", ".tif", ".tiff", ".png"}, "normals");
  if (o.cameras) checkOutputExtension(*o.cameras, {".json"}, "camera manifest");

  // Every view's, not only this part's: two parts of a run must not write one file either.
  std::vector<NamedOutput> named;
  if (o.video) named.push_back({"-o", o.color.pattern()});
  for (size_t view = 0; view < plan.views.size(); ++view) {
    for (const NamedOutput& n : o.filesOf(view).named()) named.push_back(n);
  }
  if (o.contactSheet) named.push_back({"--contact-sheet", *o.contactSheet});
  if (o.cameras) named.push_back({"--cameras", *o.cameras});
  checkDistinctOutputs(named);
  return o;
}

void checkWritable(const RenderOutputs& o, const std::vector<size_t>& views) {
  // One probe per folder (it makes the folder, as the writes will); a folder in a file's place
  // is refused for every file.
  std::set<fs::path> probed;
  const auto check = [&](const fs::path& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
      throw InputError(path.string() + ": cannot write file (a folder has that name)");
    if (probed.insert(fs::absolute(path, ec).parent_path()).second) checkWritable(path);
  };
  if (o.video) check(o.color.pattern());
  for (size_t view : views) {
    for (const NamedOutput& n : o.filesOf(view).named()) check(n.path);
  }
  for (const auto& path : {o.contactSheet, o.cameras})
    if (path) check(*path);
}

VideoOutput::VideoOutput(const fs::path& path, int width, int height)
    : file_(path), writer_(file_.pathForLibrary(), width, height, 30.0) {
  if (writer_.isOpen()) return;
  const std::string full = file_.diskFullNote();
  file_.fail(full.empty() ? "cannot open a video writer for this format"
                          : "cannot write file: the video writer could not start" + full);
}

void VideoOutput::add(const cv::Mat& frame) {
  writer_.write(frame);
}

void VideoOutput::finish() {
  writer_.close();
  const std::string problem = videoContainerProblem(file_.pathForLibrary());
  if (!problem.empty()) file_.fail("cannot write file: " + problem + file_.diskFullNote());
  file_.commit();
}

}  // namespace zrender
