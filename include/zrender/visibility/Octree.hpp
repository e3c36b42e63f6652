#pragma once

#include <cstdint>
#include <vector>

#include "zrender/scene/Scene.hpp"

namespace zrender {

// One node of the octree (56 bytes). Children are stored contiguously in octant order.
struct OctreeNode {
  // Bounds of every face below the node, world space (all instances), rounded outward to
  // float and then widened by a relative margin, so that a face is always inside.
  float lo[3], hi[3];
  // Where the node's cell splits into octants (its centre): the front-to-back order of the
  // children is taken from the side of these planes the eye is on.
  float split[3];
  uint32_t firstChild;  // index of the first child in Octree::nodes (if childMask != 0)
  uint32_t faceBegin;   // the faces below the node: Octree::faces[faceBegin, faceEnd)
  uint32_t faceEnd;
  uint32_t minFace;   // the smallest face id below the node: its faces' keys have no smaller id
  uint8_t childMask;  // bit o set when octant o (x | y << 1 | z << 2, 1 = upper half) exists
};

// An octree over all faces of all instances in world space, built once per scene.
//
// Design choice: a loose octree with tight bounds. Each face goes to the cell of its centroid
// (faces are sorted by the Morton code of the centroid, so every node's faces are one range of
// `faces`), and a node's box is the union of the boxes of the faces below it, which may reach
// past its cell. The alternative, keeping a face that straddles a split plane in the smallest
// cell that contains it, strands the faces that cross coarse planes in big nodes that are
// rarely hidden (on `crowd`, thousands of faces in the root and a hundred thousand in cells
// bigger than a bunny, to be transformed in every frame); with tight bounds every face is tested
// at leaf granularity, and the build is a radix sort plus one recursive pass over contiguous
// arrays (no per-node lists).
//
// Leaf size (kLeafFaces): bigger leaves cull a little less but cost fewer node tests, and fewer
// vertices are computed twice (once per leaf that uses them); 256 measured best of the sizes
// tried (docs/performance.md). `zrender-culling-bound --leaf-faces N` measures what perfect
// node tests would give at each size.
class Octree {
 public:
  static constexpr int kMaxDepth = 10;         // 2^10 cells per axis: 30-bit Morton codes
  static constexpr uint32_t kLeafFaces = 256;  // default: at most this many faces make a leaf

  // Builds the octree over scene.faceCount() faces (ids as Scene numbers them); a node
  // with at most `leafFaces` faces (or at kMaxDepth) is a leaf.
  void build(const Scene& scene, uint32_t leafFaces = kLeafFaces);

  const std::vector<OctreeNode>& nodes() const { return nodes_; }  // nodes_[0] is the root
  const std::vector<uint32_t>& faces() const { return faces_; }    // face ids in Morton order
  bool empty() const { return nodes_.empty(); }
  size_t memoryBytes() const {
    return nodes_.capacity() * sizeof(OctreeNode) + faces_.capacity() * sizeof(uint32_t);
  }

 private:
  std::vector<OctreeNode> nodes_;
  std::vector<uint32_t> faces_;
};

}  // namespace zrender
