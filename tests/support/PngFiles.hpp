#pragma once

// Reading a PNG file back without zrender's own code, to check what PngWriter wrote: its chunks
// taken apart by hand (each CRC-32 checked, the IDAT data inflated by zlib's uncompress, which
// checks the Adler-32), and its pixels decoded by libpng.

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace zrender::test {

struct PngChunk {
  std::string type;
  size_t length = 0;
  bool crcOk = false;
};

struct PngParts {
  bool signatureOk = false;
  std::vector<PngChunk> chunks;  // in file order, up to IEND or the first broken one
  bool endsAtIend = false;       // IEND is the last chunk and nothing follows it
  // IHDR's fields.
  int width = 0, height = 0, bitDepth = 0, colorType = -1, compression = -1, filter = -1,
      interlace = -1;
  int uncompressStatus = -1;  // zlib's uncompress on the IDAT data joined: Z_OK (0) when valid
  std::string inflated;       // its output: the filtered rows
};

// The parts of the PNG file at `path` (signatureOk false when it cannot be read).
PngParts readPngParts(const std::string& path);

// The rows of `image` (CV_8UC3 BGR, CV_8UC1 or CV_16UC1) as PNG stores them unfiltered: each a
// filter byte 0, then RGB, gray, or big-endian 16-bit gray samples.
std::string unfilteredRows(const cv::Mat& image);

// The image at `path` decoded by libpng: CV_8UC3 (BGR) for RGB, CV_8UC1 or CV_16UC1 for gray;
// empty when libpng fails, with its message in `error`.
cv::Mat readPngWithLibpng(const std::string& path, std::string& error);

}  // namespace zrender::test
