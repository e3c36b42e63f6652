// `scanline` and `interval` against the z-buffer: bit-identical keys (depth + id) and colors on
// reference models, quads, concave polygons, random soups, off-screen and near-plane geometry,
// every shading mode, culling off and MSAA 4; plus one hand-worked concave polygon.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "TestSupport.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/transform/Triangulation.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

const std::vector<std::string> kAlgorithms = {"scanline", "interval"};

using test::coveredSamples;

// Renders `scene` with zbuffer and both scan-line algorithms; keys and colors must be equal.
// Returns the number of samples zbuffer covered (so callers can check the test saw something).
size_t expectSameAsZBuffer(const Scene& scene, const std::string& what) {
  const test::Rendered ref = test::render(scene, "zbuffer");
  for (const std::string& alg : kAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    test::expectSameFrame(ref, r, alg + ", " + what);
  }
  return coveredSamples(ref.buffer);
}

size_t expectSameAsZBuffer(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                           const std::string& what) {
  Warnings warnings;
  const Scene scene = makeScene(settings, std::move(mesh));
  return expectSameAsZBuffer(scene, what);
}

uint64_t extraCounter(const RenderStats& stats, const std::string& name) {
  for (const auto& [n, value] : stats.extra)
    if (n == name) return value;
  return 0;
}

// Renders with `interval` only and returns one of its counters (to check that a test reaches
// the code path it is meant for).
uint64_t intervalCounter(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                         const std::string& name) {
  return extraCounter(test::render(std::move(mesh), settings, "interval").stats, name);
}

// ---------------------------------------------------------------------------------------------
// Hand-worked coverage: a concave hexagon in an 8 x 8 image, corners at sample centres or
// borders (sample units): A (0.5, 0.5), B (6.5, 0.5), C (6.5, 6.5), D (4.5, 6.5), E (3.5, 2.5),
// F (2.5, 6.5). Worked row by row (centre yc = j + 0.5, crossings c, covered centres in
// [c1, c2) and [c3, c4)):
//   row 0: F-A at 0.5, B-C at 6.5 (A-B is horizontal, never active)     -> columns 0..5
//   row 1: F-A at 0.833, B-C at 6.5                                     -> 1..5
//   row 2: F-A 1.167, E-F 3.5, D-E 3.5 (E is at a centre), B-C 6.5      -> 1..5
//   row 3: F-A 1.5, E-F 3.25, D-E 3.75, B-C 6.5                         -> 1, 2, 4, 5
//   row 4: F-A 1.833, E-F 3.0, D-E 4.0, B-C 6.5                         -> 2, 4, 5
//   row 5: F-A 2.167, E-F 2.75, D-E 4.25, B-C 6.5                       -> 2, 4, 5
//   row 6: yc = 6.5 is the bottom of every edge: none active            -> nothing
const char* const kHexagonMask[8] = {
    "XXXXXX..",  //
    ".XXXXX..",  //
    ".XXXXX..",  //
    ".XX.XX..",  //
    "..X.XX..",  //
    "..X.XX..",  //
    "........",  //
    "........",  //
};

FixedPoint samplePoint(double x, double y) {
  return FixedPoint{int32_t(std::lround(x * kSubpixel)), int32_t(std::lround(y * kSubpixel))};
}

