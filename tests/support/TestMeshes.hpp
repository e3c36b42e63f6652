#pragma once

// Meshes built in code for the transform and visibility tests: floors, tessellated squares and
// planar polygons.

#include <string>
#include <utility>
#include <vector>

#include "zrender/scene/Transforms.hpp"

namespace zrender::test {

// A floor of n x n cells rising 0.05 per row, from z = -6 (far) to z = 4 (behind a tiny
// scene's eye), x in [-6, 6] (past the image's sides): quads, or with `mixed` two triangles in
// two cells of three. Appends to positions `p` and faces `f`.
void addTiltedFloor(int n, bool mixed, std::vector<Vec3>& p, std::vector<std::vector<int>>& f);

// A unit square in the z = 0 plane (raised by wave * sin(i + 2 j) at grid point (i, j)), cut
// into n x n cells facing +z: quads, or two triangles each. Appends to `p` and `f`.
void addTessellatedSquare(int n, bool quads, double wave, std::vector<Vec3>& p,
                          std::vector<std::vector<int>>& f);

// A planar polygon: 2D outline (x, y) rotated by `angle` in its plane, moved by (dx, dy) and
// placed on the plane z = px * x + py * y + pz.
std::vector<Vec3> planarPolygon(const std::vector<std::pair<double, double>>& outline, double angle,
                                double dx, double dy, double px, double py, double pz);

// Polygons that share no vertex, for test::makeMesh(positions, faces).
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  void add(const std::vector<Vec3>& corners);
};

// A comb with `teeth` teeth pointing down: a row through the teeth crosses 2 * teeth edges.
std::vector<std::pair<double, double>> combOutline(int teeth, double w, double h);

}  // namespace zrender::test
