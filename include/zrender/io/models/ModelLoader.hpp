#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/models/ModelFormats.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {

// The model file at `path`, in the format its extension names (io/models/ModelFormats.hpp):
// OBJ by zrender's reader (io/obj/ObjLoader.hpp, parsed in parts on `threads`), the others by
// assimp in its plugin. Throws InputError for: an extension zrender does not read, content that
// is not of that format ("not a PLY file (looks like a PNG image)"), a file its reader refuses,
// a NaN or infinite coordinate, a face above kMaxFaceCorners corners, or no faces.
Mesh loadModel(const std::filesystem::path& path, Warnings& warnings,
               const Threads* threads = nullptr);

// The same on bytes already in memory (the fuzz targets), named `nameForMessages`; the files a
// model names (glTF buffers, textures) are not read.
Mesh readModel(std::string_view bytes, const std::string& nameForMessages, ModelFormat format,
               Warnings& warnings);

}  // namespace zrender