// Renders one hand-made face with `algorithm`; the face's depth is 0.5 everywhere.
FrameBuffer renderHandMadeFace(const std::vector<FixedPoint>& corners,
                               const std::string& algorithm) {
  Warnings warnings;
  const Scene scene = makeScene(test::tinySettings(8),
                                test::makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  const Camera camera = makeCamera(scene);
  test::GivenGeometry given;
  FrameGeometry geometry;
  geometry.width = geometry.height = 8;
  geometry.vertices = corners;
  std::vector<std::array<uint32_t, 3>> pieces;
  std::vector<uint32_t> scratch;
  EXPECT_TRUE(triangulatePolygon(corners.data(), uint32_t(corners.size()), pieces, scratch));
  ScreenFace face{};
  face.id = 7;
  face.firstVertex = 0;
  face.vertexCount = uint32_t(corners.size());
  face.firstTriangle = 0;
  face.triangleCount = uint32_t(pieces.size());
  face.frontFacing = true;
  geometry.faces.push_back(face);
  for (const auto& t : pieces)
    geometry.triangles.push_back(ScreenTriangle{
        {corners[t[0]], corners[t[1]], corners[t[2]]}, 0, face.id, DepthPlane{0.0, 0.0, 0.5}});

  auto alg = makeAlgorithm(algorithm);
  FrameBuffer fb;
  fb.resize(8, 8);
  RenderStats stats;
  FrameInput input{scene, camera, given, geometry};
  alg->render(input, fb, stats);
  return fb;
}

TEST(ScanlineInterval, HandWorkedConcaveHexagon) {
  std::vector<FixedPoint> hexagon = {samplePoint(0.5, 0.5), samplePoint(6.5, 0.5),
                                     samplePoint(6.5, 6.5), samplePoint(4.5, 6.5),
                                     samplePoint(3.5, 2.5), samplePoint(2.5, 6.5)};
  const DepthKey inside = makeDepthKey(0.5f, 7);
  for (int winding = 0; winding < 2; ++winding) {
    // zbuffer draws the triangulation; it must agree with the hand-worked polygon too.
    for (const std::string alg : {"scanline", "interval", "zbuffer"}) {
      const FrameBuffer fb = renderHandMadeFace(hexagon, alg);
      for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
          EXPECT_EQ(fb.row(y)[x], kHexagonMask[y][x] == 'X' ? inside : kClearKey)
              << alg << " winding " << winding << " sample (" << x << ", " << y << ")";
    }
    std::reverse(hexagon.begin(), hexagon.end());
  }
}

// ---------------------------------------------------------------------------------------------
// Reference models at a reduced size.

void expectModelSame(const std::string& name, int size) {
  auto mesh = test::referenceModel(name);
  if (!mesh) GTEST_SKIP() << "model " << name << " is not linked under models/";
  SceneSettings s = test::projectScene(name);
  s.width = s.height = size;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, name), size_t(size) * size / 20);
}

TEST(ScanlineInterval, Bunny) {
  expectModelSame("bunny", 300);
}
TEST(ScanlineInterval, Spot) {
  expectModelSame("spot", 300);
}
TEST(ScanlineInterval, Teapot) {
  expectModelSame("teapot", 300);
}

TEST(ScanlineInterval, BunnyNoCullNonSquare) {
  auto mesh = test::referenceModel("bunny");
  if (!mesh) GTEST_SKIP() << "bunny is not linked under models/";
  SceneSettings s = test::projectScene("bunny");
  s.width = 320;
  s.height = 240;
  s.aspect = 0.0;
  s.cull = false;
  s.shading = ShadingMode::Id;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, "bunny --no-cull 320x240"), 10000u);
}

