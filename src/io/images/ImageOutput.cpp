#include "zrender/io/images/ImageOutput.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/PngWriter.hpp"

namespace zrender {

std::initializer_list<const char*> colorExtensions() {
  static const std::initializer_list<const char*> list = {".png", ".jpg", ".jpeg", ".bmp",
                                                          ".ppm", ".tif", ".tiff"};
  return list;
}

void checkOutputExtension(const std::filesystem::path& path,
                          std::initializer_list<const char*> allowed, const char* what) {
  const std::string ext = lowerExtension(path);
  std::string list;
  for (const char* a : allowed) {
    if (ext == a) return;
    list += (list.empty() ? "" : " ") + std::string(a);
  }
  throw InputError(path.string() + ": unsupported " + what + " format '" + ext + "' (use " + list +
                   ")");
}

void writeImageAtomically(const std::filesystem::path& path, const cv::Mat& image,
                          const Threads* threads) {
  OutputFile file(path);
  std::string reason;
  if (lowerExtension(path) == ".png") {
    if (!pngCanHold(image))
      file.fail(image.empty() ? "PNG cannot hold an empty image"
                              : "PNG cannot hold this image type");
    const Threads one;
    if (!encodePng(file.stream(), image, threads ? *threads : one, reason))
      file.fail("cannot write file: " + reason);
  } else {
    std::vector<unsigned char> bytes;
    if (!encodeImage(lowerExtension(path), image, bytes, reason)) file.fail(reason);
    file.write(bytes.data(), bytes.size());
  }
  file.commit();
}

cv::Mat depthImage(const FrameBuffer& fb, int scale, bool sixteenBit) {
  const int width = fb.width() / scale, height = fb.height() / scale;
  cv::Mat out(height, width, sixteenBit ? CV_16UC1 : CV_32FC1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float d = keyDepth(nearestSample(fb, scale, x, y).key);
      if (sixteenBit)
        out.ptr<uint16_t>(y)[x] = uint16_t(std::lround(double(d) * 65535.0));
      else
        out.ptr<float>(y)[x] = d;
    }
  }
  return out;
}

cv::Mat idImage(const FrameBuffer& fb, int scale) {
  const int width = fb.width() / scale, height = fb.height() / scale;
  cv::Mat out(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    uint8_t* p = out.ptr(y);
    for (int x = 0; x < width; ++x) {
      const uint32_t v =
          keyFaceId(nearestSample(fb, scale, x, y).key) + 1;  // background wraps to 0
      p[3 * x + 2] = uint8_t(v);                              // R: low byte
      p[3 * x + 1] = uint8_t(v >> 8);                         // G: middle byte
      p[3 * x + 0] = uint8_t(v >> 16);                        // B: high byte
    }
  }
  return out;
}

}  // namespace zrender
