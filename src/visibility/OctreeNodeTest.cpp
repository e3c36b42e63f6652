#include "zrender/visibility/OctreeNodeTest.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/visibility/NearestKey.hpp"

namespace zrender {

namespace {

// A node's screen rectangle is tested against up to this many pyramid nodes (one node test
// saves many triangles, so it may look closer than a triangle test).
constexpr int kNodeQueryNodes = 64;

}  // namespace

OctreeNodeTest::OctreeNodeTest(const Camera& camera, int widthSamples, int heightSamples,
                               int rowBegin, int rowEnd)
    : vp_(camera.projection * camera.view),
      width_(widthSamples),
      height_(heightSamples),
      rowBegin_(rowBegin),
      rowEnd_(rowEnd < 0 ? heightSamples : rowEnd) {}

NodeBounds OctreeNodeTest::project(const OctreeNode& node) const {
  NodeBounds b;
  // Clip-space corners: base + any subset of the three edge vectors.
  const Vec4 base = vp_ * Vec4(node.lo[0], node.lo[1], node.lo[2], 1.0);
  Vec4 edge[3];
  for (int a = 0; a < 3; ++a) {
    const double len = double(node.hi[a]) - double(node.lo[a]);
    edge[a] = Vec4(vp_(0, a) * len, vp_(1, a) * len, vp_(2, a) * len, vp_(3, a) * len);
  }
  Vec4 corner[8];
  unsigned all = 0x3F;
  bool inFront = true;
  for (int c = 0; c < 8; ++c) {
    Vec4 p = base;
    if (c & 1) p += edge[0];
    if (c & 2) p += edge[1];
    if (c & 4) p += edge[2];
    corner[c] = p;
    const unsigned code = (p[0] < -p[3]) | (p[0] > p[3]) << 1 | (p[1] < -p[3]) << 2 |
                          (p[1] > p[3]) << 3 | (p[2] < -p[3]) << 4 | (p[2] > p[3]) << 5;
    all &= code;
    inFront = inFront && p[3] > 0.0 && p[2] > -p[3];
  }
  if (all) {
    b.kind = NodeBounds::kClipped;
    return b;
  }
  if (!inFront) return b;

  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL, z0 = HUGE_VAL;
  double w0 = HUGE_VAL;
  for (const Vec4& p : corner) {
    const double inv = 1.0 / p[3];
    const double x = (p[0] * inv + 1.0) * 0.5 * width_;   // samples, right
    const double y = (1.0 - p[1] * inv) * 0.5 * height_;  // samples, down
    const double z = (p[2] * inv + 1.0) * 0.5;            // window depth
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
    z0 = std::min(z0, z);
    w0 = std::min(w0, p[3]);
  }
  if (!(x0 <= x1 && y0 <= y1 && z0 == z0 && w0 > 0.0)) return b;
  b.kind = NodeBounds::kOnScreen;
  // Samples whose centre (i + 0.5) may be covered, with a sample of slack for snapping.
  const double minX = std::max(std::floor(x0 - 1.5), 0.0);
  const double maxX = std::min(std::ceil(x1 + 0.5), width_ - 1.0);
  const double minY = std::max(std::floor(y0 - 1.5), 0.0);
  const double maxY = std::min(std::ceil(y1 + 0.5), height_ - 1.0);
  if (minX > maxX || minY > maxY) return b;  // off screen: the empty rectangle
  b.minX = int(minX), b.maxX = int(maxX), b.minY = int(minY), b.maxY = int(maxY);
  // No sample of a face is nearer than the face's nearest corner (DepthPlane clamps to its
  // corner depths), and the corners lie in the box: below the box's nearest corner by the
  // rounding of the two matrix products only.
  const double low = z0 - 1e-6 * (1.0 + std::abs(z0));
  // With the node's smallest id, the key is no greater than any key of its faces.
  b.key = keyAtOrBelow(low, node.minFace);
  return b;
}

bool OctreeNodeTest::hidden(const NodeBounds& b, const DepthPyramid& pyramid) const {
  if (b.kind == NodeBounds::kClipped) return true;
  if (b.kind == NodeBounds::kKept) return false;
  const int minY = std::max(b.minY, rowBegin_), maxY = std::min(b.maxY, rowEnd_ - 1);
  if (b.minX > b.maxX || minY > maxY) return true;  // off screen (or off the band)
  return pyramid.occludes(b.minX, minY, b.maxX, maxY, b.key, kNodeQueryNodes);
}

}  // namespace zrender