// The eye close to the bunny: part of it is cut by the near plane, part is off screen, and
// the clipped faces project to huge coordinates.
TEST(ScanlineInterval, BunnyNearPlaneAndHalfOutside) {
  auto mesh = test::referenceModel("bunny");
  if (!mesh) GTEST_SKIP() << "bunny is not linked under models/";
  SceneSettings s = test::projectScene("bunny");
  s.width = s.height = 240;
  s.shading = ShadingMode::Depth;
  struct View {
    cv::Vec3d eye, target;
    double near;
    bool cull, nearPlaneCuts, partlyEmpty;
  };
  const View views[] = {
      // near plane through the body, bunny off the top and right borders
      {{0.06, 0.12, 0.10}, {-0.08, 0.10, -0.01}, 0.07, true, true, true},
      // eye inside the bunny, everything around it drawn
      {{0.02, 0.11, 0.03}, {-0.10, 0.10, -0.02}, 0.005, false, true, false},
      // bunny cut by the bottom and right borders
      {{-0.20, 0.10, 0.25}, {0.05, 0.12, -0.01}, 0.1, true, false, true},
  };
  for (const View& v : views) {
    s.eye = v.eye;
    s.target = v.target;
    s.near = v.near;
    s.cull = v.cull;
    Warnings warnings;
    const Scene scene = makeScene(s, mesh);
    // Check the scenario: some vertices in front of the near plane, some behind it.
    const Camera camera = makeCamera(scene);
    double nearest = 1e300, farthest = -1e300;
    for (const Vec3& p : mesh->positions) {
      const Vec4 q = camera.view * Vec4(p[0], p[1], p[2], 1.0);
      nearest = std::min(nearest, -q[2]);
      farthest = std::max(farthest, -q[2]);
    }
    if (v.nearPlaneCuts) {
      EXPECT_LT(nearest, v.near);
      EXPECT_GT(farthest, v.near);
    }
    const size_t covered = expectSameAsZBuffer(scene, "bunny close up");
    EXPECT_GT(covered, 1000u);
    if (v.partlyEmpty) {
      EXPECT_LT(covered, size_t(s.width) * s.height);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Quads and concave polygons, drawn natively by the scan-line algorithms.

// A planar polygon: 2D outline (x, y) rotated by `angle` in its plane, placed on the plane
// z = px * x + py * y + pz.
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

struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  void add(const std::vector<Vec3>& corners) {
    std::vector<int> f;
    for (const Vec3& p : corners) {
      f.push_back(int(positions.size()));
      positions.push_back(p);
    }
    faces.push_back(f);
  }
};

// A comb with `teeth` teeth pointing down: a row through the teeth crosses 2 * teeth edges.
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

std::vector<std::pair<double, double>> starOutline(int points, double outer, double inner) {
  std::vector<std::pair<double, double>> o;
  for (int k = 0; k < 2 * points; ++k) {
    const double r = k % 2 ? inner : outer, a = M_PI * k / points;
    o.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return o;
}

TEST(ScanlineInterval, QuadsAndParallelograms) {
  PolygonSoup soup;
  // A tilted 6 x 6 grid of quads sharing edges (no gaps, no double cover along them).
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      const double x = -1.5 + 0.5 * i, y = -1.5 + 0.5 * j;
      soup.add(planarPolygon({{x, y}, {x + 0.5, y}, {x + 0.5, y + 0.5}, {x, y + 0.5}}, 0.3, 0, 0,
                             0.2, -0.1, 0.0));
    }
  // Random parallelograms c +- u +- v crossing the grid and each other.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (int k = 0; k < 40; ++k) {
    const Vec3 c(r(rng), r(rng), 0.5 * r(rng)), u(0.6 * r(rng), 0.6 * r(rng), 0.6 * r(rng)),
        v(0.6 * r(rng), 0.6 * r(rng), 0.6 * r(rng));
    soup.add({c - u - v, c + u - v, c + u + v, c - u + v});
  }
  SceneSettings s = test::tinySettings(160);
  s.cull = false;
  s.shading = ShadingMode::Random;
  EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s, "quads"), 8000u);
}

TEST(ScanlineInterval, ConcavePolygons) {
  PolygonSoup soup;
  // L-shape, comb (10 crossings per row through its teeth), stars, in tilted planes that cut
  // through one another.
  soup.add(planarPolygon({{-1, -1}, {1, -1}, {1, -0.4}, {-0.4, -0.4}, {-0.4, 1}, {-1, 1}}, 0.2,
                         -0.3, 0.2, 0.3, 0.1, 0.0));
  soup.add(planarPolygon(combOutline(5, 1.2, 0.8), -0.15, 0.2, 0.1, -0.25, 0.2, 0.05));
  soup.add(planarPolygon(starOutline(7, 1.3, 0.5), 0.05, 0.4, -0.3, 0.1, -0.3, -0.05));
  soup.add(planarPolygon(starOutline(5, 0.9, 0.3), 0.0, -0.8, 0.9, 0.0, 0.0, 0.3));
  soup.add(planarPolygon(combOutline(3, 0.7, 0.5), 1.7, 1.0, 0.8, 0.0, 0.0, 0.2));
  for (const int size : {97, 200}) {
    SceneSettings s = test::tinySettings(size);
    s.cull = false;
    s.shading = ShadingMode::Id;
    EXPECT_GT(
        expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s, "concave polygons"),
        size_t(size) * size / 10);
    s.msaa = 4;
    EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                  "concave polygons, msaa 4"),
              size_t(size) * size / 10);
  }
}

