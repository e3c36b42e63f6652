#include "zrender/transform/MeshLayout.hpp"

namespace zrender {

MeshLayout::MeshLayout(const Mesh& mesh, uint32_t instanceCount, FaceBatches batches) {
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
  if (!batches.empty() && nf > 0)
    for (uint32_t id : *batches.faces) visitFace(id % nf);
  for (uint32_t f = 0; f < nf; ++f) visitFace(f);

  bounds_ = boundingBox(slotPositions_);
  for (uint32_t f = 0; f < nf; ++f) {
    const uint32_t n = mesh.cornerCount(f);
    (n >= 3 ? instanceTriangles_ : instanceDegenerate_) += n >= 3 ? n - 2 : 1;
  }
  if (!batches.empty()) layOutBatches(mesh, instanceCount, batches);
}

void MeshLayout::layOutBatches(const Mesh& mesh, uint32_t instanceCount,
                               const FaceBatches& batches) {
  const std::vector<uint32_t>& faceOrder = *batches.faces;
  const std::vector<uint32_t>& starts = *batches.starts;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const size_t slots = slotPositions_.size();
  Batches& b = batches_;
  b.faces = faceOrder;
  b.faceStart = starts;
  b.faceCorners.resize(faceOrder.size());
  for (size_t i = 0; i < faceOrder.size(); ++i) {
    const uint32_t n = mesh.cornerCount(faceOrder[i] % nf);
    b.faceCorners[i] = uint8_t(n <= 255 ? n : 0);
  }
  b.vertexStart.assign(1, 0);
  b.cornerStart.assign(1, 0);
  // Local numbers of the vertices of the batch being laid out, by global vertex (instance x
  // slots + slot); `seen` tells whether the entry belongs to this batch.
  std::vector<uint32_t> localOf(slots * instanceCount);
  std::vector<uint32_t> seen(localOf.size(), ~0u);
  for (size_t batch = 0; batch + 1 < starts.size(); ++batch) {
    const uint32_t first = uint32_t(b.vertexSlot.size());
    for (uint32_t i = starts[batch]; i < starts[batch + 1]; ++i) {
      const uint32_t id = faceOrder[i], k = id / nf, f = id % nf;
      for (uint32_t c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; ++c) {
        const size_t vertex = size_t(k) * slots + cornerSlots_[c];
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
