#pragma once

// Image and video files. PNG, which every render writes, is encoded here (PngWriter), on
// several threads when given them; libpng reads it. The other formats and video go through
// OpenCV's imgcodecs and videoio, which live in a plugin (libzrender_codecs.so) loaded on first
// use (io/CodecPlugin.hpp): on Debian the plugin loads 244 shared libraries (GDAL, FFmpeg,
// GStreamer, ...), which cost a process far more than the render of the bunny (docs/design.md,
// Plugins).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace zrender {

class Threads;

// The extension of `path` in lower case (".png" for "X.PNG"); formats are chosen by it.
std::string lowerExtension(const std::filesystem::path& path);

// Encodes `image` (8-bit gray or BGR, 16-bit gray, or float for .tif/.exr) in memory in the
// format of `extension` (".jpg", ".tif", ...; PNG is PngWriter's). Returns false and sets
// `error` on failure.
bool encodeImage(const std::string& extension, const cv::Mat& image,
                 std::vector<unsigned char>& bytes, std::string& error);

// The most pixels an image read (a texture) may have: 16384 x 8192, 384 MiB as 8-bit BGR. The
// size in a file's header is checked against it before any pixel is allocated.
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 27;
// Sets OpenCV's own limit to kMaxImagePixels (OPENCV_IO_MAX_IMAGE_PIXELS); call before the first
// plugin that links OpenCV's imgcodecs is loaded, which reads it then.
void limitImageReads();

// Decodes an image file into 8-bit BGR. Returns an empty image and sets `error` (what follows
// the file's name: "is too large (...)", "cannot be opened: ...") on failure.
cv::Mat decodeColorImage(const std::filesystem::path& path, std::string& error);
// The same for an image file's bytes in memory (a texture embedded in a model file).
cv::Mat decodeColorImage(const std::vector<unsigned char>& bytes, std::string& error);
// Decodes an image file as the file keeps it: a 16-bit PNG as 16-bit, a float TIFF or OpenEXR
// as 32-bit float, gray as one channel (a depth image to compare, docs/design.md, Reference
// images). A 16-bit gray PNG is read by libpng, the rest by the codec plugin. Errors as
// decodeColorImage's.
cv::Mat decodeImageUnchanged(const std::filesystem::path& path, std::string& error);

// A video file being written (.mp4: MPEG-4 part 2, .avi: Motion JPEG), 8-bit BGR frames.
class VideoSink;

class VideoFile {
 public:
  // Throws std::runtime_error when the codec plugin cannot be loaded; check isOpen().
  VideoFile(const std::filesystem::path& path, int width, int height, double fps);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;
  bool isOpen() const { return sink_ != nullptr; }
  void write(const cv::Mat& frame);  // 8-bit BGR
  void close();                      // flushes and closes; the destructor does it too

 private:
  std::unique_ptr<VideoSink> sink_;
};

}  // namespace zrender
