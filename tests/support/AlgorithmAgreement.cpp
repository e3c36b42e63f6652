#include "support/AlgorithmAgreement.hpp"

#include <gtest/gtest.h>

#include "../fuzz/RenderCase.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace zrender::test {

const std::vector<std::string> kPyramidAlgorithms = {"hierarchical", "octree"};
const std::vector<std::string> kScanlineAlgorithms = {"scanline", "interval"};

Compared expectSameAsZBuffer(const Scene& scene, const std::vector<std::string>& algorithms,
                             const std::string& what) {
  Compared out;
  const Rendered ref = render(scene, "zbuffer");
  out.covered = coveredSamples(ref.buffer);
  for (const std::string& alg : algorithms) {
    const Rendered r = render(scene, alg);
    expectSameFrame(ref, r, alg + ", " + what);
    out.stats.push_back(r.stats);
  }
  return out;
}

Compared expectSameAsZBuffer(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                             const std::vector<std::string>& algorithms, const std::string& what) {
  Warnings warnings;
  const Scene scene = makeScene(settings, std::move(mesh));
  return expectSameAsZBuffer(scene, algorithms, what);
}

std::shared_ptr<const Mesh> referenceScene(const std::string& name, int size,
                                           SceneSettings& settings) {
  auto mesh = referenceModel(name);
  if (!mesh) return nullptr;
  settings = projectScene(name);
  settings.width = settings.height = size;
  return mesh;
}

uint64_t extraCounter(const RenderStats& stats, const std::string& name) {
  for (const auto& [n, value] : stats.extra)
    if (n == name) return value;
  return 0;
}

uint64_t intervalCounter(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                         const std::string& name) {
  return extraCounter(render(std::move(mesh), settings, "interval").stats, name);
}

Rendered expectAgreement(const std::string& obj, const SceneSettings& settings) {
  Warnings warnings;
  auto mesh = std::make_shared<const Mesh>(loadObjFromText(obj, "case.obj", warnings));
  const Scene scene = makeScene(settings, mesh);
  EXPECT_EQ(fuzz::checkAlgorithmsAgree(scene, true), "");
  return render(scene, "zbuffer");
}

bool allBackground(const FrameBuffer& buffer) {
  for (size_t i = 0; i < buffer.size(); ++i) {
    if (keyFaceId(buffer.data()[i]) != kBackgroundId) return false;
  }
  return true;
}

}  // namespace zrender::test
