#pragma once

// What libzrender_codecs.so (src/io/images/codecs/OpenCvCodecs.cpp) gives: OpenCV's imgcodecs and
// videoio, loaded by the first image file other than PNG or the first video
// (io/ImageCodecs.hpp; base/Plugin.hpp). Its factory: zrenderCodecPlugin.

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace zrender {

// A video being written; destroying it finishes the file.
class VideoSink {
 public:
  virtual ~VideoSink() = default;
  virtual void write(const cv::Mat& frame) = 0;  // 8-bit BGR
};

class CodecPlugin {
 public:
  // `image` in the format of `extension` (".jpg"); false with the reason in `error`.
  virtual bool encode(const std::string& extension, const cv::Mat& image,
                      std::vector<unsigned char>& bytes, std::string& error) = 0;
  // The image file at `path` as 8-bit BGR; empty with the reason in `error` (what follows the
  // file's name: "is too large (...)", "cannot be read as an image").
  virtual cv::Mat read(const std::string& path, std::string& error) = 0;
  // The image file at `path` as the file keeps it (cv::IMREAD_UNCHANGED: a 16-bit PNG as
  // 16-bit, a float TIFF or OpenEXR as float, its channels as they are); errors as read().
  virtual cv::Mat readUnchanged(const std::string& path, std::string& error) = 0;
  // The same for an image file's bytes already in memory (a texture embedded in a model).
  virtual cv::Mat decode(const std::vector<unsigned char>& bytes, std::string& error) = 0;
  // A video writer (fourcc as cv::VideoWriter's) at `path`; null when none takes the format.
  virtual std::unique_ptr<VideoSink> openVideo(const std::string& path, int fourcc, double fps,
                                               cv::Size size) = 0;

 protected:
  ~CodecPlugin() = default;
};

}  // namespace zrender
