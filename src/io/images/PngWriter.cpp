#include "zrender/io/images/PngWriter.hpp"

#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

#include "zrender/base/InOrderPipeline.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/io/images/PngRows.hpp"

namespace zrender {

namespace {

// Grown and then written in full: no zeroing first.
using Bytes = std::vector<unsigned char, UninitializedAllocator<unsigned char>>;

// PNG's fixed numbers (PNG specification, sections 5.2 and 11.2.2).
constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr int kColorGray = 0, kColorRgb = 2;
constexpr unsigned char kFilterNone = 0;
// The zlib header: deflate with a 32 KiB window (0x78), "fastest" level, check bits (0x01).
constexpr unsigned char kZlibHeader[2] = {0x78, 0x01};

void putBigEndian32(unsigned char* p, uint32_t v) {
  p[0] = uint8_t(v >> 24), p[1] = uint8_t(v >> 16), p[2] = uint8_t(v >> 8), p[3] = uint8_t(v);
}

// Bytes of one row as PNG stores it, filter byte excluded.
size_t sampleBytes(const cv::Mat& image) {
  return size_t(image.cols) * image.elemSize();
}

// One row as PNG stores it: the filter byte, then RGB for BGR, big-endian for 16-bit.
void filterRow(const cv::Mat& image, int y, BgrToRgb toRgb, unsigned char* out) {
  out[0] = kFilterNone;
  unsigned char* samples = out + 1;
  const unsigned char* in = image.ptr(y);
  const size_t n = sampleBytes(image);
  if (image.type() == CV_8UC3) {
    toRgb(in, samples, size_t(image.cols));
  } else if (image.type() == CV_16UC1) {
    for (size_t i = 0; i < n; i += 2) samples[i] = in[i + 1], samples[i + 1] = in[i];
  } else if (image.type() == CV_16UC3) {
    // B, G, R little-endian words to R, G, B big-endian ones.
    for (size_t i = 0; i < n; i += 6) {
      for (size_t c = 0; c < 3; ++c) {
        samples[i + 2 * c] = in[i + 2 * (2 - c) + 1];
        samples[i + 2 * c + 1] = in[i + 2 * (2 - c)];
      }
    }
  } else {
    std::memcpy(samples, in, n);
  }
}

// What a thread keeps from strip to strip: the strip's rows filtered.
struct Scratch {
  Bytes filtered;
};

// One strip's part of the zlib stream: its rows deflated, and their Adler-32.
struct Strip {
  Bytes deflated;
  uint32_t adler = 1;
  size_t filteredBytes = 0;
  bool ok = false;
};

// Rows [first, end) filtered and deflated by igzip at level 0 as raw deflate (no header),
// ending on a byte boundary (a sync flush), or, for the last strip, with the stream's last
// block.
Strip deflateStrip(const cv::Mat& image, int first, int end, bool last, Scratch& scratch) {
  Strip strip;
  const size_t rowBytes = 1 + sampleBytes(image);
  const size_t n = rowBytes * size_t(end - first);
  strip.filteredBytes = n;
  scratch.filtered.resize(n);
  const BgrToRgb toRgb = bgrToRgb();
  for (int y = first; y < end; ++y)
    filterRow(image, y, toRgb, scratch.filtered.data() + rowBytes * size_t(y - first));
  strip.adler = isal_adler32(1, scratch.filtered.data(), n);

  // Level 0, not 1 or 2: those gave another (equivalent) match now and then on a loaded
  // machine, the same pixels in other bytes (docs/design.md, Image files).
  isal_zstream z;
  isal_deflate_init(&z);
  z.level = 0;
  z.flush = SYNC_FLUSH;
  z.end_of_stream = last ? 1 : 0;
  z.next_in = scratch.filtered.data();
  z.avail_in = uint32_t(n);
  // Stored blocks at worst (noise): 5 bytes of header per 64 KiB, and the flush. Only the
  // pages written are touched.
  strip.deflated.resize(n + n / 4096 + 1024);
  z.next_out = strip.deflated.data();
  z.avail_out = uint32_t(strip.deflated.size());
  for (;;) {
    if (isal_deflate(&z) != COMP_OK) return strip;
    const bool done =
        z.avail_in == 0 && z.avail_out > 0 && (!last || z.internal_state.state == ZSTATE_END);
    if (done) break;
    const size_t used = strip.deflated.size() - z.avail_out;  // out of room: more
    strip.deflated.resize(2 * strip.deflated.size());
    z.next_out = strip.deflated.data() + used;
    z.avail_out = uint32_t(strip.deflated.size() - used);
  }
  strip.deflated.resize(strip.deflated.size() - z.avail_out);
  strip.ok = true;
  return strip;
}

// Bytes laid end to end without copying them.
struct Piece {
  const unsigned char* data;
  size_t size;
};

bool writeAll(std::FILE* file, const void* data, size_t n) {
  return std::fwrite(data, 1, n, file) == n;
}

// A chunk's length and type; `crc` starts its CRC-32, which covers the type and the data. The
// CRC is ISA-L's (the same CRC-32 as zlib's crc32, in a tenth of its time with PCLMULQDQ).
bool beginChunk(std::FILE* file, const char* type, size_t length, uint32_t& crc) {
  unsigned char head[8];
  putBigEndian32(head, uint32_t(length));
  std::memcpy(head + 4, type, 4);
  crc = crc32_gzip_refl(0, head + 4, 4);
  return writeAll(file, head, sizeof head);
}

bool endChunk(std::FILE* file, uint32_t crc) {
  unsigned char tail[4];
  putBigEndian32(tail, uint32_t(crc));
  return writeAll(file, tail, sizeof tail);
}

// Data of one chunk, or part of it.
bool writeChunkData(std::FILE* file, const unsigned char* data, size_t n, uint32_t& crc) {
  if (n == 0) return true;  // IEND's
  crc = crc32_gzip_refl(crc, data, n);
  return writeAll(file, data, n);
}

bool writeChunk(std::FILE* file, const char* type, const unsigned char* data, size_t n) {
  uint32_t crc;
  return beginChunk(file, type, n, crc) && writeChunkData(file, data, n, crc) &&
         endChunk(file, crc);
}

// The zlib stream made of `pieces` as IDAT chunks of at most kPngChunkBytes each; a chunk may
// span pieces.
bool writeIdat(std::FILE* file, const std::vector<Piece>& pieces) {
  size_t total = 0;
  for (const Piece& p : pieces) total += p.size;
  size_t piece = 0, offset = 0;  // the next byte to write: pieces[piece].data[offset]
  while (total > 0) {
    const size_t length = std::min(total, kPngChunkBytes);
    uint32_t crc;
    if (!beginChunk(file, "IDAT", length, crc)) return false;
    for (size_t left = length; left > 0;) {
      if (offset == pieces[piece].size) {
        ++piece, offset = 0;
        continue;
      }
      const size_t n = std::min(left, pieces[piece].size - offset);
      if (!writeChunkData(file, pieces[piece].data + offset, n, crc)) return false;
      offset += n, left -= n;
    }
    if (!endChunk(file, crc)) return false;
    total -= length;
  }
  return true;
}

}  // namespace

bool pngCanHold(const cv::Mat& image) {
  const int f = image.type();
  return !image.empty() && (f == CV_8UC3 || f == CV_8UC1 || f == CV_16UC1 || f == CV_16UC3);
}

bool encodePng(std::FILE* file, const cv::Mat& image, const Threads& threads, std::string& error,
               size_t stripBytes) {
  const size_t rowBytes = 1 + sampleBytes(image);
  const int rowsPerStrip = int(std::clamp<size_t>(stripBytes / rowBytes, 1, size_t(image.rows)));
  const size_t stripCount = (size_t(image.rows) + size_t(rowsPerStrip) - 1) / size_t(rowsPerStrip);

  const bool gray = image.channels() == 1;
  unsigned char header[13];
  putBigEndian32(header, uint32_t(image.cols));
  putBigEndian32(header + 4, uint32_t(image.rows));
  header[8] = uint8_t(image.depth() == CV_16U ? 16 : 8);  // bits per sample
  header[9] = uint8_t(gray ? kColorGray : kColorRgb);
  header[10] = header[11] = header[12] = 0;  // deflate, adaptive filtering, no interlace
  const auto failed = [&] {
    error = errno ? std::strerror(errno) : "write failed";
    return false;
  };
  errno = 0;
  if (!writeAll(file, kSignature, sizeof kSignature) ||
      !writeChunk(file, "IHDR", header, sizeof header))
    return failed();

  // The strips are deflated by the threads and written in order as each is done, so that the
  // writing overlaps the deflating of the strips after it. Each strip is its own IDAT chunks,
  // the zlib header in the first strip's, the stream's Adler-32 in the last's.
  struct Stop {};  // ends the strips early; `error` says why
  const size_t slots = 2 * size_t(threads.count());
  std::vector<Strip> strips(slots);
  std::vector<Scratch> scratch(slots);
  uLong adler = adler32(0, nullptr, 0);
  try {
    pipelineInOrder(
        threads, stripCount, slots,
        [&](size_t i, size_t slot) {
          const int first = int(i) * rowsPerStrip;
          strips[slot] = deflateStrip(image, first, std::min(first + rowsPerStrip, image.rows),
                                      i + 1 == stripCount, scratch[slot]);
        },
        [&](size_t i, size_t slot) {
          const Strip& s = strips[slot];
          if (!s.ok) {
            error = "compression failed";  // igzip fails only on arguments it does not take
            throw Stop();
          }
          adler = adler32_combine(adler, s.adler, z_off_t(s.filteredBytes));
          std::vector<Piece> pieces;
          if (i == 0) pieces.push_back({kZlibHeader, sizeof kZlibHeader});
          pieces.push_back({s.deflated.data(), s.deflated.size()});
          unsigned char trailer[4];
          if (i + 1 == stripCount) {
            putBigEndian32(trailer, uint32_t(adler));
            pieces.push_back({trailer, sizeof trailer});
          }
          errno = 0;  // this thread's
          if (!writeIdat(file, pieces)) {
            failed();
            throw Stop();
          }
        });
  } catch (const Stop&) {
    return false;
  }
  errno = 0;
  if (writeChunk(file, "IEND", nullptr, 0) && std::fflush(file) == 0) return true;
  return failed();
}

}  // namespace zrender
