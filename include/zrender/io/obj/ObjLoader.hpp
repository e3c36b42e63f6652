#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {

// Largest polygon accepted, in corners. Window-space ear clipping is quadratic in the corner
// count, so larger faces are refused with an InputError instead of stalling.
constexpr uint32_t kMaxFaceCorners = 4096;

// Bytes of OBJ text per part of the parse: a part is a task, and parts of about this size keep
// a task's overhead (microseconds) a small fraction of its parse (a few hundred microseconds).
constexpr size_t kObjPartBytes = size_t(256) << 10;

// Reads a Wavefront OBJ file (and the MTL files it names, through tinyobjloader), keeping faces
// as polygons; parts of the text are parsed at once on `threads` (null: the calling thread).
// Throws InputError naming the file and line for: a missing or unreadable file, a malformed
// line, an index out of range (0, past the end, negative before the start), a NaN or infinite
// coordinate, a face above kMaxFaceCorners, or a model with no faces. A missing .mtl or texture
// file is a warning. Faces with fewer than 3 corners are kept (they get a face id) and are
// skipped as degenerate when drawn.
Mesh loadObj(const std::filesystem::path& path, Warnings& warnings,
             const Threads* threads = nullptr);

// The same loader on OBJ text already in memory (the fuzz targets use it): `nameForMessages`
// starts every message, and the .mtl files named by mtllib are looked up beside it. loadObj is
// this function after reading the file.
Mesh loadObjFromText(std::string_view text, const std::filesystem::path& nameForMessages,
                     Warnings& warnings, const Threads* threads = nullptr,
                     size_t partBytes = kObjPartBytes);

}  // namespace zrender
