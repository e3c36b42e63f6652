#include "zrender/io/ImageOutput.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <system_error>

#include "zrender/base/Error.hpp"
#include "zrender/io/ImageCodecs.hpp"

namespace zrender {

namespace {

// The nearest of a pixel's samples (its smallest key).
DepthKey pixelKey(const FrameBuffer& fb, int scale, int x, int y) {
  if (scale == 1) return fb.row(y)[x];
  const DepthKey* r0 = fb.row(2 * y);
  const DepthKey* r1 = fb.row(2 * y + 1);
  return std::min({r0[2 * x], r0[2 * x + 1], r1[2 * x], r1[2 * x + 1]});
}

// The missing folders above `path`, or InputError naming it.
void createParentFolders(const std::filesystem::path& path) {
  std::error_code ec;
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) throw InputError(path.string() + ": cannot create folder: " + ec.message());
}

}  // namespace

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

std::filesystem::path pathBeside(const std::filesystem::path& target, const char* tag) {
  return target.parent_path() / ("." + target.stem().string() + "." + tag + "-" +
                                 std::to_string(::getpid()) + target.extension().string());
}

void checkWritable(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  createParentFolders(path);
  if (fs::is_directory(path, ec))
    throw InputError(path.string() + ": cannot write file (a folder has that name)");
  const fs::path probe = pathBeside(path, "probe");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(path.string() + ": cannot write file: " + std::strerror(errno));
  ::close(fd);
  fs::remove(probe, ec);
}

void replaceFile(const std::filesystem::path& from, const std::filesystem::path& to,
                 std::error_code& ec) {
  const auto isFile = [](const std::filesystem::path& path) {
    struct stat status {};
    return ::lstat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
  };
  if (isFile(to) &&
      ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
    if (isFile(from)) {  // the old file, now under the temporary name
      std::filesystem::remove(from, ec);
      ec.clear();  // the new one is in place whatever became of the old
      return;
    }
    // Something else took the target's place since it was looked at: put it back.
    ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE);
  }
  // No file there, or not a regular one (a rename over a folder fails as it should), or a file
  // system that cannot exchange.
  std::filesystem::rename(from, to, ec);
}

void writeImageAtomically(const std::filesystem::path& path, const Image& image,
                          const Threads* threads) {
  namespace fs = std::filesystem;
  std::error_code ec;
  createParentFolders(path);
  const fs::path tmp = pathBeside(path, "tmp");
  std::string reason;
  if (!encodeImageFile(tmp, image, reason, threads)) {
    fs::remove(tmp, ec);
    throw InputError(path.string() + ": " + reason);
  }
  replaceFile(tmp, path, ec);
  if (ec) {
    std::error_code ignored;  // not ec: its message is the reason given
    fs::remove(tmp, ignored);
    throw InputError(path.string() + ": cannot replace file: " + ec.message());
  }
}

Image depthImage(const FrameBuffer& fb, int scale, bool sixteenBit) {
  const int width = fb.width() / scale, height = fb.height() / scale;
  Image out(height, width, sixteenBit ? PixelFormat::kGray16 : PixelFormat::kFloat32);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float d = keyDepth(pixelKey(fb, scale, x, y));
      if (sixteenBit)
        out.row<uint16_t>(y)[x] = uint16_t(std::lround(double(d) * 65535.0));
      else
        out.row<float>(y)[x] = d;
    }
  }
  return out;
}

Image idImage(const FrameBuffer& fb, int scale) {
  const int width = fb.width() / scale, height = fb.height() / scale;
  Image out(height, width, PixelFormat::kBgr8);
  for (int y = 0; y < height; ++y) {
    uint8_t* p = out.row(y);
    for (int x = 0; x < width; ++x) {
      const uint32_t v = keyFaceId(pixelKey(fb, scale, x, y)) + 1;  // background wraps to 0
      p[3 * x + 2] = uint8_t(v);                                    // R: low byte
      p[3 * x + 1] = uint8_t(v >> 8);                               // G: middle byte
      p[3 * x + 0] = uint8_t(v >> 16);                              // B: high byte
    }
  }
  return out;
}

}  // namespace zrender
