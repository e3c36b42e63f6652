#pragma once

#include <memory>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/SceneSettings.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// The most faces a scene may have, all instances counted: face ids run from 0 to
// kMaxSceneFaces - 1 in the 32 bits of a key, and the id 0xFFFFFFFF is the background's
// (raster/RasterRules.hpp).
inline constexpr uint64_t kMaxSceneFaces = 0xFFFFFFFFu;

// Everything that depends on the model and the settings but not on the frame: the mesh, its
// grid instances and the diffuse texture. Built once, shared by all frames and algorithms.
struct Scene {
  SceneSettings settings;  // after command-line overrides and validation
  std::shared_ptr<const Mesh> mesh;
  std::vector<Vec3>
      instanceOffsets;         // grid offset of instance k, model units (docs/design.md, Settings)
  cv::Mat texture;             // 8-bit BGR, or empty
  Vec3 boundsCentre{0, 0, 0};  // bounding sphere of all instances after rotation
  double boundsRadius = 0.0;
  Box3 meshBox;  // the mesh's box, model space (before the rotation)

  uint32_t instanceCount() const { return uint32_t(instanceOffsets.size()); }
  uint32_t faceCount() const { return uint32_t(mesh->faceCount()) * instanceCount(); }
  // Model matrix of instance k: the rotation, then the grid offset.
  Mat4 modelMatrix(uint32_t instance) const;
};

// Builds the instances and bounds (InputError when the scene has more than kMaxSceneFaces);
// `texture` (8-bit BGR, or empty) is the scene's diffuse texture, as io's loadTexture() reads it.
Scene makeScene(const SceneSettings& settings, std::shared_ptr<const Mesh> mesh,
                cv::Mat texture = cv::Mat());

// Number of triangles the faces make once triangulated (n - 2 per face of n >= 3 corners),
// all instances included.
uint64_t triangleCount(const Scene& scene);

}  // namespace zrender
