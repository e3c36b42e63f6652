#include "zrender/scene/ShadingMode.hpp"

#include <cstddef>

namespace zrender {

namespace {

// Same order as the enum and as docs/design.md, Faces, ids and shading, so an enum value indexes
// its name.
constexpr ShadingMode kModes[] = {ShadingMode::Normal, ShadingMode::Flat,    ShadingMode::Phong,
                                  ShadingMode::Random, ShadingMode::Texture, ShadingMode::Id,
                                  ShadingMode::Depth};

}  // namespace

const std::vector<std::string>& shadingModeNames() {
  static const std::vector<std::string> names{"normal",  "flat", "phong", "random",
                                              "texture", "id",   "depth"};
  return names;
}

std::optional<ShadingMode> parseShadingMode(const std::string& name) {
  const auto& names = shadingModeNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return kModes[i];
  }
  return std::nullopt;
}

std::string shadingModeName(ShadingMode mode) {
  const auto& names = shadingModeNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (kModes[i] == mode) return names[i];
  }
  return "unknown";  // only reachable with a value cast from outside the enum
}

}  // namespace zrender
