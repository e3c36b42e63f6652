#include "zrender/cli/RenderOutputs.hpp"

#include <cctype>
#include <cstdio>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/io/images/VideoContainer.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

bool isVideo(const fs::path& p) {
  const std::string ext = lowerExtension(p);
  return ext == ".mp4" || ext == ".avi";
}

// A turntable's -o pattern must hold exactly one integer directive (%d, %03d, ...) so that
// snprintf with one int argument is safe; "%%" stands for a literal percent sign.
void checkFramePattern(const std::string& pattern) {
  const InputError bad(
      "command line: -o: turntable frames need a pattern with one %d (like frames/%03d.png) or "
      "a .mp4/.avi file, got '" +
      pattern + "'");
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
    if (j >= pattern.size() || pattern[j] != 'd' || j - i > 4) throw bad;
    ++directives;
    i = j;
  }
  if (directives != 1) throw bad;
}

}  // namespace

fs::path RenderOutputs::colorOf(int frame) const {
  if (!turntable || video) return color;
  const std::string pattern = color.string();
  std::vector<char> buf(pattern.size() + 32);
  std::snprintf(buf.data(), buf.size(), pattern.c_str(), frame);
  return buf.data();
}

RenderOutputs planOutputs(const RenderOptions& options, const std::string& sceneName) {
  RenderOutputs o;
  o.turntable = options.turntable > 0;
  o.frames = o.turntable ? options.turntable : 1;
  o.color =
      options.output ? *options.output : fs::path(sceneName + (o.turntable ? "-%03d.png" : ".png"));
  o.video = o.turntable && isVideo(o.color);
  o.depth = options.depth;
  o.ids = options.ids;
  o.contactSheet = options.contactSheet;
  if (o.turntable && !o.video) checkFramePattern(o.color.string());
  if (!o.video) checkOutputExtension(o.color, colorExtensions(), "image");
  if (o.turntable && (o.depth || o.ids))
    throw InputError("command line: --depth and --ids write one image; not with --turntable");
  if (!o.turntable && o.contactSheet)
    throw InputError("command line: --contact-sheet needs --turntable");
  if (o.contactSheet) checkOutputExtension(*o.contactSheet, {".png"}, "image");
  if (o.depth) checkOutputExtension(*o.depth, {".tif", ".tiff", ".exr", ".png"}, "depth");
  if (o.ids) checkOutputExtension(*o.ids, {".png"}, "id image");

  std::vector<NamedOutput> named;
  for (int frame = 0; frame < (o.video ? 1 : o.frames); ++frame)
    named.push_back({"-o", o.colorOf(frame)});
  if (o.depth) named.push_back({"--depth", *o.depth});
  if (o.ids) named.push_back({"--ids", *o.ids});
  if (o.contactSheet) named.push_back({"--contact-sheet", *o.contactSheet});
  checkDistinctOutputs(named);
  return o;
}

void checkWritable(const RenderOutputs& o) {
  for (int frame = 0; frame < (o.video ? 1 : o.frames); ++frame) checkWritable(o.colorOf(frame));
  for (const auto& path : {o.depth, o.ids, o.contactSheet})
    if (path) checkWritable(*path);
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
