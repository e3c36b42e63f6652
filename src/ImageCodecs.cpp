#include "zrender/ImageCodecs.hpp"

#include <dlfcn.h>
#include <png.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "zrender/CodecPlugin.h"

// Where the build put the plugin; the directory of the executable is searched first.
#ifndef ZRENDER_CODECS_PLUGIN
#define ZRENDER_CODECS_PLUGIN "libzrender_codecs.so"
#endif

namespace zrender {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

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
    // Beside the executable first (build/zrender, build/libzrender_codecs.so), then the path
    // the build recorded.
    std::vector<std::string> candidates;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      candidates.push_back((exe.parent_path() / "libzrender_codecs.so").string());
      candidates.push_back((exe.parent_path().parent_path() / "libzrender_codecs.so").string());
    }
    candidates.push_back(ZRENDER_CODECS_PLUGIN);
    void* handle = nullptr;
    std::string reason;
    for (const std::string& c : candidates) {
      if (!fs::exists(c, ec)) continue;
      handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle) break;
      reason = dlerror();
    }
    if (!handle)
      throw std::runtime_error("cannot load the image codec plugin libzrender_codecs.so " + reason);
    CodecPlugin p;
    p.imwrite = reinterpret_cast<ZrenderImwriteFn>(dlsym(handle, "zrenderImwrite"));
    p.imread = reinterpret_cast<ZrenderImreadFn>(dlsym(handle, "zrenderImread"));
    p.videoOpen = reinterpret_cast<ZrenderVideoOpenFn>(dlsym(handle, "zrenderVideoOpen"));
    p.videoWrite = reinterpret_cast<ZrenderVideoWriteFn>(dlsym(handle, "zrenderVideoWrite"));
    p.videoClose = reinterpret_cast<ZrenderVideoCloseFn>(dlsym(handle, "zrenderVideoClose"));
    if (!p.imwrite || !p.imread || !p.videoOpen || !p.videoWrite || !p.videoClose)
      throw std::runtime_error("the image codec plugin libzrender_codecs.so is incomplete");
    return p;
  }();
  return plugin;
}

bool writePng(const fs::path& path, const cv::Mat& image, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.cols);
  png.height = png_uint_32(image.rows);
  png.flags = PNG_IMAGE_FLAG_FAST;  // zlib's fast setting: output size matters less than time
  png_int_32 stride = 0;            // in components
  switch (image.type()) {
    case CV_8UC3:
      png.format = PNG_FORMAT_BGR;
      stride = png_int_32(image.step / sizeof(uint8_t));
      break;
    case CV_8UC1:
      png.format = PNG_FORMAT_GRAY;
      stride = png_int_32(image.step / sizeof(uint8_t));
      break;
    case CV_16UC1:
      // 16-bit linear gray: the values are stored as they are.
      png.format = PNG_FORMAT_LINEAR_Y;
      stride = png_int_32(image.step / sizeof(uint16_t));
      break;
    default:
      error = "PNG cannot hold this image type";
      return false;
  }
  if (!png_image_write_to_file(&png, path.c_str(), 0, image.data, stride, nullptr)) {
    error = std::string("cannot write file: ") + png.message;
    png_image_free(&png);
    return false;
  }
  return true;
}

cv::Mat readPng(const fs::path& path, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    error = std::string("cannot be read as an image: ") + png.message;
    png_image_free(&png);
    return {};
  }
  png.format = PNG_FORMAT_BGRA;
  cv::Mat bgra(int(png.height), int(png.width), CV_8UC4);
  if (!png_image_finish_read(&png, nullptr, bgra.data, png_int_32(bgra.step), nullptr)) {
    error = std::string("cannot be read as an image: ") + png.message;
    png_image_free(&png);
    return {};
  }
  cv::Mat bgr;
  cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  return bgr;
}

bool isPng(const fs::path& path) {
  return lowerExtension(path) == ".png";
}

}  // namespace

bool encodeImageFile(const fs::path& path, const cv::Mat& image, std::string& error) {
  if (isPng(path)) return writePng(path, image, error);
  char message[512] = "";
  if (codecPlugin().imwrite(path.c_str(), &image, message, sizeof message) == 0) return true;
  error = message;
  return false;
}

cv::Mat decodeColorImage(const fs::path& path, std::string& error) {
  // PNG files are recognised by their signature, whatever their name.
  unsigned char signature[8] = {};
  if (FILE* f = std::fopen(path.c_str(), "rb")) {
    const size_t n = std::fread(signature, 1, sizeof signature, f);
    std::fclose(f);
    if (n == sizeof signature && png_sig_cmp(signature, 0, sizeof signature) == 0)
      return readPng(path, error);
  }
  cv::Mat out;
  char message[512] = "";
  if (codecPlugin().imread(path.c_str(), 1 /* IMREAD_COLOR */, &out, message, sizeof message))
    error = message;
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

void VideoFile::write(const cv::Mat& frame) {
  if (handle_) codecPlugin().videoWrite(handle_, &frame);
}

void VideoFile::close() {
  if (handle_) codecPlugin().videoClose(handle_);
  handle_ = nullptr;
}

}  // namespace zrender
