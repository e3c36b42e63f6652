#include "support/PngFiles.hpp"

#include <png.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "support/TestSupport.hpp"

namespace zrender::test {

namespace {

uint32_t bigEndian32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// libpng reports errors by longjmp back to the setjmp in decodeRows; the message is kept here.
void pngError(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

// The libpng calls of readPngWithLibpng, with no C++ object of this function alive across
// setjmp: reads the header, has `allocate(width, height, bitDepth, colorType)` point `rows` at
// the image's rows (left empty for a type it does not take), then reads the pixels into them.
template <typename Allocate>
bool decodeRows(std::FILE* file, std::string* error, std::vector<png_bytep>& rows,
                const Allocate& allocate) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, error, pngError, pngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  const int bitDepth = png_get_bit_depth(png, info), colorType = png_get_color_type(png, info);
  if (colorType == PNG_COLOR_TYPE_RGB) png_set_bgr(png);  // to OpenCV's order
  if (bitDepth == 16) png_set_swap(png);                  // to the machine's byte order
  png_read_update_info(png, info);
  allocate(int(png_get_image_width(png, info)), int(png_get_image_height(png, info)), bitDepth,
           colorType);
  if (rows.empty()) png_error(png, "unexpected image type");
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

PngParts readPngParts(const std::string& path) {
  PngParts parts;
  const std::string bytes = readFile(path);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(data, kSignature, 8) != 0) return parts;
  parts.signatureOk = true;
  std::string idat;
  size_t at = 8;
  while (at + 12 <= bytes.size()) {
    PngChunk chunk;
    chunk.length = bigEndian32(data + at);
    if (at + 12 + chunk.length > bytes.size()) break;
    chunk.type = bytes.substr(at + 4, 4);
    const unsigned char* body = data + at + 8;
    const uLong crc = crc32_z(crc32(0, nullptr, 0), data + at + 4, 4 + chunk.length);
    chunk.crcOk = crc == bigEndian32(body + chunk.length);
    if (chunk.type == "IHDR" && chunk.length == 13) {
      parts.width = int(bigEndian32(body));
      parts.height = int(bigEndian32(body + 4));
      parts.bitDepth = body[8], parts.colorType = body[9], parts.compression = body[10];
      parts.filter = body[11], parts.interlace = body[12];
    }
    if (chunk.type == "IDAT") idat.append(bytes, at + 8, chunk.length);
    parts.chunks.push_back(chunk);
    at += 12 + chunk.length;
    if (chunk.type == "IEND") {
      parts.endsAtIend = at == bytes.size();
      break;
    }
  }
  // The filtered rows' size, known from IHDR, is all uncompress needs of the output.
  const size_t samples = parts.colorType == 2 ? 3 : 1;
  uLongf size = uLongf(parts.height) * (1 + uLongf(parts.width) * samples * parts.bitDepth / 8);
  parts.inflated.resize(size + 1);  // one spare byte: output longer than expected shows
  size = uLongf(parts.inflated.size());
  parts.uncompressStatus =
      uncompress(reinterpret_cast<Bytef*>(parts.inflated.data()), &size,
                 reinterpret_cast<const Bytef*>(idat.data()), uLong(idat.size()));
  parts.inflated.resize(size);
  return parts;
}

std::string unfilteredRows(const cv::Mat& image) {
  std::string out;
  for (int y = 0; y < image.rows; ++y) {
    out += '\0';
    const cv::Mat row = image.row(y);
    for (int x = 0; x < image.cols; ++x) {
      if (image.type() == CV_8UC3) {
        const cv::Vec3b bgr = row.at<cv::Vec3b>(x);
        out += char(bgr[2]), out += char(bgr[1]), out += char(bgr[0]);
      } else if (image.type() == CV_16UC1) {
        const uint16_t v = row.at<uint16_t>(x);
        out += char(v >> 8), out += char(v & 255);
      } else {
        out += char(row.at<uint8_t>(x));
      }
    }
  }
  return out;
}

cv::Mat readPngWithLibpng(const std::string& path, std::string& error) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    error = "cannot open";
    return {};
  }
  cv::Mat image;
  std::vector<png_bytep> rows;
  const bool ok = decodeRows(file, &error, rows, [&](int width, int height, int depth, int color) {
    const int channels = color == PNG_COLOR_TYPE_RGB ? 3 : color == PNG_COLOR_TYPE_GRAY ? 1 : 0;
    if (channels == 0 || (depth != 8 && depth != 16)) return;
    image.create(height, width, CV_MAKETYPE(depth == 16 ? CV_16U : CV_8U, channels));
    for (int y = 0; y < height; ++y) rows.push_back(image.ptr<png_byte>(y));
  });
  std::fclose(file);
  return ok ? image : cv::Mat();
}

}  // namespace zrender::test
