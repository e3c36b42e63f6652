#pragma once

#include <vector>

#include "zrender/HierarchicalAlgorithm.hpp"
#include "zrender/Octree.hpp"
#include "zrender/VisibilityAlgorithm.hpp"

namespace zrender {

// The test of one octree node against the view volume and the z-pyramid, set up once per
// frame.
class OctreeNodeTest {
 public:
  // Faces seen closer than this sine to edge-on are the ones the depth margin may not cover
  // (see marginPerDepth_).
  static constexpr double kGrazingSine = 1e-5;

  // `widthSamples` x `heightSamples`: the buffer's size; `scale`: samples per pixel side.
  OctreeNodeTest(const Camera& camera, int widthSamples, int heightSamples, int scale);

  // Whether every face below the node can be skipped: its box lies wholly outside one plane
  // of the view volume (the faces are clipped away), or wholly in front of the near plane and
  // behind the z-pyramid over its screen bounds (widened by a sample for snapping), with the
  // depth margin. A box that reaches the near plane is never rejected for occlusion. NaN
  // anywhere keeps the node.
  bool hidden(const OctreeNode& node, const DepthPyramid& pyramid) const;

 private:
  Mat4 vp_;                // world to clip space
  double width_, height_;  // samples
  // The faces' depth planes are fitted to their unsnapped window vertices, but coverage is
  // decided on snapped ones: a covered sample can lie up to delta = sqrt(2) * scale / 512
  // samples outside a face, where its plane is extrapolated by |grad z| * delta. For a face
  // whose plane passes at distance d from the eye, |grad z| <= B / (f * d), with B = far *
  // near / (far - near) (window depth = f / (f - n) - B / w) and f the focal length in
  // samples; d >= w * sin(phi) for a face seen at angle phi from edge-on at eye depth >= w.
  // So the depth can dip below the box's nearest corner by at most marginPerDepth_ / w for
  // every face seen at more than kGrazingSine from edge-on. Measured on `crowd` at 1800 x 1800
  // (6.9M faces): 95 visible faces dip below their vertices' depth, the worst by 1.3e-4, as a
  // face at sine 1.8e-4 would; the margin covers eighteen times that. It costs culling: 40%
  // more faces transformed on `crowd` than with no margin (sine 1e-4 would cost 5%). No finite
  // margin covers a face seen exactly edge-on whose snapped sliver still covers a sample (it
  // would be a poke-through artefact of the z-buffer too): that case is left to the margin.
  double marginPerDepth_;
};

// Greene, Kass and Miller's hierarchical z-buffer with an object-space octree: the octree is
// built once (prepare) over all instances in world space and traversed front to back; a node
// whose projected box lies behind the z-pyramid (or outside the view volume) is skipped with
// everything below it. Faces of the other leaves are transformed lazily and their triangles
// go through the pyramid test of HzbRasterizer.
class OctreeAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "octree"; }
  void prepare(const Scene& scene) override { octree_.build(scene); }
  bool transformsAll() const override { return false; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

  const Octree& octree() const { return octree_; }

 private:
  Octree octree_;
  HzbRasterizer rasterizer_;
  std::vector<uint32_t> stack_;  // nodes still to visit, nearest on top
};

}  // namespace zrender
