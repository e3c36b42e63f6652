#include "zrender/io/ImageCodecs.hpp"

#include <png.h>

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

// Where the build put the plugin; the directory of the executable is searched first.
#ifndef ZRENDER_CODECS_PLUGIN
#define ZRENDER_CODECS_PLUGIN "libzrender_codecs.so"
#endif

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
  ZrenderImwriteFn imwrite = nullptr;
  ZrenderImreadFn imread = nullptr;
  ZrenderVideoOpenFn videoOpen = nullptr;
  ZrenderVideoWriteFn videoWrite = nullptr;
  ZrenderVideoCloseFn videoClose = nullptr;
};

const CodecPlugin& codecPlugin() {
  static const CodecPlugin plugin = [] {
    std::string reason;
    void* handle = openPlugin("libzrender_codecs.so", ZRENDER_CODECS_PLUGIN, reason);
    if (!handle)
      throw std::runtime_error("cannot load the image codec plugin libzrender_codecs.so: " +
                               reason);
    const auto symbol = [handle](const char* name) { return pluginSymbol(handle, name); };
    CodecPlugin p;
    p.imwrite = reinterpret_cast<ZrenderImwriteFn>(symbol("zrenderImwrite"));
    p.imread = reinterpret_cast<ZrenderImreadFn>(symbol("zrenderImread"));
    p.videoOpen = reinterpret_cast<ZrenderVideoOpenFn>(symbol("zrenderVideoOpen"));
    p.videoWrite = reinterpret_cast<ZrenderVideoWriteFn>(symbol("zrenderVideoWrite"));
    p.videoClose = reinterpret_cast<ZrenderVideoCloseFn>(symbol("zrenderVideoClose"));
    if (!p.imwrite || !p.imread || !p.videoOpen || !p.videoWrite || !p.videoClose)
      throw std::runtime_error("the image codec plugin libzrender_codecs.so is incomplete");
    return p;
  }();
  return plugin;
}

bool writePng(const fs::path& path, const Image& image, const Threads& threads,
              std::string& error) {
  if (!pngCanHold(image)) {
    error = image.empty() ? "PNG cannot hold an empty image" : "PNG cannot hold this image type";
    return false;
  }
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    error = "cannot write file";
    return false;
  }
  std::string reason;
  const bool ok = encodePng(file, image, threads, reason);
  const bool closed = std::fclose(file) == 0;
  if (!ok || !closed) {
    error = "cannot write file" + (reason.empty() ? std::string() : ": " + reason);
    return false;
  }
  return true;
}

Image readPng(const fs::path& path, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto failed = [&] {
    error = std::string("cannot be read as an image: ") + png.message;
    png_image_free(&png);
    return Image();
  };
  if (!png_image_begin_read_from_file(&png, path.c_str())) return failed();
  const size_t width = png.width, height = png.height;
  Image bgr(int(height), int(width), PixelFormat::kBgr8);
  if (!(png.format & PNG_FORMAT_FLAG_ALPHA)) {  // no alpha (nor tRNS): read as it is kept
    png.format = PNG_FORMAT_BGR;
    if (!png_image_finish_read(&png, nullptr, bgr.data(), png_int_32(bgr.step()), nullptr))
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
    uint8_t* out = bgr.row(int(y));
    for (size_t x = 0; x < width; ++x) std::memcpy(out + 3 * x, in + 4 * x, 3);
  }
  return bgr;
}

bool isPng(const fs::path& path) {
  return lowerExtension(path) == ".png";
}

}  // namespace

bool encodeImageFile(const fs::path& path, const Image& image, std::string& error,
                     const Threads* threads) {
  if (isPng(path)) {
    const Threads one;
    return writePng(path, image, threads ? *threads : one, error);
  }
  char message[512] = "";
  if (codecPlugin().imwrite(path.c_str(), &image, message, sizeof message) == 0) return true;
  error = message;
  return false;
}

Image decodeColorImage(const fs::path& path, std::string& error) {
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
  const size_t n = std::fread(signature, 1, sizeof signature, f);
  std::fclose(f);
  if (n == sizeof signature && png_sig_cmp(signature, 0, sizeof signature) == 0)
    return readPng(path, error);
  Image out;
  char message[512] = "";
  if (codecPlugin().imread(path.c_str(), &out, message, sizeof message)) {
    error = message;
    return {};
  }
  return out;
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

void VideoFile::write(const Image& frame) {
  if (handle_) codecPlugin().videoWrite(handle_, &frame);
}

void VideoFile::close() {
  if (handle_) codecPlugin().videoClose(handle_);
  handle_ = nullptr;
}

}  // namespace zrender