// The comb alone, in the image plane: the scan-line algorithms really see 4+ crossings per row.
TEST(ScanlineInterval, CombCrossesRowsManyTimes) {
  PolygonSoup soup;
  soup.add(planarPolygon(combOutline(4, 1.5, 1.2), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
  SceneSettings s = test::tinySettings(64);
  s.cull = false;  // the outline runs clockwise
  EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s, "comb"), 500u);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(soup.positions, soup.faces));
  for (const std::string& alg : kAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    EXPECT_GE(extraCounter(r.stats, "max_active_edges"), 8u) << alg;
  }
}

// ---------------------------------------------------------------------------------------------
// Random soups: interpenetrating triangles (crossing depths inside spans) and exact coplanar
// duplicates (ties that the smaller id must win).

TEST(ScanlineInterval, RandomSoups) {
  uint64_t split = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    SceneSettings s = test::tinySettings(seed % 2 ? 180 : 131);
    s.width += int(seed) * 7;  // non-square too
    s.cull = false;
    s.shading = ShadingMode::Id;
    const auto soup = test::randomSoup(seed, 300, true);
    EXPECT_GT(expectSameAsZBuffer(soup, s, "soup seed " + std::to_string(seed)), 1000u);
    split += intervalCounter(soup, s, "spans_split");
  }
  EXPECT_GT(split, 100u);  // depths crossing inside spans were really met
}

// Triangles in nearly one plane, offsets from 1e-3 down to 1e-8: ties and ulp-sized crossings.
TEST(ScanlineInterval, RandomNearlyCoplanarSoups) {
  uint64_t oneByOne = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-1.8, 1.8), unit(-1.0, 1.0);
    const double offset = std::pow(10.0, -3.0 - double(seed % 6));
    const double px = 0.3 * unit(rng), py = 0.3 * unit(rng);
    PolygonSoup soup;
    for (int t = 0; t < 40; ++t) {
      std::vector<Vec3> corners;
      for (int i = 0; i < 3; ++i) {
        const double x = coord(rng), y = coord(rng);
        corners.emplace_back(x, y, px * x + py * y + offset * unit(rng));
      }
      soup.add(corners);
    }
    SceneSettings s = test::tinySettings(100 + int(seed % 37));
    s.cull = false;
    s.near = 0.5 + (seed % 5) * 0.3;
    s.shading = ShadingMode::Id;
    const auto mesh = test::makeMesh(soup.positions, soup.faces);
    EXPECT_GT(expectSameAsZBuffer(mesh, s, "near coplanar seed " + std::to_string(seed)), 1000u);
    oneByOne += intervalCounter(mesh, s, "samples_one_by_one");
  }
  EXPECT_GT(oneByOne, 1000u);  // the end values could not decide there: exact keys did
}

TEST(ScanlineInterval, RandomSoupMsaa4) {
  SceneSettings s = test::tinySettings(120);
  s.cull = false;
  s.msaa = 4;
  s.shading = ShadingMode::Depth;
  EXPECT_GT(expectSameAsZBuffer(test::randomSoup(9, 200, true), s, "soup msaa 4"), 1000u);
}

// Nearly coplanar layers: depths within a few float ulps over whole spans, where the end values
// cannot prove the order and samples must be decided one by one.
TEST(ScanlineInterval, NearlyCoplanarLayers) {
  PolygonSoup soup;
  for (int k = 0; k < 6; ++k) {
    const double eps = 1e-7 * k;
    soup.add({{-1.5, -1.2, eps}, {1.4, -1.5, -eps}, {0.1, 1.5, 2 * eps}});
    soup.add({{-1.3, 1.4, -eps}, {-1.2, -1.5, eps}, {1.5, 0.3, 0.0}});
  }
  SceneSettings s = test::tinySettings(150);
  s.cull = false;
  s.shading = ShadingMode::Id;
  const auto mesh = test::makeMesh(soup.positions, soup.faces);
  EXPECT_GT(expectSameAsZBuffer(mesh, s, "near ties"), 5000u);
  EXPECT_GT(intervalCounter(mesh, s, "samples_one_by_one"), 100u);
}

