#pragma once

// PNG files encoded on several threads (docs/design.md, Image files). The rows are cut into
// strips, each deflated on its own (ISA-L's igzip at level 0, raw deflate, filter None on every
// row) and ended with a sync flush, so that the strips laid end to end are one deflate stream;
// their Adler-32 sums are combined into the zlib stream's (zlib). The file is written here,
// without libpng: signature, IHDR, the zlib stream in IDAT chunks, IEND.

#include <cstddef>
#include <cstdio>
#include <string>

#include <opencv2/core/mat.hpp>

namespace zrender {

class Threads;

// Filtered bytes (a filter byte and a row of samples) per strip, as near as whole rows allow:
// large enough that a strip's fresh deflate window costs little compression, small enough that
// a 1800 x 1800 color image gives some 38 strips to balance over the threads.
inline constexpr size_t kPngStripBytes = 256 * 1024;

// The most data bytes of one IDAT chunk.
inline constexpr size_t kPngChunkBytes = 1 << 20;

// Whether encodePng can write `image`: not empty, and 8-bit BGR (stored as RGB), 8-bit gray or
// 16-bit gray (stored big-endian).
bool pngCanHold(const cv::Mat& image);

// Writes `image` (pngCanHold) as a PNG file into `file`, its strips of about `stripBytes` (at
// least one row each) deflated by `threads` and written in order as each is done, each strip
// its own IDAT chunks. The bytes written do not depend on the number of threads. Returns false and
// sets `error` ("out of memory", or the system's reason for a failed write) on failure; `file` is
// left open either way.
bool encodePng(std::FILE* file, const cv::Mat& image, const Threads& threads, std::string& error,
               size_t stripBytes = kPngStripBytes);

}  // namespace zrender
