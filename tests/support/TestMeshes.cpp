#include "support/TestMeshes.hpp"

#include <cmath>

namespace zrender::test {

void addTiltedFloor(int n, bool mixed, std::vector<Vec3>& p, std::vector<std::vector<int>>& f) {
  const int b = int(p.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      p.emplace_back(-6.0 + 12.0 * i / n, -0.6 + 0.05 * j, -6.0 + 10.0 * j / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = b + j * (n + 1) + i;
      if (mixed && (i + j) % 3 != 0) {
        f.push_back({a, a + 1, a + n + 2});
        f.push_back({a, a + n + 2, a + n + 1});
      } else {
        f.push_back({a, a + 1, a + n + 2, a + n + 1});
      }
    }
}

void addTessellatedSquare(int n, bool quads, double wave, std::vector<Vec3>& p,
                          std::vector<std::vector<int>>& f) {
  const int b = int(p.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      p.emplace_back(-0.5 + double(i) / n, -0.5 + double(j) / n, wave * std::sin(i + 2.0 * j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = b + j * (n + 1) + i;
      if (quads) {
        f.push_back({a, a + 1, a + n + 2, a + n + 1});
      } else {
        f.push_back({a, a + 1, a + n + 2});
        f.push_back({a, a + n + 2, a + n + 1});
      }
    }
}

std::vector<Vec3> planarPolygon(const std::vector<std::pair<double, double>>& outline, double angle,
                                double dx, double dy, double px, double py, double pz) {
  std::vector<Vec3> out;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const auto& [x0, y0] : outline) {
    const double x = c * x0 - s * y0 + dx, y = s * x0 + c * y0 + dy;
    out.emplace_back(x, y, px * x + py * y + pz);
  }
  return out;
}

void PolygonSoup::add(const std::vector<Vec3>& corners) {
  std::vector<int> f;
  for (const Vec3& p : corners) {
    f.push_back(int(positions.size()));
    positions.push_back(p);
  }
  faces.push_back(f);
}

std::vector<std::pair<double, double>> combOutline(int teeth, double w, double h) {
  std::vector<std::pair<double, double>> o = {{-w, h}, {w, h}};
  const double step = 2 * w / (2 * teeth - 1);
  for (int k = 2 * teeth - 1; k >= 0; --k) {
    const double x1 = -w + step * (k + 1), x0 = -w + step * k;
    const bool tooth = k % 2 == 0;
    const double bottom = tooth ? -h : 0.2 * h;
    o.push_back({x1, bottom});
    o.push_back({x0, bottom});
  }
  return o;
}

}  // namespace zrender::test
