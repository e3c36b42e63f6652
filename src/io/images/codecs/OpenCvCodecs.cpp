// libzrender_codecs.so: OpenCV's imgcodecs and videoio behind io/CodecPlugin.hpp, loaded by the
// program only when a format other than PNG or a video is used.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "zrender/io/images/CodecPlugin.hpp"
#include "zrender/io/images/ImageCodecs.hpp"

namespace zrender {

namespace {

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

class OpenCvVideo : public VideoSink {
 public:
  explicit OpenCvVideo(std::unique_ptr<cv::VideoWriter> writer) : writer_(std::move(writer)) {}
  void write(const cv::Mat& frame) override { writer_->write(frame); }

 private:
  std::unique_ptr<cv::VideoWriter> writer_;
};

class OpenCvCodecs : public CodecPlugin {
 public:
  // OpenCV's own log (and through it libtiff's and FFmpeg's) never reaches the terminal: what
  // went wrong is the one line zrender prints.
  OpenCvCodecs() { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT); }

  bool encode(const std::string& extension, const cv::Mat& image, std::vector<unsigned char>& bytes,
              std::string& error) override {
    try {
      if (cv::imencode(extension, image, bytes)) return true;
      error = "cannot encode image";
    } catch (const cv::Exception& e) {
      error = "cannot encode image: " + e.msg;
    }
    return false;
  }

  cv::Mat read(const std::string& path, std::string& error) override {
    return decodeWith([&] { return cv::imread(path, cv::IMREAD_COLOR); }, error);
  }

  cv::Mat readUnchanged(const std::string& path, std::string& error) override {
    return decodeWith([&] { return cv::imread(path, cv::IMREAD_UNCHANGED); }, error);
  }

  cv::Mat decode(const std::vector<unsigned char>& bytes, std::string& error) override {
    return decodeWith([&] { return cv::imdecode(bytes, cv::IMREAD_COLOR); }, error);
  }

  std::unique_ptr<VideoSink> openVideo(const std::string& path, int fourcc, double fps,
                                       cv::Size size) override {
    auto writer = std::make_unique<cv::VideoWriter>(path, fourcc, fps, size);
    if (!writer->isOpened()) return nullptr;
    return std::make_unique<OpenCvVideo>(std::move(writer));
  }

 private:
  template <typename Decode>
  static cv::Mat decodeWith(const Decode& decode, std::string& error) {
    const CerrCapture capture;
    // OpenCV checks the header's size against OPENCV_IO_MAX_IMAGE_PIXELS (which zrender sets)
    // before it allocates, and says so only in its message.
    const auto tooLarge = [](const std::string& said) {
      return said.find("CV_IO_MAX_IMAGE_PIXELS") != std::string::npos;
    };
    const std::string largeMessage =
        "is too large (over " + std::to_string(kMaxImagePixels) + " pixels)";
    try {
      cv::Mat image = decode();
      if (!image.empty()) return image;
      error = tooLarge(capture.said()) ? largeMessage : "cannot be read as an image";
    } catch (const cv::Exception& e) {
      error = tooLarge(e.msg) ? largeMessage : "cannot decode image: " + e.msg;
    } catch (const std::bad_alloc&) {
      error = "cannot be read: out of memory";
    }
    return cv::Mat();
  }
};

}  // namespace

}  // namespace zrender

extern "C" __attribute__((visibility("default"))) void* zrenderCodecPlugin() {
  static zrender::OpenCvCodecs plugin;
  return static_cast<zrender::CodecPlugin*>(&plugin);
}
