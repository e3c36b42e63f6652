#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zrender {

// The model formats zrender reads: OBJ by its own reader (io/obj), the others through assimp in
// a plugin (io/models/ModelPlugin.hpp). docs/design.md, Model formats, gives each format's face
// order.
enum class ModelFormat { Obj, Ply, Stl, Off, Gltf, Fbx, Collada, ThreeDs };

struct ModelFormatInfo {
  ModelFormat format;
  const char* name;                     // "ply": what messages and --formats call it
  const char* title;                    // "PLY": what "not a PLY file" says
  const char* description;              // a line for --formats
  std::vector<const char*> extensions;  // lower case, with the dot
};

// Every format, in the order --formats lists them.
const std::vector<ModelFormatInfo>& modelFormats();
const ModelFormatInfo& modelFormatInfo(ModelFormat format);

// The format of a file name's extension (any case); none when zrender reads no such format.
std::optional<ModelFormat> modelFormatOfPath(const std::filesystem::path& path);

// "obj, ply, stl, off, gltf, glb, fbx, dae, 3ds": the extensions zrender reads.
std::string modelExtensionList();

// The unsigned 32-bit little-endian number at byte `at` of `bytes` (at + 4 <= size).
uint32_t littleEndian32(std::string_view bytes, size_t at);

// Whether `bytes` (a whole file, or its first 84 bytes with `fileSize`) are a binary STL: an
// 80-byte header, a triangle count, then 50 bytes per triangle, exactly.
bool isBinaryStl(std::string_view bytes, uint64_t fileSize);

// What a file's first bytes (`head`, up to kModelHeadBytes of them) look like, for a file of
// `fileSize` bytes: the model format when they are one's, and words for a message ("a PNG
// image", "a PLY model", "text", "binary data").
inline constexpr size_t kModelHeadBytes = 4096;
struct ModelContent {
  std::optional<ModelFormat> format;
  std::string looksLike;
};
ModelContent sniffModelContent(std::string_view head, uint64_t fileSize);

// Throws InputError "FILE: not a PLY file (looks like a PNG image); zrender reads: obj, ..."
// when the content of `file` (its first bytes `head`, its size) is not of `format`. An OBJ is
// text without a signature, so it is refused only when its bytes are another known kind.
void checkModelContent(const std::string& file, ModelFormat format, std::string_view head,
                       uint64_t fileSize);

}  // namespace zrender
