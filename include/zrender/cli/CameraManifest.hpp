#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <json/json.h>

#include "zrender/cli/RenderOutputs.hpp"
#include "zrender/scene/Camera.hpp"

namespace zrender {

// The camera manifest of a run (--cameras; docs/design.md, Camera manifest): every view's
// files and camera in the transforms.json form that instant-ngp and nerfstudio read (w, h,
// fl_x, fl_y, cx, cy, camera_angle_x and per frame file_path and a camera-to-world
// transform_matrix, OpenGL axes), and per frame zrender's own near, far, projection matrix and
// depth, id and normal files. Paths are relative to the manifest's folder. The same, byte for
// byte, whichever part of the run writes it: it holds every view.
Json::Value cameraManifest(const std::vector<Camera>& cameras, const RenderOutputs& outputs,
                           const std::filesystem::path& manifest, int msaa);

// The manifest as its file holds it: indented JSON and a final newline.
std::string manifestText(const Json::Value& manifest);

}  // namespace zrender
