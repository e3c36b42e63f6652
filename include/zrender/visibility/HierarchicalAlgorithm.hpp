#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "zrender/raster/BandOrder.hpp"
#include "zrender/raster/TriangleBands.hpp"
#include "zrender/visibility/HzbRasterizer.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// Greene, Kass and Miller's hierarchical z-buffer without the object-space octree: every face
// is transformed, and each triangle is tested against the z-pyramid before rasterization.
// Instances (of a grid) are taken one at a time, nearest first: each is pulled (an Instance
// FaceRequest) with the pyramid as its previous ones left it as a filter, so that
// a triangle face already proved hidden there costs no depth plane, no storage and no sorting; then
// its triangles are drawn in bands of sample rows, top to bottom, in face id order within a band
// (TriangleBands), each tested against the pyramid again. A model whose faces come front to back in
// the file keeps most of its culling within one instance. With several threads, the image is cut
// into bands of rows, each with a pyramid of its own: an instance is transformed by all the
// threads while the bands draw the one before it (the pull and the bands' drawing tasks of one
// loop), its faces left in the parts the threads transformed them into, and the filter drops
// only the faces in tiles where the instance's nearest depth is behind.
class HierarchicalAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "hierarchical"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  // Sets instances_ to this frame's order.
  void orderInstances(const FrameInput& input);
  void renderBands(FrameInput& input, FrameBuffer& fb, RenderStats& stats);

  HzbRasterizer rasterizer_;
  TriangleBands bands_;
  std::vector<HzbRasterizer> bandRasterizers_;  // several threads: each band's
  // Several threads: each instance's faces in parts (nearest first), and the last one's
  // triangles in each band.
  std::vector<std::vector<FrameGeometry>> instanceParts_;
  BandLists<const ScreenTriangle*> bandTriangles_;
  std::vector<RenderStats> bandStats_;
  BandOrder bandOrder_;              // several threads: the order of the bands' last loop
  std::vector<uint32_t> instances_;  // this frame's instance order, nearest first
};

}  // namespace zrender
