#include "zrender/shading/ShadingModel.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

uint32_t packRgb(double r, double g, double b) {
  auto q = [](double v) { return uint32_t(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5); };
  return (q(r) << 16) | (q(g) << 8) | q(b);
}

Vec3 newellSum(const Mesh& mesh, size_t face) {
  const Corner* c = mesh.faceCorners(face);
  const uint32_t n = mesh.cornerCount(face);
  Vec3 normal(0, 0, 0);
  for (uint32_t i = 0; i < n; ++i) {
    const Vec3& p = mesh.positions[size_t(c[i].position)];
    const Vec3& q = mesh.positions[size_t(c[(i + 1) % n].position)];
    normal += Vec3((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                   (p[0] - q[0]) * (p[1] + q[1]));
  }
  return normal;
}

Vec3 newellNormal(const Mesh& mesh, size_t face) {
  const Vec3 normal = newellSum(mesh, face);
  const double len = cv::norm(normal);
  return len > 0.0 ? normal / len : Vec3(0, 0, 0);
}

uint32_t randomFaceColor(uint32_t faceId) {
  // splitmix32-style finalizer: neighbouring ids get unrelated colors.
  uint32_t h = faceId * 0x9E3779B9u + 0x7F4A7C15u;
  h = (h ^ (h >> 16)) * 0x85EBCA6Bu;
  h = (h ^ (h >> 13)) * 0xC2B2AE35u;
  h ^= h >> 16;
  // Keep colors away from black so faces stand out from the default background.
  return (h & 0x00FFFFFFu) | 0x00303030u;
}

uint32_t idColor(uint32_t faceId) {
  const uint32_t v = faceId + 1;
  return ((v & 0xFF) << 16) | (((v >> 8) & 0xFF) << 8) | ((v >> 16) & 0xFF);
}

}  // namespace zrender