// Faces far outside the image and across the near plane: huge snapped coordinates.
TEST(ScanlineInterval, HugeAndOffscreenFaces) {
  PolygonSoup soup;
  soup.add({{-1000, -1000, -1}, {1000, -900, -1.2}, {0, 1000, -0.8}});  // covers everything
  soup.add({{-0.5, -0.5, 1.99}, {0.5, -0.4, 1.99}, {0, 0.5, -3}});      // crosses the near plane
  soup.add({{3, 3, 0}, {9, 3, 0}, {9, 9, 0}, {3, 9, 0}});               // off screen
  soup.add({{-50, 0.2, 0.5}, {50, 0.1, 0.4}, {0.2, 0.3, 0.5}});         // long sliver
  soup.add({{-1, -1.9, 0.2}, {1, -1.95, 0.2}, {0, -2.5, 0.2}});         // crosses the bottom
  // Just beyond the near plane (0.101 from the eye) and 1e4 to the sides: millions of pixels
  // off screen, cut by the guard band.
  soup.add({{-1e4, 0.3, 1.899}, {1e4, 0.35, 1.899}, {0.1, -0.2, 0.0}});
  soup.add({{0.3, -1e4, 1.8995}, {0.2, 1e4, 1.8995}, {-0.6, 0.4, 0.1}});
  SceneSettings s = test::tinySettings(90);
  s.cull = false;
  s.shading = ShadingMode::Id;
  EXPECT_EQ(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s, "huge"),
            size_t(90 * 90));
}

// ---------------------------------------------------------------------------------------------
// Every shading mode (colors must match exactly too), on spot (normals, texture).

TEST(ScanlineInterval, EveryShadingMode) {
  auto mesh = test::referenceModel("spot");
  if (!mesh) GTEST_SKIP() << "spot is not linked under models/";
  SceneSettings s = test::projectScene("spot");
  s.width = s.height = 128;
  for (const std::string& name : shadingModeNames()) {
    s.shading = *parseShadingMode(name);
    expectSameAsZBuffer(mesh, s, "spot shading " + name);
  }
  s.msaa = 4;
  s.shading = ShadingMode::Texture;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, "spot msaa 4 texture"), 2000u);
}

TEST(ScanlineInterval, TeapotMsaa4NoCull) {
  auto mesh = test::referenceModel("teapot");
  if (!mesh) GTEST_SKIP() << "teapot is not linked under models/";
  SceneSettings s = test::projectScene("teapot");
  s.width = s.height = 160;
  s.msaa = 4;
  s.cull = false;
  s.shading = ShadingMode::Phong;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, "teapot msaa 4 no cull"), 2000u);
}

// The counters SPEC §7 asks of these algorithms are reported.
TEST(ScanlineInterval, Counters) {
  SceneSettings s = test::tinySettings(100);
  s.cull = false;
  Warnings warnings;
  const Scene scene = makeScene(s, test::randomSoup(3, 100, true));
  for (const std::string& alg : kAlgorithms) {
    const test::Rendered r = test::render(scene, alg);
    std::map<std::string, uint64_t> extra(r.stats.extra.begin(), r.stats.extra.end());
    EXPECT_GT(extra["spans"], 0u) << alg;
    EXPECT_GT(extra["max_active_edges"], 0u) << alg;
    EXPECT_GT(extra["max_active_polygons"], 0u) << alg;
    EXPECT_GT(r.stats.trianglesRasterized, 0u) << alg;
    EXPECT_GT(r.stats.pixelsWritten, 0u) << alg;
  }
}

}  // namespace
}  // namespace zrender
