#pragma once

// Image and video files. PNG, which every render writes, is encoded here (PngWriter), on
// several threads when given them; libpng reads it. The other formats and video go through
// OpenCV's imgcodecs and videoio, which live in a plugin (libzrender_codecs.so) loaded on first
// use: on Debian those two libraries pull in about 200 shared libraries (GDAL, ffmpeg, ...)
// whose loading alone costs more CPU per process than the whole render of the bunny
// (docs/performance.md).

#include <filesystem>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

namespace zrender {

class Threads;

// The extension of `path` in lower case (".png" for "X.PNG"); formats are chosen by it.
std::string lowerExtension(const std::filesystem::path& path);

// Encodes `image` (CV_8UC1, CV_8UC3 BGR, CV_16UC1, or CV_32FC1 for .tif/.exr) into `path`, the
// format chosen by the extension; a PNG is deflated by `threads` when there are several (null:
// one). Returns false and sets `error` on failure.
bool encodeImageFile(const std::filesystem::path& path, const cv::Mat& image, std::string& error,
                     const Threads* threads = nullptr);

// Decodes an image file into CV_8UC3 (BGR). Returns an empty Mat and sets `error` on failure.
cv::Mat decodeColorImage(const std::filesystem::path& path, std::string& error);

// A video file being written (.mp4: MPEG-4 part 2, .avi: Motion JPEG), 8-bit BGR frames.
class VideoFile {
 public:
  // Throws std::runtime_error when the codec plugin cannot be loaded; check isOpen().
  VideoFile(const std::filesystem::path& path, int width, int height, double fps);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;
  bool isOpen() const { return handle_ != nullptr; }
  void write(const cv::Mat& frame);
  void close();  // flushes and closes; the destructor does it too

 private:
  void* handle_ = nullptr;
};

}  // namespace zrender
