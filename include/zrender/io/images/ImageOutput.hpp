#pragma once

#include <filesystem>

#include <opencv2/core/mat.hpp>

#include "zrender/raster/FrameBuffer.hpp"

namespace zrender {

class Threads;

// Throws InputError unless `path` ends in one of `allowed` (e.g. {".png", ".tif"}), so that a
// bad output name fails before any rendering.
void checkOutputExtension(const std::filesystem::path& path,
                          std::initializer_list<const char*> allowed, const char* what);

// The extensions -o accepts.
std::initializer_list<const char*> colorExtensions();

// Writes an image completely or not at all, as an OutputFile (io/OutputFile.hpp); missing
// parent folders are created. InputError on failure. A PNG is encoded by `threads` when there
// are several (null: one thread); the other formats are encoded in memory, then written.
void writeImageAtomically(const std::filesystem::path& path, const cv::Mat& image,
                          const Threads* threads = nullptr);

// The depth buffer at pixel resolution (with MSAA, each pixel's nearest sample): float in 0..1
// for .tif/.exr, 16-bit round(depth * 65535) for .png (near = dark); background is 1.
cv::Mat depthImage(const FrameBuffer& fb, int sampleScale, bool sixteenBit);

// Face id + 1 in 24 bits per pixel, R = low byte, G = middle, B = high (docs/design.md, Faces, ids
// and shading), as 8-bit BGR; 0 is background. With MSAA, each pixel's nearest sample.
cv::Mat idImage(const FrameBuffer& fb, int sampleScale);

}  // namespace zrender
