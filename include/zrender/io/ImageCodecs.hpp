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

#include "zrender/base/Image.hpp"

namespace zrender {

class Threads;

// The extension of `path` in lower case (".png" for "X.PNG"); formats are chosen by it.
std::string lowerExtension(const std::filesystem::path& path);

// Encodes `image` (8-bit gray or BGR, 16-bit gray, or float for .tif/.exr) into `path`, the
// format chosen by the extension; a PNG is deflated by `threads` when there are several (null:
// one). Returns false and sets `error` on failure.
bool encodeImageFile(const std::filesystem::path& path, const Image& image, std::string& error,
                     const Threads* threads = nullptr);

// Decodes an image file into 8-bit BGR. Returns an empty image and sets `error` on failure.
Image decodeColorImage(const std::filesystem::path& path, std::string& error);

// A video file being written (.mp4: MPEG-4 part 2, .avi: Motion JPEG), 8-bit BGR frames.
class VideoFile {
 public:
  // Throws std::runtime_error when the codec plugin cannot be loaded; check isOpen().
  VideoFile(const std::filesystem::path& path, int width, int height, double fps);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;
  bool isOpen() const { return handle_ != nullptr; }
  void write(const Image& frame);  // 8-bit BGR
  void close();                    // flushes and closes; the destructor does it too

 private:
  void* handle_ = nullptr;
};

}  // namespace zrender
