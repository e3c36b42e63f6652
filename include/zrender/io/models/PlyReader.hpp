#pragma once

#include <string>
#include <string_view>

#include "zrender/scene/Mesh.hpp"

namespace zrender {

// Reads a PLY file's bytes (ASCII, or binary of either byte order): the `vertex` element's x, y,
// z, and where present nx, ny, nz, texture coordinates (s, t or u, v or texture_u, texture_v)
// and colors (red, green, blue: uchar as n / 255, float as given); the `face` element's
// vertex_indices (or vertex_index) list, a face per entry in file order. Other elements and
// properties are read past. Throws InputError naming `file` (and the header line) for a
// malformed header, a body cut short, an index out of range or a face above kMaxFaceCorners.
// zrender's own rather than assimp's: docs/design.md, Model formats, says why.
Mesh readPly(std::string_view bytes, const std::string& file);

}  // namespace zrender
