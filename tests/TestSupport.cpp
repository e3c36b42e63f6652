#include "TestSupport.hpp"

#include <filesystem>
#include <random>

#include "zrender/ObjLoader.hpp"

namespace zrender::test {

std::shared_ptr<const Mesh> makeMesh(const std::vector<Vec3>& positions,
                                     const std::vector<std::vector<int>>& faces) {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = positions;
  mesh->faceStart.push_back(0);
  for (const auto& f : faces) {
    for (int i : f) mesh->corners.push_back(Corner{i, -1, -1});
    mesh->faceStart.push_back(uint32_t(mesh->corners.size()));
    mesh->faceMaterial.push_back(-1);
  }
  return mesh;
}

SceneSettings tinySettings(int size) {
  SceneSettings s;
  s.name = "tiny";
  s.width = s.height = size;
  s.eye = Vec3(0, 0, 2);
  s.target = Vec3(0, 0, 0);
  s.fovy = 90.0;
  s.near = 0.1;
  s.far = 10.0;
  return s;
}

Rendered render(const Scene& scene, const std::string& algorithm) {
  Renderer renderer(scene, algorithm);
  const Camera camera = makeCamera(scene);
  renderer.renderFrame(camera);
  return Rendered{renderer.buffer(), renderer.color().clone(), renderer.stats()};
}

Rendered render(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                const std::string& algorithm) {
  Warnings warnings;
  const Scene scene = makeScene(settings, std::move(mesh), warnings);
  return render(scene, algorithm);
}

std::shared_ptr<const Mesh> randomSoup(unsigned seed, int count, bool coplanarDuplicates) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  for (int t = 0; t < count; ++t) {
    if (coplanarDuplicates && t % 7 == 6) {
      faces.push_back(faces.back());
      continue;
    }
    const int base = int(positions.size());
    for (int i = 0; i < 3; ++i) positions.emplace_back(coord(rng), coord(rng), coord(rng));
    faces.push_back({base, base + 1, base + 2});
  }
  return makeMesh(positions, faces);
}

std::shared_ptr<const Mesh> referenceModel(const std::string& name) {
  const SceneSettings s = projectScene(name);
  if (!std::filesystem::exists(s.modelPath)) return nullptr;
  Warnings warnings;
  return std::make_shared<const Mesh>(loadObj(s.modelPath, warnings));
}

SceneSettings projectScene(const std::string& name) {
  Warnings warnings;
  const SettingsFile file = loadSettings(ZRENDER_SOURCE_DIR "/settings.json", warnings);
  return file.scenes.at(name);
}

size_t countDifferences(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a.data()[i] != b.data()[i];
  return n;
}

}  // namespace zrender::test
