#include "zrender/io/ImageCodecs.hpp"

#include <png.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "zrender/base/Plugin.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/CodecPlugin.h"
#include "zrender/io/PngWriter.hpp"

namespace zrender {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

namespace {

// The plugin's entry points, resolved once on first use and never changed afterwards.
struct CodecPlugin {
  ZrenderImencodeFn imencode = nullptr;
  ZrenderImreadFn imread = nullptr;
  ZrenderVideoOpenFn videoOpen = nullptr;
  ZrenderVideoWriteFn videoWrite = nullptr;
  ZrenderVideoCloseFn videoClose = nullptr;
};

const CodecPlugin& codecPlugin() {
  static const CodecPlugin plugin = [] {
    // OpenCV reads its limit on an image's pixels when it is loaded; it checks each file's
    // header against it before allocating (docs/design.md, Limits).
    ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", std::to_string(kMaxImagePixels).c_str(), 1);
    std::string reason;
    void* handle = openPlugin("libzrender_codecs.so", reason);
    if (!handle)
      throw std::runtime_error("cannot load the image codec plugin libzrender_codecs.so: " +
                               reason);
    const auto symbol = [handle](const char* name) { return pluginSymbol(handle, name); };
    CodecPlugin p;
    p.imencode = reinterpret_cast<ZrenderImencodeFn>(symbol("zrenderImencode"));
    p.imread = reinterpret_cast<ZrenderImreadFn>(symbol("zrenderImread"));
    p.videoOpen = reinterpret_cast<ZrenderVideoOpenFn>(symbol("zrenderVideoOpen"));
    p.videoWrite = reinterpret_cast<ZrenderVideoWriteFn>(symbol("zrenderVideoWrite"));
    p.videoClose = reinterpret_cast<ZrenderVideoCloseFn>(symbol("zrenderVideoClose"));
    if (!p.imencode || !p.imread || !p.videoOpen || !p.videoWrite || !p.videoClose)
      throw std::runtime_error("the image codec plugin libzrender_codecs.so is incomplete");
    return p;
  }();
  return plugin;
}

cv::Mat readPng(const fs::path& path, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto failed = [&] {
    error = std::string("cannot be read as an image: ") + png.message;
    png_image_free(&png);
    return cv::Mat();
  };
  if (!png_image_begin_read_from_file(&png, path.c_str())) return failed();
  const size_t width = png.width, height = png.height;
  if (uint64_t(width) * height > kMaxImagePixels) {
    error = "is too large (" + std::to_string(width) + " x " + std::to_string(height) +
            " pixels, over " + std::to_string(kMaxImagePixels) + ")";
    png_image_free(&png);
    return cv::Mat();
  }
  cv::Mat bgr(int(height), int(width), CV_8UC3);
  if (!(png.format & PNG_FORMAT_FLAG_ALPHA)) {  // no alpha (nor tRNS): read as it is kept
    png.format = PNG_FORMAT_BGR;
    if (!png_image_finish_read(&png, nullptr, bgr.data, png_int_32(bgr.step), nullptr))
      return failed();
    return bgr;
  }
  // Read with its alpha, then the alpha dropped (not blended: what cv::imread gives).
  png.format = PNG_FORMAT_BGRA;
  std::vector<uint8_t> bgra(width * height * 4);
  if (!png_image_finish_read(&png, nullptr, bgra.data(), png_int_32(width * 4), nullptr))
    return failed();
  for (size_t y = 0; y < height; ++y) {
    const uint8_t* in = bgra.data() + y * width * 4;
    uint8_t* out = bgr.ptr(int(y));
    for (size_t x = 0; x < width; ++x) std::memcpy(out + 3 * x, in + 4 * x, 3);
  }
  return bgr;
}

}  // namespace

bool encodeImage(const std::string& extension, const cv::Mat& image,
                 std::vector<unsigned char>& bytes, std::string& error) {
  char message[512] = "";
  if (codecPlugin().imencode(extension.c_str(), &image, &bytes, message, sizeof message) == 0)
    return true;
  error = message;
  return false;
}

namespace {

cv::Mat decodeOrThrow(const fs::path& path, std::string& error) {
  // PNG files are recognised by their signature, whatever their name.
  unsigned char signature[8] = {};
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    error = "cannot be opened (it is a folder)";
    return {};
  }
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {  // said here: OpenCV would print a warning of its own on stderr
    error = std::string("cannot be opened: ") + std::strerror(errno);
    return {};
  }
  struct stat status {};
  if (::fstat(fileno(f), &status) != 0 || !S_ISREG(status.st_mode)) {
    std::fclose(f);
    error = "cannot be read (not a regular file)";  // a device or a pipe never ends
    return {};
  }
  const size_t n = std::fread(signature, 1, sizeof signature, f);
  std::fclose(f);
  if (n == sizeof signature && png_sig_cmp(signature, 0, sizeof signature) == 0)
    return readPng(path, error);
  cv::Mat out;
  char message[512] = "";
  if (codecPlugin().imread(path.c_str(), &out, message, sizeof message)) {
    error = message;
    return {};
  }
  return out;
}

}  // namespace

cv::Mat decodeColorImage(const fs::path& path, std::string& error) {
  try {
    return decodeOrThrow(path, error);
  } catch (const std::bad_alloc&) {
    error = "cannot be read: out of memory";
  } catch (const std::exception& e) {  // the codec plugin cannot be loaded
    error = std::string("cannot be read: ") + e.what();
  }
  return {};
}

VideoFile::VideoFile(const fs::path& path, int width, int height, double fps) {
  const bool mp4 = lowerExtension(path) == ".mp4";
  const auto fourcc = [](char a, char b, char c, char d) {
    return (a & 255) + ((b & 255) << 8) + ((c & 255) << 16) + ((d & 255) << 24);
  };
  handle_ = codecPlugin().videoOpen(path.c_str(),
                                    mp4 ? fourcc('m', 'p', '4', 'v') : fourcc('M', 'J', 'P', 'G'),
                                    fps, width, height);
}

VideoFile::~VideoFile() {
  close();
}

void VideoFile::write(const cv::Mat& frame) {
  if (handle_) codecPlugin().videoWrite(handle_, &frame);
}

void VideoFile::close() {
  if (handle_) codecPlugin().videoClose(handle_);
  handle_ = nullptr;
}

}  // namespace zrender
