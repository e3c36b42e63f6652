#include "support/ScreenGeometry.hpp"

#include "support/FaceByFace.hpp"

namespace zrender::test {

ScreenTriangle makeTriangle(double x0, double y0, double x1, double y1, double x2, double y2,
                            uint32_t id, double depth) {
  ScreenTriangle t{};
  t.v[0] = FixedPoint{snapToSubpixel(x0), snapToSubpixel(y0)};
  t.v[1] = FixedPoint{snapToSubpixel(x1), snapToSubpixel(y1)};
  t.v[2] = FixedPoint{snapToSubpixel(x2), snapToSubpixel(y2)};
  t.id = id;
  t.plane.a = 0.0;
  t.plane.b = 0.0;
  t.plane.c = depth;
  return t;
}

WallPyramid::WallPyramid(const Scene& scene, const Camera& camera) {
  FaceByFace transformer(scene, camera, 1, false);
  FrameGeometry wall;
  transformer.transformFace(0, wall);
  transformer.transformFace(1, wall);
  fb.resize(wall.width, wall.height);
  r.begin(fb);
  RenderStats stats;
  for (const ScreenTriangle& t : wall.triangles) r.drawTriangle(t, stats);
}

}  // namespace zrender::test
