#include "support/XwdImage.hpp"

#include <cstdint>

#include "support/TestSupport.hpp"

namespace zrender::test {

namespace {

// A big-endian 32-bit field of the header.
uint32_t field(const std::string& bytes, size_t index) {
  const auto byte = [&](size_t i) { return uint32_t(uint8_t(bytes[index * 4 + i])); };
  return byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
}

int lowestBit(uint32_t mask) {
  int shift = 0;
  while (mask && !(mask & 1u)) mask >>= 1, ++shift;
  return shift;
}

}  // namespace

cv::Mat readXwd(const std::string& path) {
  // X11/XWDFile.h: 25 fields of 32 bits, the window's name to header_size, then ncolors
  // colormap entries of 12 bytes, then the pixels.
  const std::string bytes = readFile(path);
  if (bytes.size() < 100) return {};
  const uint32_t headerSize = field(bytes, 0), format = field(bytes, 2), width = field(bytes, 4),
                 height = field(bytes, 5), byteOrder = field(bytes, 7),
                 bitsPerPixel = field(bytes, 11), bytesPerLine = field(bytes, 12),
                 redMask = field(bytes, 14), greenMask = field(bytes, 15),
                 blueMask = field(bytes, 16), colors = field(bytes, 19);
  const size_t start = size_t(headerSize) + size_t(colors) * 12;
  if (format != 2 /* ZPixmap */ || bitsPerPixel != 32 ||
      bytes.size() < start + size_t(bytesPerLine) * height)
    return {};
  cv::Mat image(int(height), int(width), CV_8UC3);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t at = start + size_t(y) * bytesPerLine + size_t(x) * 4;
      uint32_t p = 0;
      for (int i = 0; i < 4; ++i) {
        const uint32_t b = uint8_t(bytes[at + size_t(i)]);
        p |= byteOrder == 0 ? b << (8 * i) : b << (8 * (3 - i));  // 0: least significant first
      }
      image.at<cv::Vec3b>(int(y), int(x)) =
          cv::Vec3b(uint8_t((p & blueMask) >> lowestBit(blueMask)),
                    uint8_t((p & greenMask) >> lowestBit(greenMask)),
                    uint8_t((p & redMask) >> lowestBit(redMask)));
    }
  }
  return image;
}

}  // namespace zrender::test
