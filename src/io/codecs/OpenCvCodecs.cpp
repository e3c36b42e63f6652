// libzrender_codecs.so: OpenCV's imgcodecs and videoio behind the C interface of
// CodecPlugin.h, loaded by the program only when a format other than PNG or a video is used.

#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "zrender/base/Plugin.hpp"
#include "zrender/io/CodecPlugin.h"
#include "zrender/io/ImageMat.hpp"

using zrender::setPluginError;

extern "C" {

__attribute__((visibility("default"))) int zrenderImwrite(const char* path,
                                                          const zrender::Image* image, char* error,
                                                          size_t size) {
  try {
    if (cv::imwrite(path, zrender::asMat(*image))) return 0;
    setPluginError(error, size, "cannot write file");
  } catch (const cv::Exception& e) {
    setPluginError(error, size, "cannot encode image: " + e.msg);
  }
  return 1;
}

__attribute__((visibility("default"))) int zrenderImread(const char* path, zrender::Image* out,
                                                         char* error, size_t size) {
  try {
    const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
    if (!image.empty() && zrender::copyToImage(image, *out)) return 0;
    setPluginError(error, size, "cannot be read as an image");
  } catch (const cv::Exception& e) {
    setPluginError(error, size, "cannot decode image: " + e.msg);
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

__attribute__((visibility("default"))) int zrenderVideoWrite(void* writer,
                                                             const zrender::Image* frame) {
  static_cast<cv::VideoWriter*>(writer)->write(zrender::asMat(*frame));
  return 0;
}

__attribute__((visibility("default"))) void zrenderVideoClose(void* writer) {
  delete static_cast<cv::VideoWriter*>(writer);
}

}  // extern "C"
