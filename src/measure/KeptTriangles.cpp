#include "zrender/measure/KeptTriangles.hpp"

#include <algorithm>

namespace zrender {

void KeptTriangles::leaveOut(FrameGeometry& out, size_t first) {
  ScopedTimer timer(ownMs_);
  GeometryVector<ScreenTriangle>& triangles = out.triangles;
  triangles.erase(std::remove_if(triangles.begin() + std::ptrdiff_t(first), triangles.end(),
                                 [this](const ScreenTriangle& t) { return !keep_(t); }),
                  triangles.end());
}

}  // namespace zrender
