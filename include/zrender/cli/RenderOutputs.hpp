#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <opencv2/core/mat.hpp>

#include "zrender/cli/RenderCommand.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageCodecs.hpp"

namespace zrender {

// The files one render command writes, named and checked before any work (docs/design.md,
// Outputs).
struct RenderOutputs {
  bool turntable = false;
  int frames = 1;               // the turntable's, else 1
  std::filesystem::path color;  // an image, a turntable's frame pattern, or a video
  bool video = false;           // `color` is a .mp4 or .avi
  std::optional<std::filesystem::path> depth, ids, contactSheet;

  // The color image of frame `frame`: `color`, or for a turntable's frames the pattern filled
  // in.
  std::filesystem::path colorOf(int frame) const;
};

// The outputs of `options` for the scene `sceneName` (SCENE.png or SCENE-%03d.png without -o):
// extensions, the frame pattern, options that exclude each other and two outputs at one file
// are checked; InputError.
RenderOutputs planOutputs(const RenderOptions& options, const std::string& sceneName);

// Throws InputError unless every output can be written (checkWritable): after the loading,
// whose errors are the common ones, and before the first frame, so that a run that fails
// writes nothing.
void checkWritable(const RenderOutputs& outputs);

// A turntable's video: frames added in order, written to an OutputFile that takes the target's
// place once the container is known to be finished (io/VideoContainer.hpp).
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
