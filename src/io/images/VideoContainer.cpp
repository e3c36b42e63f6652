#include "zrender/io/images/VideoContainer.hpp"

#include <cstdint>
#include <fstream>
#include <set>
#include <string_view>

#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/models/ModelFormats.hpp"

namespace zrender {

namespace {

uint64_t bigEndian(const unsigned char* p, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = v << 8 | p[i];
  return v;
}

// ISO base media file format (MP4): boxes of a 32-bit big-endian size (1: a 64-bit one
// follows the type; 0: to the file's end) and a four-letter type.
std::string mp4Problem(std::ifstream& in, uint64_t fileSize) {
  std::set<std::string> types;
  uint64_t offset = 0;
  while (offset < fileSize) {
    unsigned char head[16];
    in.seekg(std::streamoff(offset));
    if (!in.read(reinterpret_cast<char*>(head), 8)) return "the video is cut short";
    uint64_t size = bigEndian(head, 4);
    if (size == 1) {
      if (!in.read(reinterpret_cast<char*>(head + 8), 8)) return "the video is cut short";
      size = bigEndian(head + 8, 8);
    } else if (size == 0) {
      size = fileSize - offset;
    }
    if (size < 8 || size > fileSize - offset) return "the video is cut short";
    types.insert(std::string(reinterpret_cast<const char*>(head + 4), 4));
    offset += size;
  }
  if (!types.count("moov")) return "the video has no index (moov box)";
  if (!types.count("mdat")) return "the video has no frames (mdat box)";
  return "";
}

// RIFF (AVI): chunks of a four-letter id and a 32-bit little-endian size, padded to even
// sizes; an AVI is a "RIFF" chunk of form "AVI ", then (past 1 GiB) "RIFF" chunks "AVIX".
std::string aviProblem(std::ifstream& in, uint64_t fileSize) {
  uint64_t offset = 0;
  while (offset < fileSize) {
    char bytes[12];
    in.seekg(std::streamoff(offset));
    if (!in.read(bytes, 12)) return "the video is cut short";
    const std::string_view head(bytes, 12);
    if (head.substr(0, 4) != "RIFF" || head.substr(8, 4) != (offset == 0 ? "AVI " : "AVIX"))
      return "the video is cut short";
    const uint64_t chunk = littleEndian32(head, 4);
    const uint64_t size = 8 + chunk + (chunk & 1);
    if (size > fileSize - offset) return "the video is cut short";
    offset += size;
  }
  return "";
}

}  // namespace

std::string videoContainerProblem(const std::filesystem::path& path) {
  std::error_code ec;
  const uint64_t fileSize = std::filesystem::file_size(path, ec);
  if (ec) return "the video cannot be read back: " + ec.message();
  if (fileSize == 0) return "the video is empty";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "the video cannot be read back";
  return lowerExtension(path) == ".avi" ? aviProblem(in, fileSize) : mp4Problem(in, fileSize);
}

}  // namespace zrender
