#include "zrender/scene/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "zrender/base/Error.hpp"

namespace zrender {

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

SceneModel wholeMesh(const Mesh& mesh) {
  SceneModel m;
  m.faceEnd = uint32_t(mesh.faceCount());
  m.positionEnd = uint32_t(mesh.positions.size());
  m.box = boundingBox(mesh.positions);
  return m;
}

// Bounding sphere of one model's grid, as a grid's instances only translate: centre of the box
// of all instances, radius to the farthest vertex, exactly.
void gridBounds(Scene& scene, const std::vector<Vec3>& offsets) {
  const Mat4 rot = rotation(scene.settings.angle, scene.settings.axis);
  std::vector<Vec3> rotated;
  rotated.reserve(scene.mesh->positions.size());
  for (const Vec3& p : scene.mesh->positions) rotated.push_back(transformPoint(rot, p));
  if (rotated.empty()) return;
  const Box3 box = boundingBox(rotated);
  Vec3 offLo = offsets.front(), offHi = offsets.back();
  for (int a = 0; a < 3; ++a) {
    if (offLo[a] > offHi[a]) std::swap(offLo[a], offHi[a]);
  }
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

// The same for instances of any placement, from the corners of each instance's model box in
// world space: a sphere that holds every vertex, without a pass over the vertices of every
// instance (a scene of many objects is framed as quickly as its models are read).
void instanceBounds(Scene& scene) {
  std::vector<Vec3> corners;
  corners.reserve(scene.instances.size() * 8);
  for (const SceneInstance& instance : scene.instances) {
    const SceneModel& m = scene.models[instance.part];
    if (m.positionBegin == m.positionEnd) continue;
    for (int c = 0; c < 8; ++c) {
      const Vec3 p(c & 1 ? m.box.hi[0] : m.box.lo[0], c & 2 ? m.box.hi[1] : m.box.lo[1],
                   c & 4 ? m.box.hi[2] : m.box.lo[2]);
      corners.push_back(transformPoint(instance.model, p));
    }
  }
  if (corners.empty()) return;
  const Box3 box = boundingBox(corners);
  scene.boundsCentre = box.centre();
  double r2 = 0.0;
  for (const Vec3& p : corners) {
    const Vec3 d = p - scene.boundsCentre;
    r2 = std::max(r2, d.dot(d));
  }
  scene.boundsRadius = std::sqrt(r2);
}

Mat4 scaling(const Vec3& s) {
  return Mat4(s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1);
}

}  // namespace

SceneMeshes joinMeshes(const std::vector<std::shared_ptr<const Mesh>>& meshes) {
  SceneMeshes joined;
  if (meshes.size() == 1) {
    joined.mesh = meshes.front();
    joined.models.push_back(wholeMesh(*joined.mesh));
    return joined;
  }
  auto mesh = std::make_shared<Mesh>();
  bool colors = false;
  for (const auto& m : meshes) colors |= !m->faceColors.empty();
  mesh->faceStart.push_back(0);
  for (const auto& part : meshes) {
    const Mesh& m = *part;
    SceneModel model;
    model.faceBegin = uint32_t(mesh->faceCount());
    model.positionBegin = uint32_t(mesh->positions.size());
    const int32_t positions = int32_t(mesh->positions.size()),
                  texcoords = int32_t(mesh->texcoords.size()),
                  normals = int32_t(mesh->normals.size()),
                  materials = int32_t(mesh->materials.size());
    const uint32_t corners = uint32_t(mesh->corners.size());
    mesh->positions.insert(mesh->positions.end(), m.positions.begin(), m.positions.end());
    mesh->texcoords.insert(mesh->texcoords.end(), m.texcoords.begin(), m.texcoords.end());
    mesh->normals.insert(mesh->normals.end(), m.normals.begin(), m.normals.end());
    mesh->materials.insert(mesh->materials.end(), m.materials.begin(), m.materials.end());
    for (Corner c : m.corners) {
      c.position += positions;
      if (c.texcoord >= 0) c.texcoord += texcoords;
      if (c.normal >= 0) c.normal += normals;
      mesh->corners.push_back(c);
    }
    for (size_t f = 0; f < m.faceCount(); ++f) {
      mesh->faceStart.push_back(corners + m.faceStart[f + 1]);
      const int32_t material = f < m.faceMaterial.size() ? m.faceMaterial[f] : -1;
      mesh->faceMaterial.push_back(material >= 0 ? material + materials : -1);
      if (colors) {
        mesh->faceColors.push_back(!m.faceColors.empty() ? m.faceColors[f]
                                   : material >= 0       ? m.materials[size_t(material)].diffuse
                                                         : cv::Vec3f(0.8f, 0.8f, 0.8f));
      }
    }
    model.faceEnd = uint32_t(mesh->faceCount());
    model.positionEnd = uint32_t(mesh->positions.size());
    model.box = boundingBox(m.positions);
    joined.models.push_back(model);
  }
  joined.mesh = std::move(mesh);
  return joined;
}

void Scene::numberFaces() {
  meshFaces_ = std::max<uint32_t>(1, uint32_t(mesh->faceCount()));
  uniform = true;
  uint64_t faces = 0;
  for (SceneInstance& instance : instances) {
    const SceneModel& m = models[instance.part];
    uniform &= m.faceBegin == 0 && m.faceEnd == mesh->faceCount();
    instance.firstId = uint32_t(std::min<uint64_t>(faces, kMaxSceneFaces));
    faces += m.faceEnd - m.faceBegin;
  }
  // Face ids count across instances (docs/design.md, Faces, ids and shading): checked in 64
  // bits before any id is used.
  if (faces > kMaxSceneFaces) {
    throw InputError("scene '" + settings.name + "': " + std::to_string(instances.size()) +
                     " instances make " + std::to_string(faces) + " faces, over the " +
                     std::to_string(kMaxSceneFaces) + " face ids a frame can tell apart");
  }
  faceCount_ = uint32_t(faces);
}

const cv::Mat& Scene::textureOf(uint32_t meshFace) const {
  static const cv::Mat none;
  if (!texture.empty()) return texture;
  const int32_t material = meshFace < mesh->faceMaterial.size() ? mesh->faceMaterial[meshFace] : -1;
  if (material < 0 || size_t(material) >= materialTextures.size()) return none;
  return materialTextures[size_t(material)];
}

const cv::Mat& Scene::textureOf(const SceneInstance& instance, uint32_t meshFace) const {
  if (texture.empty() && instance.texture >= 0) return objectTextures[size_t(instance.texture)];
  return textureOf(meshFace);
}

FaceRef Scene::locateSearch(uint32_t faceId) const {
  const auto after = std::upper_bound(
      instances.begin(), instances.end(), faceId,
      [](uint32_t id, const SceneInstance& instance) { return id < instance.firstId; });
  const uint32_t k = uint32_t(after - instances.begin()) - 1;
  return {k, models[instances[k].part].faceBegin + (faceId - instances[k].firstId)};
}

Scene makeScene(const SceneSettings& settings, std::shared_ptr<const Mesh> mesh, cv::Mat texture) {
  const uint64_t cells = settings.grid ? uint64_t(settings.grid->instanceCount()) : 1;
  const uint64_t faces = uint64_t(mesh->faceCount()) * cells;
  if (faces > kMaxSceneFaces) {
    throw InputError("scene '" + settings.name + "': " + std::to_string(mesh->faceCount()) +
                     " faces x " + std::to_string(cells) + " instances = " + std::to_string(faces) +
                     " faces, over the " + std::to_string(kMaxSceneFaces) +
                     " face ids a frame can tell apart");
  }
  Scene scene;
  scene.settings = settings;
  scene.mesh = std::move(mesh);
  scene.models.push_back(wholeMesh(*scene.mesh));
  const std::vector<Vec3> offsets = gridOffsets(settings);
  const Mat4 rot = rotation(settings.angle, settings.axis);
  for (const Vec3& offset : offsets) {
    SceneInstance instance;
    instance.model = translation(offset) * rot;  // the rotation, then the grid offset
    scene.instances.push_back(instance);
  }
  scene.numberFaces();
  gridBounds(scene, offsets);
  scene.texture = std::move(texture);
  return scene;
}

Scene makeScene(const SceneSettings& settings, SceneMeshes meshes,
                const std::vector<uint32_t>& objectModel, cv::Mat texture) {
  if (settings.objects.empty()) return makeScene(settings, meshes.mesh, std::move(texture));
  Scene scene;
  scene.settings = settings;
  scene.mesh = std::move(meshes.mesh);
  scene.models = std::move(meshes.models);
  const std::vector<Vec3> offsets = gridOffsets(settings);
  const Mat4 rot = rotation(settings.angle, settings.axis);
  std::vector<Mat4> placements;
  for (const SceneObject& o : settings.objects)
    placements.push_back(translation(o.translate) * rotation(o.angle, o.axis) * scaling(o.scale));
  uint64_t faces = 0;
  for (size_t o = 0; o < settings.objects.size(); ++o) {
    const SceneModel& m = scene.models[objectModel[o]];
    faces += uint64_t(m.faceEnd - m.faceBegin);
  }
  if (faces * offsets.size() > kMaxSceneFaces) {
    throw InputError(
        "scene '" + settings.name + "': " + std::to_string(faces) + " faces x " +
        std::to_string(offsets.size()) + " grid cells = " + std::to_string(faces * offsets.size()) +
        " faces, over the " + std::to_string(kMaxSceneFaces) + " face ids a frame can tell apart");
  }
  for (const Vec3& offset : offsets) {
    const Mat4 cell = translation(offset) * rot;
    for (size_t o = 0; o < settings.objects.size(); ++o) {
      SceneInstance instance;
      instance.model = cell * placements[o];
      instance.part = objectModel[o];
      if (settings.objects[o].color) {
        instance.colored = true;
        instance.color = cv::Vec3f(*settings.objects[o].color);
      }
      scene.instances.push_back(instance);
    }
  }
  scene.numberFaces();
  instanceBounds(scene);
  scene.texture = std::move(texture);
  return scene;
}

uint64_t triangleCount(const Scene& scene) {
  const Mesh& m = *scene.mesh;
  std::vector<uint64_t> perModel;
  for (const SceneModel& model : scene.models) {
    uint64_t n = 0;
    for (uint32_t f = model.faceBegin; f < model.faceEnd; ++f) {
      const uint32_t c = m.cornerCount(f);
      if (c >= 3) n += c - 2;
    }
    perModel.push_back(n);
  }
  uint64_t n = 0;
  for (const SceneInstance& instance : scene.instances) n += perModel[instance.part];
  return n;
}

}  // namespace zrender
