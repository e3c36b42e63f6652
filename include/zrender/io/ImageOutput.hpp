#pragma once

#include <filesystem>

#include "zrender/base/Image.hpp"
#include "zrender/raster/FrameBuffer.hpp"

namespace zrender {

class Threads;

// Throws InputError unless `path` ends in one of `allowed` (e.g. {".png", ".tif"}), so that a
// bad output name fails before any rendering.
void checkOutputExtension(const std::filesystem::path& path,
                          std::initializer_list<const char*> allowed, const char* what);

// The extensions -o accepts.
std::initializer_list<const char*> colorExtensions();

// The hidden file ".STEM.TAG-PID.EXT" in the folder of `target`, for writing an output
// completely before renaming it into place: the same folder, so the rename is atomic; the
// same extension, so a codec chosen from it is the target's.
std::filesystem::path pathBeside(const std::filesystem::path& target, const char* tag);

// Moves the file `from` to `to` in one step (the same file system), replacing what is there,
// as std::filesystem::rename does; `ec` as its. A regular file at `to` is exchanged with
// `from` (RENAME_EXCHANGE) and then removed, rather than renamed over: ext4 starts writing the
// new file to disk inside a rename over an existing one (auto_da_alloc), 0.7 ms for a PNG of
// 760 KB on this machine (docs/design.md, Outputs).
void replaceFile(const std::filesystem::path& from, const std::filesystem::path& to,
                 std::error_code& ec);

// Fails now (InputError) if `path` could not be written later, so that a run that would fail
// at its end writes nothing: creates the missing parent folders (the write would), refuses a
// folder in the target's place, and creates a probe file beside the target, removed at once.
void checkWritable(const std::filesystem::path& path);

// Writes an image completely or not at all: encodes to a temporary file beside the target,
// then renames it over the target; missing parent folders are created. InputError on failure.
// A PNG is encoded by `threads` when there are several (null: one thread).
void writeImageAtomically(const std::filesystem::path& path, const Image& image,
                          const Threads* threads = nullptr);

// The depth buffer at pixel resolution (with MSAA, each pixel's nearest sample): float in 0..1
// for .tif/.exr, 16-bit round(depth * 65535) for .png (near = dark); background is 1.
Image depthImage(const FrameBuffer& fb, int sampleScale, bool sixteenBit);

// Face id + 1 in 24 bits per pixel, R = low byte, G = middle, B = high (docs/design.md, Faces, ids
// and shading), as 8-bit BGR; 0 is background. With MSAA, each pixel's nearest sample.
Image idImage(const FrameBuffer& fb, int sampleScale);

}  // namespace zrender
