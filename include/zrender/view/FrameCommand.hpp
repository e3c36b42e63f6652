#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "zrender/scene/Camera.hpp"
#include "zrender/scene/SceneSettings.hpp"
#include "zrender/view/ViewControls.hpp"

namespace zrender {

// The `zrender SCENE ...` command line that renders exactly the frame the viewer rendered with
// `state` and `camera`: the algorithm, shading, MSAA and culling, the size, and every camera and
// model-rotation value with 17 significant digits, which parse back to the same doubles. `fit`
// is turned off (--no-fit) where the scene had it, since the camera is given in full. `scene` and
// `settingsFile` are as the user typed them; arguments a shell would split are quoted.
std::string frameCommand(const std::string& scene,
                         const std::optional<std::filesystem::path>& settingsFile,
                         const SceneSettings& settings, const ViewState& state,
                         const Camera& camera);

}  // namespace zrender
