#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

constexpr int kMaxImageSize = 16384;  // pixels, per side (docs/design.md, Command line)

// The model repeated as instances (docs/design.md, Settings: `grid`).
struct Grid {
  std::array<int, 3> count{1, 1, 1};  // nx, ny, nz >= 1
  cv::Vec3d spacing{0.0, 0.0, 0.0};   // model units
  int instanceCount() const { return count[0] * count[1] * count[2]; }
};

// One object of a scene of many (settings key `objects`, or a model file of several on the command
// line): a model file placed in the world by scale, then rotation, then translation.
struct SceneObject {
  SceneObject() = default;
  explicit SceneObject(std::filesystem::path file) : path(std::move(file)) {}

  std::filesystem::path path;          // resolved against the settings file's folder
  cv::Vec3d translate{0.0, 0.0, 0.0};  // world units
  double angle = 0.0;                  // degrees about axis
  cv::Vec3d axis{0.0, 1.0, 0.0};
  cv::Vec3d scale{1.0, 1.0, 1.0};
  std::optional<cv::Vec3d> color;  // linear 0..1 RGB: its faces' base color, else theirs
  std::optional<std::filesystem::path> texture;  // its faces' texture, else their materials'
};

// One view of a run (settings key `views`, --azimuth, --orbit: docs/design.md, Views). A camera
// value given replaces the scene's (and fit frames the view as it frames the scene, keeping what
// the view gives); then the eye turns about the target by `azimuth` about the up axis and by
// `elevation` toward it, and the image is magnified by `zoom`.
struct ViewSpec {
  std::optional<cv::Vec3d> eye, target, up;  // world space
  double azimuth = 0.0;                      // degrees, right-hand rule about up
  double elevation = 0.0;                    // degrees: positive raises the eye
  double zoom = 1.0;                         // > 0: the focal length times zoom
  bool givesCamera() const { return eye || target || up; }
};

// The camera values `fit` leaves as they are. A settings scene's "fit": true and --fit frame
// the model on their own (docs/design.md, Camera and transforms: none kept); a model file named on
// the command line is framed around the camera options the user typed (docs: the camera rule).
struct FitKeeps {
  bool eye = false, target = false, near = false, far = false;
};

// One scene of settings.json with every default (docs/design.md, Settings) filled in.
struct SceneSettings {
  std::string name;
  // What messages about its keys name: "settings.json: scene 'bunny'" (empty for a model file).
  std::string where;
  std::filesystem::path modelPath;  // resolved against the settings file's folder
  // A scene of many objects (docs/design.md, Settings: `objects`); when there are any, they are
  // the scene and modelPath is the first one's path (for messages).
  std::vector<SceneObject> objects;
  int width = 1024;  // pixels, 1..16384
  int height = 1024;
  std::optional<cv::Vec3d> eye;  // world space; required unless fit is on
  cv::Vec3d target{0.0, 0.0, 0.0};
  cv::Vec3d up{0.0, 1.0, 0.0};
  double angle = 0.0;  // degrees about axis
  cv::Vec3d axis{0.0, 1.0, 0.0};
  double fovy = 45.0;   // degrees, in (0, 180)
  double aspect = 0.0;  // <= 0 means width / height
  double near = 0.1;    // > 0 (sign of the file's value ignored)
  double far = 100.0;   // > near
  bool fit = false;
  FitKeeps fitKeeps;  // with fit: what it leaves as given
  ShadingMode shading = ShadingMode::Normal;
  int msaa = 1;  // 1 or 4
  bool cull = true;
  std::optional<std::filesystem::path> texture;  // overrides the material's map_Kd
  std::array<int, 3> background{0, 0, 0};        // r, g, b in 0..255
  std::optional<Grid> grid;
  std::vector<ViewSpec> views;  // none: the scene's camera alone
  bool bench = false;
};

}  // namespace zrender
