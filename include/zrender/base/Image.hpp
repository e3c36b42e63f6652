#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>

namespace zrender {

// How an Image stores a pixel.
enum class PixelFormat {
  kGray8,    // one byte
  kBgr8,     // three bytes: blue, green, red
  kGray16,   // one uint16_t
  kFloat32,  // one float
};

inline size_t bytesPerPixel(PixelFormat format) {
  switch (format) {
    case PixelFormat::kGray8:
      return 1;
    case PixelFormat::kBgr8:
      return 3;
    case PixelFormat::kGray16:
      return 2;
    case PixelFormat::kFloat32:
      return 4;
  }
  return 1;
}

// An image: `rows` rows of `cols` pixels, each row `step` bytes after the one before. The
// program's own image type, so that it needs none of OpenCV's libraries to start: those are met
// only in the plugins that read, write, draw and show images, which see an Image as a cv::Mat
// without a copy (io/ImageMat.hpp; docs/design.md, Plugins). Like a cv::Mat, copies share the
// pixels; clone() copies them.
class Image {
 public:
  Image() = default;
  // New pixels, zeroed.
  Image(int rows, int cols, PixelFormat format)
      : rows_(rows > 0 && cols > 0 ? rows : 0),
        cols_(rows > 0 && cols > 0 ? cols : 0),
        format_(format),
        step_(size_t(cols_) * bytesPerPixel(format)) {
    if (rows_ > 0) {
      owner_.reset(new uint8_t[step_ * size_t(rows_)]());
      data_ = owner_.get();
    }
  }
  // A view of pixels that something else owns, which must outlive the view and its copies.
  Image(int rows, int cols, PixelFormat format, void* data, size_t step)
      : data_(static_cast<uint8_t*>(data)),
        rows_(rows),
        cols_(cols),
        format_(format),
        step_(step) {}

  // New zeroed pixels unless the image already has this size and format (as cv::Mat::create).
  void create(int rows, int cols, PixelFormat format) {
    if (rows == rows_ && cols == cols_ && format == format_ && !empty()) return;
    *this = Image(rows, cols, format);
  }

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  PixelFormat format() const { return format_; }
  size_t step() const { return step_; }  // bytes from a row to the next
  size_t pixelBytes() const { return bytesPerPixel(format_); }
  bool empty() const { return data_ == nullptr || rows_ == 0 || cols_ == 0; }

  uint8_t* data() const { return data_; }
  template <typename T = uint8_t>
  T* row(int y) const {
    return reinterpret_cast<T*>(data_ + size_t(y) * step_);
  }

  // A new image with the same pixels, rows packed.
  Image clone() const {
    Image copy(rows_, cols_, format_);
    for (int y = 0; y < copy.rows_; ++y) std::memcpy(copy.row(y), row(y), copy.step_);
    return copy;
  }

  // The same size, format and pixels.
  bool samePixels(const Image& o) const {
    if (rows_ != o.rows_ || cols_ != o.cols_ || format_ != o.format_) return false;
    const size_t bytes = size_t(cols_) * pixelBytes();
    for (int y = 0; y < rows_; ++y)
      if (std::memcmp(row(y), o.row(y), bytes) != 0) return false;
    return true;
  }

 private:
  std::shared_ptr<uint8_t[]> owner_;  // null for a view
  uint8_t* data_ = nullptr;
  int rows_ = 0, cols_ = 0;
  PixelFormat format_ = PixelFormat::kBgr8;
  size_t step_ = 0;
};

}  // namespace zrender
