#pragma once

#include "zrender/scene/Scene.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// The per-frame camera: view and projection (docs/design.md, Camera and transforms) and the image
// size in samples.
struct Camera {
  Vec3 eye, target, up;          // world space
  double fovy = 45.0;            // degrees
  double aspect = 1.0;           // width / height of the view
  double near = 0.1, far = 100;  // positive distances
  Mat4 view = Mat4::eye();
  Mat4 projection = Mat4::eye();
  int width = 0, height = 0;  // pixels
};

// The camera of a scene, with `fit` applied when it is on (docs/design.md, Camera and
// transforms, and The camera rule): fit moves the target to the model's bounding sphere, the eye
// along the viewing direction until the sphere fits the smaller field of view with a 5% margin,
// and near and far to hug the sphere, except for what scene.settings.fitKeeps keeps as given. A
// scene without `eye` looks down -Z. Throws InputError when what is kept and what fit supplies
// do not make a camera (a near beyond fit's far, an eye at the model's centre).
Camera makeCamera(const Scene& scene);
// The same with the camera values of `settings` in place of the scene's own.
Camera makeCamera(const Scene& scene, const SceneSettings& settings);

// The camera of turntable frame at `degrees`: the model turned about the camera's up axis
// through the target (right-hand rule), which is the view composed with that rotation.
Camera turntableCamera(const Camera& camera, double degrees);

// The camera of view `view` of a run (docs/design.md, Views): `base` (the scene's camera), or
// the scene's camera with the view's eye, target and up when it gives any, turned about its
// target and zoomed. `where` names the view in messages ("settings.json: scene 'bunny': key
// 'views[2]'"); InputError when the view's camera values do not make a camera.
Camera viewCamera(const Scene& scene, const Camera& base, const ViewSpec& view,
                  const std::string& where);

}  // namespace zrender
