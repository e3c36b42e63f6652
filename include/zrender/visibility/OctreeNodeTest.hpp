#pragma once

#include <cstdint>

#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/visibility/Octree.hpp"

namespace zrender {

// Where an octree node's box lies seen by the frame's camera (OctreeNodeTest::project): the
// same for every band of the image, so computed once a frame.
struct NodeBounds {
  enum Kind : uint8_t {
    kClipped,  // wholly outside one plane of the view volume: every face below is clipped away
    kKept,     // reaches the near plane, behind the eye, or NaN: never rejected for occlusion
    kOnScreen  // in front of the near plane: the samples and key below
  };
  Kind kind = kKept;
  // kOnScreen: the samples [minX, maxX] x [minY, maxY] (clamped to the image; empty when off
  // it) that a face below may cover, and a key no greater than any of theirs.
  int minX = 0, minY = 0, maxX = -1, maxY = -1;
  DepthKey key = 0;
};

// The test of one octree node against the view volume and the z-pyramid, set up once per
// frame.
class OctreeNodeTest {
 public:
  // `widthSamples` x `heightSamples`: the buffer's size; a node is tested on sample rows
  // [rowBegin, rowEnd) only (a band of the image, with a pyramid of its own; default: all).
  OctreeNodeTest(const Camera& camera, int widthSamples, int heightSamples, int rowBegin = 0,
                 int rowEnd = -1);

  // The node's box seen by the camera, for every band.
  NodeBounds project(const OctreeNode& node) const;
  // Whether every face below a node whose box projects to `bounds` can be skipped: its box
  // lies wholly outside one plane of the view volume (the faces are clipped away), off the
  // rows tested, or wholly in front of the near plane and behind the z-pyramid over its screen
  // bounds (widened by a sample for snapping). Exact because no sample of a face is nearer than
  // the face's nearest corner (DepthPlane clamps to its corner depths) and the corners lie in
  // the box. A box that reaches the near plane is never rejected for occlusion.
  bool hidden(const NodeBounds& bounds, const DepthPyramid& pyramid) const;
  bool hidden(const OctreeNode& node, const DepthPyramid& pyramid) const {
    return hidden(project(node), pyramid);
  }

 private:
  Mat4 vp_;                // world to clip space
  double width_, height_;  // samples
  int rowBegin_, rowEnd_;  // the rows tested
};

}  // namespace zrender
