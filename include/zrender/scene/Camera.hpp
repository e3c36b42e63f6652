#pragma once

#include "zrender/scene/Scene.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// The per-frame camera: view and projection (SPEC §4) and the image size in samples.
struct Camera {
  Vec3 eye, target, up;          // world space
  double fovy = 45.0;            // degrees
  double aspect = 1.0;           // width / height of the view
  double near = 0.1, far = 100;  // positive distances
  Mat4 view = Mat4::eye();
  Mat4 projection = Mat4::eye();
  int width = 0, height = 0;  // pixels
};

// The camera of a scene, with `fit` applied (SPEC §4): the viewing direction and up are kept,
// the target moves to the bounding sphere's centre and the eye backs off until the sphere fits
// the smaller field of view with a 5% margin; near and far hug the sphere. A scene without
// `eye` looks down -Z.
Camera makeCamera(const Scene& scene);

// The camera of turntable frame at `degrees`: the model turned about the camera's up axis
// through the target (right-hand rule), which is the view composed with that rotation.
Camera turntableCamera(const Camera& camera, double degrees);

}  // namespace zrender
