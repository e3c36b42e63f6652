#pragma once

#include "zrender/raster/DepthPyramid.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/visibility/Octree.hpp"

namespace zrender {

// The test of one octree node against the view volume and the z-pyramid, set up once per
// frame.
class OctreeNodeTest {
 public:
  // `widthSamples` x `heightSamples`: the buffer's size; a node is tested on sample rows
  // [rowBegin, rowEnd) only (a band of the image, with a pyramid of its own; default: all).
  OctreeNodeTest(const Camera& camera, int widthSamples, int heightSamples, int rowBegin = 0,
                 int rowEnd = -1);

  // Whether every face below the node can be skipped: its box lies wholly outside one plane
  // of the view volume (the faces are clipped away), or wholly in front of the near plane and
  // behind the z-pyramid over its screen bounds (widened by a sample for snapping). Exact
  // because no sample of a face is nearer than the face's nearest corner (DepthPlane clamps to
  // its corner depths) and the corners lie in the box. A box that reaches the near plane is
  // never rejected for occlusion. NaN anywhere keeps the node.
  bool hidden(const OctreeNode& node, const DepthPyramid& pyramid) const;

 private:
  Mat4 vp_;                   // world to clip space
  double width_, height_;     // samples
  double rowBegin_, rowEnd_;  // the rows tested
};

}  // namespace zrender
