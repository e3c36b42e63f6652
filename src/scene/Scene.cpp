#include "zrender/scene/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "zrender/base/Error.hpp"

namespace zrender {

Mat4 Scene::modelMatrix(uint32_t instance) const {
  return translation(instanceOffsets[instance]) * rotation(settings.angle, settings.axis);
}

namespace {

std::vector<Vec3> gridOffsets(const SceneSettings& s) {
  if (!s.grid) return {Vec3(0, 0, 0)};
  const Grid& g = *s.grid;
  std::vector<Vec3> offsets;
  offsets.reserve(size_t(g.instanceCount()));
  // Instance (i, j, k) is numbered i fastest, then j, then k (docs/design.md, Settings).
  for (int k = 0; k < g.count[2]; ++k)
    for (int j = 0; j < g.count[1]; ++j)
      for (int i = 0; i < g.count[0]; ++i)
        offsets.emplace_back((i - (g.count[0] - 1) / 2.0) * g.spacing[0],
                             (j - (g.count[1] - 1) / 2.0) * g.spacing[1],
                             (k - (g.count[2] - 1) / 2.0) * g.spacing[2]);
  return offsets;
}

}  // namespace

Scene makeScene(const SceneSettings& settings, std::shared_ptr<const Mesh> mesh, cv::Mat texture) {
  // Face ids count across instances (docs/design.md, Faces, ids and shading): checked in 64
  // bits before any id is made.
  const uint64_t instances = settings.grid ? uint64_t(settings.grid->instanceCount()) : 1;
  const uint64_t faces = uint64_t(mesh->faceCount()) * instances;
  if (faces > kMaxSceneFaces) {
    throw InputError("scene '" + settings.name + "': " + std::to_string(mesh->faceCount()) +
                     " faces x " + std::to_string(instances) +
                     " instances = " + std::to_string(faces) + " faces, over the " +
                     std::to_string(kMaxSceneFaces) + " face ids a frame can tell apart");
  }
  Scene scene;
  scene.settings = settings;
  scene.mesh = std::move(mesh);
  scene.instanceOffsets = gridOffsets(settings);
  scene.meshBox = boundingBox(scene.mesh->positions);

  // Bounding sphere: centre of the bounding box of all instances, radius to the farthest
  // vertex. Instances only translate, so the extreme instances are the corners of the grid.
  const Mat4 rot = rotation(settings.angle, settings.axis);
  std::vector<Vec3> rotated;
  rotated.reserve(scene.mesh->positions.size());
  for (const Vec3& p : scene.mesh->positions) rotated.push_back(transformPoint(rot, p));
  const Box3 box = boundingBox(rotated);
  Vec3 offLo = scene.instanceOffsets.front(), offHi = scene.instanceOffsets.back();
  for (int a = 0; a < 3; ++a) {
    if (offLo[a] > offHi[a]) std::swap(offLo[a], offHi[a]);
  }
  if (!rotated.empty()) {
    scene.boundsCentre = ((box.lo + offLo) + (box.hi + offHi)) * 0.5;
    // The farthest of the 8 extreme instances for each vertex, axis by axis: the squared
    // distance is a sum over the axes, whose terms each pick the larger of two offsets, and a
    // rounded sum never shrinks when a term grows, so this is the 8 corners' largest exactly.
    double r2 = 0.0;
    for (const Vec3& p : rotated) {
      double d2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double lo = (p[a] + offLo[a]) - scene.boundsCentre[a];
        const double hi = (p[a] + offHi[a]) - scene.boundsCentre[a];
        d2 += std::max(lo * lo, hi * hi);
      }
      r2 = std::max(r2, d2);
    }
    scene.boundsRadius = std::sqrt(r2);
  }

  scene.texture = std::move(texture);
  return scene;
}

uint64_t triangleCount(const Scene& scene) {
  uint64_t n = 0;
  const Mesh& m = *scene.mesh;
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const uint32_t c = m.cornerCount(f);
    if (c >= 3) n += c - 2;
  }
  return n * scene.instanceCount();
}

}  // namespace zrender
