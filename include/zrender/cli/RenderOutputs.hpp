#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/cli/NameTemplate.hpp"
#include "zrender/cli/RenderCommand.hpp"
#include "zrender/cli/ViewPlan.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageCodecs.hpp"

namespace zrender {

// The files of one view.
struct ViewFiles {
  std::filesystem::path color;  // none when the views make a video
  std::optional<std::filesystem::path> depth, ids, normals;
  // Each of them, with the option that names it.
  std::vector<NamedOutput> named() const;
};

// The files one render command writes, named and checked before any work (docs/design.md,
// Outputs and Views).
struct RenderOutputs {
  bool video = false;  // the views make one .mp4 or .avi, `color`
  NameTemplate color;
  std::optional<NameTemplate> depth, ids, normals;
  std::optional<std::filesystem::path> contactSheet, cameras;
  NameFields fields;  // the scene, algorithm and shading; the view is filled in per view

  ViewFiles filesOf(size_t view) const;
};

// The outputs of `options` for the views of `plan` of the scene `settings` (SCENE.png, or
// SCENE-{view:03}.png for several views, without -o): fields and extensions, {view} wherever
// several views write, options that exclude each other and two outputs at one file are checked;
// InputError.
RenderOutputs planOutputs(const RenderOptions& options, const ViewPlan& plan,
                          const SceneSettings& settings);

// Throws InputError unless every output of views `views` (and the run's own files) can be
// written (checkWritable): after the loading, whose errors are the common ones, and before the
// first frame, so that a run that fails writes nothing.
void checkWritable(const RenderOutputs& outputs, const std::vector<size_t>& views);

// A video of the views: frames added in order, written to an OutputFile that takes the
// target's place once the container is known to be finished (io/VideoContainer.hpp).
class VideoOutput {
 public:
  VideoOutput(const std::filesystem::path& path, int width, int height);
  void add(const cv::Mat& frame);  // 8-bit BGR
  void finish();                   // InputError when the video could not be finished

 private:
  OutputFile file_;
  VideoFile writer_;
};

}  // namespace zrender
