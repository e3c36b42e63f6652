#pragma once

#include <optional>
#include <string>
#include <vector>

namespace zrender {

enum class ShadingMode { Normal, Flat, Phong, Random, Texture, Id, Depth };

// The names of docs/design.md, Faces, ids and shading, in the order listed there.
const std::vector<std::string>& shadingModeNames();
std::optional<ShadingMode> parseShadingMode(const std::string& name);
std::string shadingModeName(ShadingMode mode);

}  // namespace zrender
