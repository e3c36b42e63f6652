#pragma once

#include "zrender/base/Error.hpp"
#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/SceneSettings.hpp"

namespace zrender {

class Threads;

// The scene's diffuse texture (8-bit BGR): its `texture` key, else the first material's
// map_Kd; empty when there is none. A `texture` key naming a file that cannot be read is bad
// input (InputError); a material's map_Kd that cannot be read is a warning, and the model is
// drawn without it.
cv::Mat loadTexture(const SceneSettings& settings, const Mesh& mesh, Warnings& warnings);

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
