#include "zrender/transform/MeshLayout.hpp"

namespace zrender {

MeshLayout::MeshLayout(const Scene& scene, FaceBatches batches) {
  const Mesh& mesh = *scene.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  constexpr uint32_t kUnseen = ~0u;
  std::vector<uint32_t> slotOf(mesh.positions.size(), kUnseen);
  std::vector<uint8_t> visited(nf, 0);
  cornerSlots_.resize(mesh.corners.size());
  auto visitFace = [&](uint32_t f) {
    if (visited[f]) return;
    visited[f] = 1;
    for (uint32_t i = mesh.faceStart[f]; i < mesh.faceStart[f + 1]; ++i) {
      const size_t position = size_t(mesh.corners[i].position);
      if (slotOf[position] == kUnseen) {
        slotOf[position] = uint32_t(slotPositions_.size());
        slotPositions_.push_back(mesh.positions[position]);
      }
      cornerSlots_[i] = slotOf[position];
    }
  };
  // The batches' faces by model, in batch order.
  std::vector<std::vector<uint32_t>> batchFaces(scene.models.size());
  if (!batches.empty() && nf > 0) {
    for (uint32_t id : *batches.faces) {
      const FaceRef face = scene.locate(id);
      batchFaces[scene.instances[face.instance].part].push_back(face.meshFace);
    }
  }
  parts_.resize(scene.models.size());
  for (size_t m = 0; m < scene.models.size(); ++m) {
    const SceneModel& model = scene.models[m];
    Part& part = parts_[m];
    part.slotBegin = uint32_t(slotPositions_.size());
    for (uint32_t f : batchFaces[m]) visitFace(f);
    std::vector<uint32_t>().swap(batchFaces[m]);
    for (uint32_t f = model.faceBegin; f < model.faceEnd; ++f) visitFace(f);
    part.slotEnd = uint32_t(slotPositions_.size());
    part.bounds = boundingBox(
        std::vector<Vec3>(slotPositions_.begin() + part.slotBegin, slotPositions_.end()));
    for (uint32_t f = model.faceBegin; f < model.faceEnd; ++f) {
      const uint32_t n = mesh.cornerCount(f);
      (n >= 3 ? part.triangles : part.degenerate) += n >= 3 ? n - 2 : 1;
    }
  }
  if (!batches.empty()) layOutBatches(scene, batches);
}

void MeshLayout::layOutBatches(const Scene& scene, const FaceBatches& batches) {
  const Mesh& mesh = *scene.mesh;
  const std::vector<uint32_t>& faceOrder = *batches.faces;
  const std::vector<uint32_t>& starts = *batches.starts;
  Batches& b = batches_;
  b.faces = faceOrder;
  b.faceStart = starts;
  b.faceCorners.resize(faceOrder.size());
  for (size_t i = 0; i < faceOrder.size(); ++i) {
    const uint32_t n = mesh.cornerCount(scene.locate(faceOrder[i]).meshFace);
    b.faceCorners[i] = uint8_t(n <= 255 ? n : 0);
  }
  b.vertexStart.assign(1, 0);
  b.cornerStart.assign(1, 0);
  // Every instance's vertices numbered one after another (instance k's slot s is vertex
  // vertexBase[k] + s - its part's first slot); localOf holds the local numbers of the vertices
  // of the batch being laid out, and `seen` tells whether the entry belongs to this batch.
  std::vector<size_t> vertexBase(scene.instanceCount() + 1, 0);
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    const Part& part = parts_[scene.instances[k].part];
    vertexBase[k + 1] = vertexBase[k] + (part.slotEnd - part.slotBegin);
  }
  std::vector<uint32_t> localOf(vertexBase.back());
  std::vector<uint32_t> seen(localOf.size(), ~0u);
  for (size_t batch = 0; batch + 1 < starts.size(); ++batch) {
    const uint32_t first = uint32_t(b.vertexSlot.size());
    for (uint32_t i = starts[batch]; i < starts[batch + 1]; ++i) {
      const FaceRef face = scene.locate(faceOrder[i]);
      const uint32_t k = face.instance, f = face.meshFace;
      const uint32_t slotBegin = parts_[scene.instances[k].part].slotBegin;
      for (uint32_t c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; ++c) {
        const size_t vertex = vertexBase[k] + (cornerSlots_[c] - slotBegin);
        if (seen[vertex] != batch) {
          seen[vertex] = uint32_t(batch);
          localOf[vertex] = uint32_t(b.vertexSlot.size()) - first;
          b.vertexSlot.push_back(cornerSlots_[c]);
          b.vertexInstance.push_back(k);
        }
        b.corners.push_back(localOf[vertex]);
      }
    }
    b.vertexStart.push_back(uint32_t(b.vertexSlot.size()));
    b.cornerStart.push_back(uint32_t(b.corners.size()));
  }
}

}  // namespace zrender
