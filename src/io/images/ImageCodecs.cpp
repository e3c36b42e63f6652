#include "zrender/io/images/ImageCodecs.hpp"

#include <png.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "zrender/base/Plugin.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/images/CodecPlugin.hpp"
#include "zrender/io/images/PngWriter.hpp"

namespace zrender {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void limitImageReads() {
  // OpenCV reads its limit on an image's pixels when it is loaded; it checks each file's
  // header against it before allocating (docs/design.md, Limits).
  // Once: two plugins may be loaded at once (a model's and a texture's side by side).
  static const bool set =
      ::setenv("OPENCV_IO_MAX_IMAGE_PIXELS", std::to_string(kMaxImagePixels).c_str(), 1) == 0;
  (void)set;
}

namespace {

CodecPlugin& codecPlugin() {
  static CodecPlugin& plugin = [&]() -> CodecPlugin& {
    limitImageReads();
    return loadPlugin<CodecPlugin>("libzrender_codecs.so", "zrenderCodecPlugin");
  }();
  return plugin;
}

// A PNG image read by libpng: `begin` starts `png` on a file or on bytes in memory.
template <typename Begin>
cv::Mat readPng(const Begin& begin, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto failed = [&] {
    error = std::string("cannot be read as an image: ") + png.message;
    png_image_free(&png);
    return cv::Mat();
  };
  if (!begin(png)) return failed();
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
  return codecPlugin().encode(extension, image, bytes, error);
}

namespace {

// Whether `path` is a regular file that opens, so that a decoder may read it; sets `error`
// otherwise. Whether it starts with PNG's signature, in `isPng`.
bool openableImage(const fs::path& path, bool& isPng, std::string& error) {
  unsigned char signature[8] = {};
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    error = "cannot be opened (it is a folder)";
    return false;
  }
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {  // said here: OpenCV would print a warning of its own on stderr
    error = std::string("cannot be opened: ") + std::strerror(errno);
    return false;
  }
  struct stat status {};
  if (::fstat(fileno(f), &status) != 0 || !S_ISREG(status.st_mode)) {
    std::fclose(f);
    error = "cannot be read (not a regular file)";  // a device or a pipe never ends
    return false;
  }
  const size_t n = std::fread(signature, 1, sizeof signature, f);
  std::fclose(f);
  isPng = n == sizeof signature && png_sig_cmp(signature, 0, sizeof signature) == 0;
  return true;
}

cv::Mat decodeOrThrow(const fs::path& path, std::string& error) {
  // PNG files are recognised by their signature, whatever their name.
  bool isPng = false;
  if (!openableImage(path, isPng, error)) return {};
  if (isPng)
    return readPng(
        [&](png_image& png) { return png_image_begin_read_from_file(&png, path.c_str()); }, error);
  return codecPlugin().read(path.string(), error);
}

// Turns the exceptions of `decode` into `error`, as the decoders' own failures.
template <typename Decode>
cv::Mat decodeCaught(const Decode& decode, std::string& error) {
  try {
    return decode();
  } catch (const std::bad_alloc&) {
    error = "cannot be read: out of memory";
  } catch (const std::exception& e) {  // the codec plugin cannot be loaded
    error = std::string("cannot be read: ") + e.what();
  }
  return {};
}

}  // namespace

cv::Mat decodeColorImage(const std::vector<unsigned char>& bytes, std::string& error) {
  try {
    if (bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0) {
      return readPng(
          [&](png_image& png) {
            return png_image_begin_read_from_memory(&png, bytes.data(), bytes.size());
          },
          error);
    }
    return codecPlugin().decode(bytes, error);
  } catch (const std::bad_alloc&) {
    error = "cannot be read: out of memory";
  } catch (const std::exception& e) {  // the codec plugin cannot be loaded
    error = std::string("cannot be read: ") + e.what();
  }
  return {};
}

cv::Mat decodeColorImage(const fs::path& path, std::string& error) {
  return decodeCaught([&] { return decodeOrThrow(path, error); }, error);
}

cv::Mat decodeImageUnchanged(const fs::path& path, std::string& error) {
  return decodeCaught(
      [&] {
        // Through OpenCV, a 16-bit PNG too: a hand-made libpng reader needs setjmp, whose
        // longjmp the compiler cannot prove safe for the strings around it (-Wclobbered).
        bool isPng = false;
        if (!openableImage(path, isPng, error)) return cv::Mat();
        return codecPlugin().readUnchanged(path.string(), error);
      },
      error);
}

VideoFile::VideoFile(const fs::path& path, int width, int height, double fps) {
  const bool mp4 = lowerExtension(path) == ".mp4";
  // As cv::VideoWriter::fourcc: four characters, the first in the lowest byte.
  const auto fourcc = [](char a, char b, char c, char d) {
    return (a & 255) + ((b & 255) << 8) + ((c & 255) << 16) + ((d & 255) << 24);
  };
  const int code = mp4 ? fourcc('m', 'p', '4', 'v') : fourcc('M', 'J', 'P', 'G');
  sink_ = codecPlugin().openVideo(path.string(), code, fps, cv::Size(width, height));
}

VideoFile::~VideoFile() = default;

void VideoFile::write(const cv::Mat& frame) {
  if (sink_) sink_->write(frame);
}

void VideoFile::close() {
  sink_.reset();
}

}  // namespace zrender
