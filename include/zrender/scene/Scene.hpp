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

// One model file's part of the scene's mesh: its faces and positions, one range each.
struct SceneModel {
  uint32_t faceBegin = 0, faceEnd = 0;
  uint32_t positionBegin = 0, positionEnd = 0;
  Box3 box;  // of its positions, model space
};

// The meshes of a scene's distinct model files, one after another in one mesh: each read once,
// however many objects place it.
struct SceneMeshes {
  std::shared_ptr<const Mesh> mesh;
  std::vector<SceneModel> models;
};
// Joins `meshes` in their order (materials and colors included); one mesh is kept as it is.
SceneMeshes joinMeshes(const std::vector<std::shared_ptr<const Mesh>>& meshes);

// A model placed in the world: an object of the scene in a cell of its grid.
struct SceneInstance {
  Mat4 model;                         // model space to world space
  uint32_t part = 0;                  // index into Scene::models
  uint32_t firstId = 0;               // face id of the part's first face here
  bool colored = false;               // its object gives its faces' base color
  cv::Vec3f color{0.0f, 0.0f, 0.0f};  // linear 0..1 RGB
  int32_t texture = -1;               // into Scene::objectTextures: its object's texture, else -1
};

// A face id's instance and its face in the mesh.
struct FaceRef {
  uint32_t instance;
  uint32_t meshFace;
};

// Everything that depends on the models and the settings but not on the frame: the mesh, its
// instances and the diffuse texture. Built once, shared by all frames and algorithms.
struct Scene {
  SceneSettings settings;  // after command-line overrides and validation
  std::shared_ptr<const Mesh> mesh;
  std::vector<SceneModel> models;
  // Grid cell after grid cell (docs/design.md, Settings), the objects in list order in each; face
  // ids count on in the same order.
  std::vector<SceneInstance> instances;
  // Every instance is the whole mesh (one model file, a grid of it): a face id's instance is
  // id / mesh faces.
  bool uniform = true;
  cv::Mat texture;  // the `texture` key's image (8-bit BGR): every textured face's; or empty
  std::vector<cv::Mat> materialTextures;  // per mesh material: its texture (8-bit BGR), or empty
  std::vector<cv::Mat> objectTextures;    // the objects' own textures (SceneInstance::texture)
  Vec3 boundsCentre{0, 0, 0};             // bounding sphere of all instances, world space
  double boundsRadius = 0.0;

  uint32_t instanceCount() const { return uint32_t(instances.size()); }
  uint32_t faceCount() const { return faceCount_; }
  const Mat4& modelMatrix(uint32_t instance) const { return instances[instance].model; }
  const SceneModel& modelOf(uint32_t instance) const { return models[instances[instance].part]; }
  // The texture mesh face f is drawn with: the scene's, else its material's; empty for none.
  // An instance's object texture (SceneInstance::texture) comes before the material's.
  const cv::Mat& textureOf(uint32_t meshFace) const;
  const cv::Mat& textureOf(const SceneInstance& instance, uint32_t meshFace) const;
  // The instance and mesh face of a face id (< faceCount()).
  FaceRef locate(uint32_t faceId) const {
    if (uniform) {
      const uint32_t k = faceId / meshFaces_;
      return {k, faceId - k * meshFaces_};
    }
    return locateSearch(faceId);
  }

  // Sets the instances' face ids, face count and look-up; InputError past kMaxSceneFaces.
  void numberFaces();

 private:
  FaceRef locateSearch(uint32_t faceId) const;

  uint32_t faceCount_ = 0;
  uint32_t meshFaces_ = 1;
};

// The scene of one model: `settings`' grid of the mesh rotated by its angle and axis. Throws
// InputError when the scene has more than kMaxSceneFaces. `texture` (8-bit BGR, or empty) is the
// texture of every face that has texture coordinates, as a `texture` key gives it; the
// materials' own (materialTextures) are set by io's loadScene().
Scene makeScene(const SceneSettings& settings, std::shared_ptr<const Mesh> mesh,
                cv::Mat texture = cv::Mat());
// The scene of `settings.objects`, object o showing model objectModel[o] of `meshes`: its
// model matrix is the grid offset, then the scene's rotation, then the object's placement.
Scene makeScene(const SceneSettings& settings, SceneMeshes meshes,
                const std::vector<uint32_t>& objectModel, cv::Mat texture = cv::Mat());

// Number of triangles the faces make once triangulated (n - 2 per face of n >= 3 corners),
// all instances included.
uint64_t triangleCount(const Scene& scene);

}  // namespace zrender
