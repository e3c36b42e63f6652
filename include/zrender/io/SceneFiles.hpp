#pragma once

#include "zrender/base/Error.hpp"
#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/SceneSettings.hpp"

namespace zrender {

class Threads;

// The scene's `texture` key's image (8-bit BGR), empty without one; a file that cannot be read
// is bad input (InputError).
cv::Mat loadTexture(const SceneSettings& settings);
// Each material's texture (8-bit BGR; map_Kd, glTF's base color texture times its factor,
// embedded images), empty where it has none; a file used by several materials is read once. One
// that cannot be read is a warning, and its faces are drawn without it.
std::vector<cv::Mat> loadMaterialTextures(const Mesh& mesh, Warnings& warnings);

// The scene of `settings`: its model file (or its objects' files), its texture, its instances.
// Throws InputError. With `threads` (more than one), a `texture` key's image is read while the
// model loads.
Scene loadScene(const SceneSettings& settings, Warnings& warnings,
                const Threads* threads = nullptr);
// The scene of `settings.objects`: each distinct file read once, then joined into one mesh that
// the objects' instances share.
Scene loadObjects(const SceneSettings& settings, Warnings& warnings,
                  const Threads* threads = nullptr);

}  // namespace zrender
