#pragma once

#include <cstdint>
#include <vector>

#include "zrender/scene/Scene.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/GeometrySource.hpp"

namespace zrender {

// The model's vertices as the transform reads them, set up once per scene (prepare_ms).
//
// Slots: the positions faces use, numbered in the order faces first use them, the faces taken
// in the batches' order when there are batches (the first instance of a mesh face met
// decides), then the rest in file order; model after model, so that each model of the scene
// (SceneModel) has a range of slots, which its instances project. Nothing drawn depends on that
// order, but faces read their vertices by it: in first-use order consecutive faces find theirs in
// cache (scanned models such as the bunny list vertices in an order unrelated to their faces).
//
// Batches: each batch's vertices (slot and instance) under local numbers, and its faces'
// corners in those numbers, so that a batch computes its vertices into a small array that its
// faces then find in cache whatever the size of the model (a vertex shared by two batches is
// computed twice).
class MeshLayout {
 public:
  explicit MeshLayout(const Scene& scene, FaceBatches batches = FaceBatches());

  const std::vector<Vec3>& slotPositions() const { return slotPositions_; }  // model space
  const std::vector<uint32_t>& cornerSlots() const { return cornerSlots_; }  // per mesh corner
  // Per model of the scene (Scene::models): its slots, their box (model space), the triangles
  // of its faces of 3 or more corners and its faces of fewer, which is what an instance wholly
  // outside the view counts.
  struct Part {
    uint32_t slotBegin = 0, slotEnd = 0;
    Box3 bounds;
    uint64_t triangles = 0, degenerate = 0;
  };
  const Part& part(uint32_t model) const { return parts_[model]; }

  // Batch b: faces faces[faceStart[b], faceStart[b + 1]) (global ids, with their corner count
  // in faceCorners, 0 when over 255), vertices [vertexStart[b], vertexStart[b + 1]) of
  // vertexSlot and vertexInstance, and the faces' corners, face after face, from
  // corners[cornerStart[b]] as vertex numbers local to the batch.
  struct Batches {
    std::vector<uint32_t> faces, faceStart, vertexStart, cornerStart;
    std::vector<uint32_t> vertexSlot, vertexInstance, corners;
    std::vector<uint8_t> faceCorners;
  };
  const Batches& batches() const { return batches_; }

 private:
  void layOutBatches(const Scene& scene, const FaceBatches& batches);

  std::vector<Vec3> slotPositions_;
  std::vector<uint32_t> cornerSlots_;
  std::vector<Part> parts_;
  Batches batches_;
};

}  // namespace zrender
