#include "zrender/measure/RowOcclusion.hpp"

#include <algorithm>
#include <map>

#include "zrender/measure/KeptTriangles.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

namespace zrender {

namespace {

// Samples of `fb` owned by each of the `rowCount` rows (kBackgroundId: none).
std::vector<size_t> samplesPerRow(const FrameBuffer& fb, const std::vector<uint32_t>& rowOfFace,
                                  size_t rowCount) {
  std::vector<size_t> samples(rowCount);
  for (size_t i = 0; i < fb.size(); ++i) {
    const uint32_t id = keyFaceId(fb.data()[i]);
    if (id != kBackgroundId) ++samples[rowOfFace[id]];
  }
  return samples;
}

}  // namespace

std::vector<RowOcclusion> measureRowOcclusion(const Scene& scene, const Camera& camera) {
  // Rows by offset along z; each one's distance from the eye along the view direction.
  // A grid instance's offset is its model matrix's translation.
  const auto offset = [&](uint32_t k) {
    const Mat4& m = scene.modelMatrix(k);
    return Vec3(m(0, 3), m(1, 3), m(2, 3));
  };
  std::map<double, std::vector<uint32_t>> instancesAt;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) instancesAt[offset(k)[2]].push_back(k);
  const Vec3 forward = cv::normalize(camera.target - camera.eye);
  struct Row {
    double offsetZ, distance;
    std::vector<uint32_t> instances;
  };
  std::vector<Row> rows;
  for (const auto& [z, instances] : instancesAt) {
    Vec3 mean(0, 0, 0);
    for (uint32_t k : instances) mean += offset(k);
    mean *= 1.0 / double(instances.size());
    rows.push_back(Row{z, (mean - camera.eye).dot(forward), instances});
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.distance < b.distance; });

  std::vector<uint32_t> rowOfFace(scene.faceCount());
  for (uint32_t r = 0; r < rows.size(); ++r) {
    for (uint32_t k : rows[r].instances) {
      const SceneModel& m = scene.modelOf(k);
      std::fill_n(rowOfFace.begin() + scene.instances[k].firstId, m.faceEnd - m.faceBegin, r);
    }
  }

  Renderer renderer(scene, "zbuffer");
  renderer.renderFrame(camera);
  const std::vector<size_t> visible = samplesPerRow(renderer.buffer(), rowOfFace, rows.size());
  std::vector<RowOcclusion> result;
  for (uint32_t r = 0; r < rows.size(); ++r) {
    Renderer alone(scene, std::make_unique<ZBufferAlgorithm>(),
                   [&rowOfFace, r](GeometrySource& transform, FaceBatches) {
                     return std::make_unique<KeptTriangles>(
                         transform,
                         [&rowOfFace, r](const ScreenTriangle& t) { return rowOfFace[t.id] == r; });
                   });
    alone.renderFrame(camera);
    const std::vector<size_t> samples = samplesPerRow(alone.buffer(), rowOfFace, rows.size());
    result.push_back(RowOcclusion{rows[r].offsetZ, samples[r], visible[r]});
  }
  return result;
}

}  // namespace zrender
