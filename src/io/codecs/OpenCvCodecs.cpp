// libzrender_codecs.so: OpenCV's imgcodecs and videoio behind the C interface of
// CodecPlugin.h, loaded by the program only when a format other than PNG or a video is used.

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "zrender/base/Plugin.hpp"
#include "zrender/io/CodecPlugin.h"
#include "zrender/io/ImageCodecs.hpp"

using zrender::setPluginError;

namespace {

// OpenCV's own log (and through it libtiff's and FFmpeg's) never reaches the terminal: what
// went wrong is the one line zrender prints.
__attribute__((constructor)) void silenceOpenCv() {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
}

// cv::imread prints why it failed on std::cerr: what it says while `this` lives is kept here
// instead. Textures are read while no other thread prints.
class CerrCapture {
 public:
  CerrCapture() : old_(std::cerr.rdbuf(said_.rdbuf())) {}
  ~CerrCapture() { std::cerr.rdbuf(old_); }
  std::string said() const { return said_.str(); }

 private:
  std::ostringstream said_;
  std::streambuf* old_;
};

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int zrenderImencode(const char* extension,
                                                           const cv::Mat* image, void* out,
                                                           char* error, size_t size) {
  try {
    auto& bytes = *static_cast<std::vector<unsigned char>*>(out);
    if (cv::imencode(extension, *image, bytes)) return 0;
    setPluginError(error, size, "cannot encode image");
  } catch (const cv::Exception& e) {
    setPluginError(error, size, "cannot encode image: " + e.msg);
  }
  return 1;
}

__attribute__((visibility("default"))) int zrenderImread(const char* path, cv::Mat* out,
                                                         char* error, size_t size) {
  const CerrCapture capture;
  // OpenCV checks the header's size against OPENCV_IO_MAX_IMAGE_PIXELS (which zrender sets)
  // before it allocates, and says so only in its message.
  const auto tooLarge = [](const std::string& said) {
    return said.find("CV_IO_MAX_IMAGE_PIXELS") != std::string::npos;
  };
  const std::string largeMessage =
      "is too large (over " + std::to_string(zrender::kMaxImagePixels) + " pixels)";
  try {
    const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
    if (!image.empty()) {
      *out = image;
      return 0;
    }
    setPluginError(error, size,
                   tooLarge(capture.said()) ? largeMessage : "cannot be read as an image");
  } catch (const cv::Exception& e) {
    setPluginError(error, size, tooLarge(e.msg) ? largeMessage : "cannot decode image: " + e.msg);
  } catch (const std::bad_alloc&) {
    setPluginError(error, size, "cannot be read: out of memory");
  }
  return 1;
}

__attribute__((visibility("default"))) void* zrenderVideoOpen(const char* path, int fourcc,
                                                              double fps, int width, int height) {
  auto* writer = new cv::VideoWriter(path, fourcc, fps, cv::Size(width, height));
  if (writer->isOpened()) return writer;
  delete writer;
  return nullptr;
}

__attribute__((visibility("default"))) int zrenderVideoWrite(void* writer, const cv::Mat* frame) {
  static_cast<cv::VideoWriter*>(writer)->write(*frame);
  return 0;
}

__attribute__((visibility("default"))) void zrenderVideoClose(void* writer) {
  delete static_cast<cv::VideoWriter*>(writer);
}

}  // extern "C"
