#pragma once

#include <string>
#include <string_view>

#include "zrender/scene/Mesh.hpp"

namespace zrender {

// Reads an STL file's bytes, binary (an 80-byte header, a count, 50 bytes per triangle) or ASCII
// (solid, facet, outer loop, vertex lines): a face per facet in file order, solid after solid,
// corners at equal positions joined into one vertex (io/models/PositionIndex.hpp). Facet normals
// are not kept: they are the faces' own, which zrender computes. Throws InputError naming `file`
// (and the line) for a malformed number, a facet outside a loop's grammar or no facets' room.
// zrender's own rather than assimp's: docs/design.md, Model formats, says why.
Mesh readStl(std::string_view bytes, const std::string& file);

}  // namespace zrender
