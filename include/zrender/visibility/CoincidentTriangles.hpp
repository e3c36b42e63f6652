#pragma once

#include <cstdint>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"

namespace zrender {

// The big triangles drawn in a frame, by what decides their samples: snapped corners (the
// coverage) and depth plane (the depth at every sample). A triangle equal in both to one drawn
// earlier with a smaller id can never win a sample: wherever it covers one, the earlier one
// covered it with the same depth and wins the tie by its id, or lost it to a key smaller
// still. So it is rejected exactly. This is what makes a model whose faces repeat (a mesh
// exported twice, one face listed a million times) cheap for the hierarchical algorithms: the
// z-pyramid cannot reject such a copy, since the samples around its edges that it leaves clear
// keep every tile it touches at the background's key.
class CoincidentTriangles {
 public:
  // Forgets every triangle (a new frame).
  void clear();
  // True when a triangle with t's corners and plane was recorded with a smaller id; otherwise
  // records t (or lowers the recorded id to t's) and returns false.
  bool hiddenByEarlier(const ScreenTriangle& t);

 private:
  struct Entry {
    FixedPoint v[3];
    uint32_t id;
    DepthPlane plane;
    uint64_t hash;  // 0: empty slot
  };
  void grow();
  std::vector<Entry> slots_;  // open addressing, linear probing; size a power of two
  size_t used_ = 0;
};

}  // namespace zrender
