#pragma once

#include <cstdint>

#include <opencv2/core.hpp>

#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// The formulas and constants of the shading modes (docs/design.md, Faces, ids and shading, and
// Choices: shading constants). Colors are RGB in 0..1, or packed as 0x00RRGGBB.

// Packs an RGB color in 0..1 as 0x00RRGGBB, rounding to nearest.
uint32_t packRgb(double r, double g, double b);

// Newell's sum over a face's corners (model space): the face normal times twice its area.
Vec3 newellSum(const Mesh& mesh, size_t face);

// The unit normal of a face; zero for a degenerate face.
Vec3 newellNormal(const Mesh& mesh, size_t face);

// v / |v|, or +Z for a zero vector. Inline: set-up normalizes three normals per face.
inline Vec3 safeNormalize(const Vec3& v) {
  const double len = cv::norm(v);
  return len > 0.0 ? v / len : Vec3(0, 0, 1);
}

// A fixed pseudo-random color per face id (`random` shading), packed.
uint32_t randomFaceColor(uint32_t faceId);

// The `id` shading color: face id + 1 in 24 bits, R = low byte, G = middle, B = high, packed.
uint32_t idColor(uint32_t faceId);

}  // namespace zrender
