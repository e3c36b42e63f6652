#include "zrender/io/ImageCodecs.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "zrender/base/Plugin.hpp"
#include "zrender/io/CodecPlugin.h"

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

// libpng reports errors by longjmp back to the setjmp in writePngRows; the message is kept here.
void pngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<std::string*>(png_get_error_ptr(png));
  *error = message;
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

// The libpng calls of writePng, in a function with no C++ object alive across setjmp.
bool writePngRows(FILE* file, const cv::Mat& image, int bitDepth, int colorType,
                  std::string* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, pngError, pngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, png_uint_32(image.cols), png_uint_32(image.rows), bitDepth, colorType,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Speed over size: zlib level 1 without row filters (libpng would otherwise try all five
  // per row), the fastest and smallest of the level 1 variants measured (docs/performance.md).
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  if (colorType == PNG_COLOR_TYPE_RGB) png_set_bgr(png);  // OpenCV stores BGR
  if (bitDepth == 16) png_set_swap(png);                  // PNG is big-endian
  for (int y = 0; y < image.rows; ++y)
    png_write_row(png, const_cast<png_bytep>(image.ptr<png_byte>(y)));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

bool writePng(const fs::path& path, const cv::Mat& image, std::string& error) {
  int bitDepth = 8, colorType = PNG_COLOR_TYPE_RGB;
  switch (image.type()) {
    case CV_8UC3:
      break;
    case CV_8UC1:
      colorType = PNG_COLOR_TYPE_GRAY;
      break;
    case CV_16UC1:
      bitDepth = 16, colorType = PNG_COLOR_TYPE_GRAY;
      break;
    default:
      error = "PNG cannot hold this image type";
      return false;
  }
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    error = "cannot write file";
    return false;
  }
  std::string pngMessage;
  const bool ok = writePngRows(file, image, bitDepth, colorType, &pngMessage);
  const bool closed = std::fclose(file) == 0;
  if (!ok || !closed) {
    error = "cannot write file" + (pngMessage.empty() ? std::string() : ": " + pngMessage);
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
