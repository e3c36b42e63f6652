// The transform (FaceTransformer, the GeometrySource the algorithms pull faces from) against
// the transform one face at a time (test::FaceByFace): by batch and by instance, instances wholly
// outside the view, each instance's nearest depth and sample area, and the faces it drops before
// their depths: those covering no sample centre and those a TriangleFilter hides; and an
// instance's parts on several threads against its geometry on one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "support/FaceByFace.hpp"
#include "support/TestMeshes.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/transform/FaceTransformer.hpp"
#include "zrender/transform/InstanceView.hpp"

namespace zrender {
namespace {

using test::addTessellatedSquare;
using test::addTiltedFloor;

// Geometry as bytes-comparable fields: faces, vertices, triangles (corners, face, id, plane)
// and the counters.
void expectSameGeometry(const FrameGeometry& a, const FrameGeometry& b, const std::string& what) {
  ASSERT_EQ(a.faces.size(), b.faces.size()) << what;
  ASSERT_EQ(a.triangles.size(), b.triangles.size()) << what;
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
  for (size_t i = 0; i < a.faces.size(); ++i) {
    const ScreenFace &x = a.faces[i], &y = b.faces[i];
    EXPECT_TRUE(x.id == y.id && x.firstVertex == y.firstVertex && x.vertexCount == y.vertexCount &&
                x.firstTriangle == y.firstTriangle && x.triangleCount == y.triangleCount &&
                x.rows.first == y.rows.first && x.rows.last == y.rows.last &&
                x.frontFacing == y.frontFacing)
        << what << ", face " << i;
  }
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]) << what;
  for (size_t i = 0; i < a.triangles.size(); ++i) {
    const ScreenTriangle &x = a.triangles[i], &y = b.triangles[i];
    EXPECT_TRUE(x.v[0] == y.v[0] && x.v[1] == y.v[1] && x.v[2] == y.v[2] && x.face == y.face &&
                x.id == y.id && x.plane.a == y.plane.a && x.plane.b == y.plane.b &&
                x.plane.c == y.plane.c && x.plane.loBits == y.plane.loBits &&
                x.plane.hiBits == y.plane.hiBits)
        << what << ", triangle " << i;
  }
  EXPECT_EQ(a.counters.backfaceCulled, b.counters.backfaceCulled) << what;
  EXPECT_EQ(a.counters.clippedAway, b.counters.clippedAway) << what;
  EXPECT_EQ(a.counters.degenerate, b.counters.degenerate) << what;
}

// The scene of the transform tests: quads, mixed triangles and a concave polygon on a floor
// that crosses the near plane and leaves the image, plus a face that snaps to fewer than three
// corners, in a grid of 3 x 1 x 2 instances.
Scene floorGridScene(SceneSettings& s) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTiltedFloor(12, true, p, f);
  const int b = int(p.size());
  p.insert(p.end(), {{-1.8, -1.0, 0.0},
                     {0.0, -1.6, 0.0},
                     {1.6, -1.0, 0.0},
                     {0.5, -0.8, -0.9},
                     {1.4, 0.8, 0.0},
                     {0.0, 0.1, 0.9},
                     {-1.4, 0.8, -0.4}});
  f.push_back({b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6});
  f.push_back({b + 6, b + 5, b + 4, b + 3, b + 2, b + 1, b});
  f.push_back({b, b, b + 1});  // snaps to fewer than three corners
  s = test::tinySettings(90);
  s.grid = Grid{{3, 1, 2}, {4.0, 0.0, 5.0}};
  Warnings warnings;
  return makeScene(s, test::makeMesh(p, f));
}

// The camera of floorGridScene()'s settings `s`, seen from `eye`.
Camera floorGridCamera(const SceneSettings& s, const Scene& scene, const Vec3& eye) {
  SceneSettings view = s;
  view.eye = eye;
  Warnings warnings;
  return makeCamera(makeScene(view, scene.mesh));
}

TEST(FaceTransformer, BatchesGiveWhatFaceByFaceGives) {
  // Quads and a concave polygon, on a floor that crosses the near plane and leaves the image,
  // in a grid of 3 x 1 x 2 instances; faces in a shuffled order cut into batches of random
  // sizes, two frames from different eyes. Each batch computes its own vertices, so a vertex
  // shared by batches is computed several times: every face must still come out as when it is
  // transformed on its own with the whole model's vertices.
  SceneSettings s;
  const Scene scene = floorGridScene(s);

  std::mt19937 rng(7);
  std::vector<uint32_t> order(scene.faceCount());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<uint32_t> batches = {0};
  while (batches.back() < order.size())
    batches.push_back(std::min(uint32_t(order.size()), batches.back() + 1 + uint32_t(rng() % 40)));

  for (bool cull : {true, false}) {
    test::FaceByFace byFace(scene, 1, cull);
    FaceTransformer byBatch(scene, 1, cull, FaceBatches{&order, &batches});
    for (const Vec3& eye : {Vec3(0.3, 0.2, 1.0), Vec3(-0.5, -0.3, 2.5)}) {
      const Camera camera = floorGridCamera(s, scene, eye);
      byFace.beginFrame(camera);
      byBatch.beginFrame(camera);
      FrameGeometry expected, actual;
      for (uint32_t id : order) byFace.transformFace(id, expected);
      for (uint32_t batch = 0; batch + 1 < batches.size(); ++batch)
        byBatch.pull(FaceRequest::batch(batch), actual);
      // Not vacuous: many faces went through the whole path, some were clipped or dropped.
      EXPECT_GT(expected.triangles.size() + expected.counters.backfaceCulled, 300u);
      EXPECT_GT(expected.triangles.size(), 0u);
      EXPECT_GT(expected.counters.clippedAway + expected.counters.degenerate, 0u);
      expectSameGeometry(expected, actual, cull ? "culling" : "no culling");
    }
  }
}

TEST(FaceTransformer, EveryFaceCarriesTheSampleRowsOfItsCorners) {
  // The rows a face records for binning (ScreenFace::rows) against those of its snapped
  // corners, clamped to the image: on a floor that crosses the near plane and leaves the image
  // (clipped faces, faces partly above and below it), with and without MSAA's 2 x 2 samples.
  SceneSettings s;
  const Scene scene = floorGridScene(s);
  for (int scale : {1, 2}) {
    FaceTransformer transformer(scene, scale, false, FaceBatches{});
    const Camera camera = floorGridCamera(s, scene, Vec3(0.3, 0.2, 1.0));
    transformer.beginFrame(camera);
    FrameGeometry g;
    transformer.pull(FaceRequest::frame(), g);
    ASSERT_GT(g.faces.size(), 100u);
    size_t clampedAbove = 0, clampedBelow = 0;
    for (const ScreenFace& face : g.faces) {
      int64_t minY = g.vertices[face.firstVertex].y, maxY = minY;
      for (uint32_t k = 1; k < face.vertexCount; ++k) {
        minY = std::min<int64_t>(minY, g.vertices[face.firstVertex + k].y);
        maxY = std::max<int64_t>(maxY, g.vertices[face.firstVertex + k].y);
      }
      // Rows whose centre (row + 1/2, in 1/256 units) lies in [minY, maxY].
      const int64_t first = std::max<int64_t>(0, (minY - 128 + 255) >> 8);
      const int64_t last = std::min<int64_t>(g.height - 1, (maxY - 128) >> 8);
      clampedAbove += minY < 0;
      clampedBelow += maxY >= int64_t(g.height) * 256;
      if (first > last) {
        EXPECT_GT(face.rows.first, face.rows.last) << "face " << face.id;
      } else {
        EXPECT_EQ(face.rows.first, first) << "face " << face.id;
        EXPECT_EQ(face.rows.last, last) << "face " << face.id;
      }
    }
    EXPECT_GT(clampedAbove + clampedBelow, 0u);  // not vacuous: the clamping was exercised
  }
}

TEST(FaceTransformer, InstancesGiveWhatFaceByFaceGives) {
  // Instances in a shuffled order, each with its vertices in arrays reused from one to the
  // next: a face of instance k (clipped ones included, which recompute clip coordinates from
  // the instance) must come out as when transformed on its own.
  SceneSettings s;
  const Scene scene = floorGridScene(s);
  const uint32_t nf = uint32_t(scene.mesh->faceCount());
  const std::vector<uint32_t> instances = {3, 0, 5, 1, 4, 2};
  for (bool cull : {true, false}) {
    test::FaceByFace byFace(scene, 1, cull);
    FaceTransformer byInstance(scene, 1, cull);
    for (const Vec3& eye : {Vec3(0.3, 0.2, 1.0), Vec3(-0.5, -0.3, 2.5)}) {
      const Camera camera = floorGridCamera(s, scene, eye);
      byFace.beginFrame(camera);
      byInstance.beginFrame(camera);
      FrameGeometry expected, actual;
      for (uint32_t k : instances) {
        for (uint32_t f = 0; f < nf; ++f) byFace.transformFace(k * nf + f, expected);
        byInstance.pull(FaceRequest::instance(k), actual);
      }
      // Not vacuous: many faces went through the whole path, some were clipped or dropped.
      EXPECT_GT(expected.triangles.size() + expected.counters.backfaceCulled, 300u);
      EXPECT_GT(expected.triangles.size(), 0u);
      EXPECT_GT(expected.counters.clippedAway, 0u);
      expectSameGeometry(expected, actual, cull ? "culling" : "no culling");
    }
  }
}

TEST(FaceTransformer, InstancesWhollyOutsideTheViewAreOnlyCounted) {
  // A tessellated unit square facing the eye (plus a face of two corners), repeated in a row
  // across the view and in a column along it: instances beyond a side, behind the eye or
  // beyond the far plane are skipped whole, one straddling the right side is not, and every
  // face and counter comes out as when transformed face by face.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(4, true, 0.0, p, f);
  f.push_back({0, 1});
  const auto mesh = test::makeMesh(p, f);
  // Eye at z = 2 looking down -z, 90 degrees: at z = 0 the view spans x, y in [-2, 2].
  struct Case {
    Grid grid;
    std::vector<bool> outside;  // per instance
  };
  const std::vector<Case> cases = {
      // x = -9, -6, -3, 0, 3, 6, 9: all but the middle one beyond a side.
      {Grid{{7, 1, 1}, {3.0, 0.0, 0.0}}, {true, true, true, false, true, true, true}},
      // y = -3, 0, 3: below and above.
      {Grid{{1, 3, 1}, {0.0, 3.0, 0.0}}, {true, false, true}},
      // z = -10 (beyond the far plane at distance 10), -5, 0, 5 and 10 (behind the eye).
      {Grid{{1, 1, 5}, {0.0, 0.0, 5.0}}, {true, false, false, true, true}},
      // x = -2, 0, 2: the outer two straddle the sides.
      {Grid{{3, 1, 1}, {2.0, 0.0, 0.0}}, {false, false, false}},
  };
  Warnings warnings;
  for (const Case& c : cases) {
    SceneSettings s = test::tinySettings(64);
    s.grid = c.grid;
    const Scene scene = makeScene(s, mesh);
    const Camera camera = makeCamera(scene);
    const uint32_t nf = uint32_t(scene.mesh->faceCount());
    test::FaceByFace byFace(scene, camera, 1, true);
    FaceTransformer byInstance(scene, camera, 1, true);
    FrameGeometry expected, actual;
    ASSERT_EQ(scene.instanceCount(), c.outside.size());
    for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
      EXPECT_EQ(byInstance.viewOfInstance(k).outside, bool(c.outside[k])) << "instance " << k;
      for (uint32_t face = 0; face < nf; ++face) byFace.transformFace(k * nf + face, expected);
      byInstance.pull(FaceRequest::instance(k), actual);
    }
    EXPECT_GT(expected.triangles.size(), 0u);
    EXPECT_GT(expected.counters.clippedAway, 0u);
    expectSameGeometry(expected, actual, "instances");
  }
}

TEST(FaceTransformer, InstanceNearestDepthBoundsEveryFaceTightly) {
  // Tessellated squares at several depths and tilts, seen from several eyes: no face of an
  // instance is nearer than viewOfInstance().nearest (its plane's least depth included), which
  // is within a millionth of the nearest corner of the instance's box; an instance reaching
  // past the near plane gets 0.
  // Flat and square-on too, where the box's nearest corners are vertices.
  Warnings warnings;
  int bounded = 0, zero = 0;
  for (double wave : {0.3, 0.0}) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> f;
    addTessellatedSquare(6, false, wave, p, f);
    const auto mesh = test::makeMesh(p, f);
    for (const Vec3& eye : {Vec3(0.0, 0.0, 3.0), Vec3(1.0, 0.7, 4.0), Vec3(-0.4, 0.2, 1.2)}) {
      SceneSettings s = test::tinySettings(96);
      s.grid = Grid{{2, 1, 4}, {0.7, 0.0, 0.9}};
      s.angle = wave > 0.0 ? 35.0 : 0.0;
      s.axis = Vec3(1.0, 1.0, 0.0);
      s.eye = eye;
      s.far = 50.0;
      const Scene scene = makeScene(s, mesh);
      const Camera camera = makeCamera(scene);
      const uint32_t nf = uint32_t(scene.mesh->faceCount());
      FaceTransformer t(scene, camera, 1, false);
      test::FaceByFace byFace(scene, camera, 1, false);
      for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
        const InstanceView view = t.viewOfInstance(k);
        const float nearest = view.nearest;
        const SampleRect& area = view.area;
        FrameGeometry g;
        for (uint32_t face = 0; face < nf; ++face) byFace.transformFace(k * nf + face, g);
        if (g.counters.clippedAway > 0) {  // reaches past the near plane or a side
          zero += nearest == 0.0f;
          continue;
        }
        for (const ScreenTriangle& tri : g.triangles) {
          ASSERT_LE(nearest, tri.plane.minDepth()) << "instance " << k;
          // And every sample it covers lies in the area.
          TriangleSetup b;
          if (!b.bounds(tri.v, 96, 96)) continue;
          EXPECT_TRUE(b.minX >= area.minX && b.maxX <= area.maxX && b.minY >= area.minY &&
                      b.maxY <= area.maxY)
              << "instance " << k;
        }
        ASSERT_FALSE(g.triangles.empty());
        double boxNearest = HUGE_VAL;
        for (int c = 0; c < 8; ++c) {
          Vec3 corner;
          for (int a = 0; a < 3; ++a) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (const Vec3& q : p) lo = std::min(lo, q[a]), hi = std::max(hi, q[a]);
            corner[a] = (c >> a & 1) ? hi : lo;
          }
          const Vec4 clip = t.modelViewProjection(k) * Vec4(corner[0], corner[1], corner[2], 1.0);
          boxNearest = std::min(boxNearest, (clip[2] / clip[3] + 1.0) * 0.5);
        }
        EXPECT_GT(nearest, 0.0f) << "instance " << k;
        EXPECT_LE(nearest, boxNearest) << "instance " << k;
        EXPECT_GT(nearest, boxNearest - 1e-6) << "instance " << k;
        ++bounded;
      }
    }
  }
  EXPECT_GT(bounded, 16);
  EXPECT_GT(zero, 0);
}

// Every instance of the scene (culling on), into `plain` without a filter and into `filtered`
// with `filter`.
void transformWithAndWithout(const Scene& scene, TriangleFilter& filter, FrameGeometry& plain,
                             FrameGeometry& filtered) {
  const Camera camera = makeCamera(scene);
  FaceTransformer without(scene, camera, 1, true), with(scene, camera, 1, true);
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    without.pull(FaceRequest::instance(k), plain);
    with.pull(FaceRequest::instance(k, &filter), filtered);
  }
}

// Marks the tiles of the left half of a 128-sample-wide image as hidden, for every instance.
class LeftHalfFilter : public TriangleFilter {
 public:
  std::vector<uint8_t> marked = std::vector<uint8_t>(8 * 8, 0);
  std::vector<float> bounds;  // what beginInstance() was told
  LeftHalfFilter() {
    for (int ty = 0; ty < 8; ++ty)
      for (int tx = 0; tx < 4; ++tx) marked[size_t(ty * 8 + tx)] = 1;
  }
  HiddenTiles beginInstance(float nearestDepth, const SampleRect& /*area*/) override {
    bounds.push_back(nearestDepth);
    return HiddenTiles{marked.data(), 4, 8};
  }
  bool hidden(const FixedPoint*, float, uint32_t) override { return false; }
};

TEST(FaceTransformer, FacesInHiddenTilesAreDroppedBeforeTheirDepths) {
  // A grid of tessellated squares in front of the eye, on a 128 x 128 image of 8 x 8 tiles
  // whose left half the filter marks: a face whose sample bounds lie in at most 2 x 2 marked
  // tiles is dropped and counted as filtered, every other face comes out as without the filter.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTessellatedSquare(7, false, 0.0, p,
                       f);  // odd: faces of the middle square straddle the image centre
  SceneSettings s = test::tinySettings(128);
  s.grid = Grid{{3, 2, 1}, {1.2, 1.2, 0.0}};
  s.eye = Vec3(0.0, 0.0, 2.5);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  LeftHalfFilter filter;
  FrameGeometry expected, actual;
  transformWithAndWithout(scene, filter, expected, actual);
  EXPECT_EQ(filter.bounds.size(), scene.instanceCount());
  for (float b : filter.bounds) EXPECT_GT(b, 0.0f);
  std::map<uint32_t, size_t> kept;
  for (size_t i = 0; i < actual.faces.size(); ++i) kept[actual.faces[i].id] = i;
  uint64_t dropped = 0, straddling = 0;
  for (const ScreenFace& face : expected.faces) {
    const ScreenTriangle& t = expected.triangles[face.firstTriangle];
    TriangleSetup bounds;
    ASSERT_TRUE(bounds.bounds(t.v, 128, 128));
    const bool inLeft = (bounds.maxX >> 4) < 4;
    const bool small = (bounds.maxX >> 4) - (bounds.minX >> 4) <= 1 &&
                       (bounds.maxY >> 4) - (bounds.minY >> 4) <= 1;
    if (inLeft && small) {
      EXPECT_EQ(kept.count(face.id), 0u) << face.id;
      ++dropped;
      continue;
    }
    straddling += (bounds.minX >> 4) < 4;
    ASSERT_EQ(kept.count(face.id), 1u) << face.id;
    const ScreenTriangle& u = actual.triangles[actual.faces[kept[face.id]].firstTriangle];
    EXPECT_TRUE(t.v[0] == u.v[0] && t.v[1] == u.v[1] && t.v[2] == u.v[2] &&
                t.plane.loBits == u.plane.loBits && t.plane.c == u.plane.c);
  }
  EXPECT_GT(dropped, 50u);
  EXPECT_GT(straddling, 5u);
  EXPECT_EQ(actual.counters.filtered, dropped);
  EXPECT_EQ(actual.faces.size(), expected.faces.size() - dropped);
  EXPECT_EQ(expected.counters.filtered, 0u);
}

TEST(FaceTransformer, TrianglesCoveringNoSampleCentreAreDroppedBeforeTheirPlane) {
  // 8 x 8 pixels over [-2, 2]^2 at z = 0: pixel column (x + 2) * 2, row (2 - y) * 2, sample
  // centres at half pixels. Face 0 spans columns 4.1-4.4 and rows 3.6-3.9: no centre. Face 1
  // (bigger) covers the centre of pixel (4, 4), at (0.25, -0.25). Both are front-facing and
  // inside the view volume.
  std::vector<Vec3> p = {{0.05, 0.05, 0.0}, {0.2, 0.05, 0.0}, {0.05, 0.2, 0.0},
                         {-0.2, -0.6, 0.0}, {0.8, -0.6, 0.0}, {-0.2, 0.4, 0.0}};
  const std::vector<std::vector<int>> f = {{0, 1, 2}, {3, 4, 5}};
  const SceneSettings s = test::tinySettings(8);
  Warnings warnings;
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  FaceTransformer transformer(scene, makeCamera(scene), 1, true);
  FrameGeometry g;
  transformer.pull(FaceRequest::instance(0), g);
  ASSERT_EQ(g.faces.size(), 1u);  // no plane set up, nothing stored for face 0
  EXPECT_EQ(g.faces[0].id, 1u);
  // Counted nowhere, as the z-buffer's set-up never counted them.
  EXPECT_EQ(g.counters.degenerate + g.counters.backfaceCulled + g.counters.clippedAway, 0u);
  // The same faces one at a time (the general path) agree.
  FrameGeometry one;
  test::FaceByFace byFace(scene, makeCamera(scene), 1, true);
  for (uint32_t id = 0; id < 2; ++id) byFace.transformFace(id, one);
  ASSERT_EQ(one.faces.size(), 1u);
  EXPECT_EQ(one.faces[0].id, 1u);
  // And no algorithm draws face 0, while face 1 owns the sample it covers.
  for (const char* alg : {"zbuffer", "scanline", "interval", "hierarchical", "octree"}) {
    const test::Rendered r = test::render(scene, alg);
    EXPECT_EQ(keyFaceId(r.buffer.row(4)[4]), 1u) << alg;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) EXPECT_NE(keyFaceId(r.buffer.row(y)[x]), 0u) << alg;
  }
}

// Drops every third face it is asked about and remembers what it was told.
class RecordingFilter : public TriangleFilter {
 public:
  struct Asked {
    FixedPoint v[3];
    float nearestDepth;
  };
  std::map<uint32_t, Asked> asked;
  bool hidden(const FixedPoint* v, float nearestDepth, uint32_t faceId) override {
    asked[faceId] = Asked{{v[0], v[1], v[2]}, nearestDepth};
    return faceId % 3 == 0;
  }
};

TEST(FaceTransformer, FilterSeesTheFaceAsDrawnAndDropsOnlyWhatItRejects) {
  SceneSettings s;
  const Scene scene = floorGridScene(s);
  RecordingFilter filter;
  FrameGeometry expected, actual;
  transformWithAndWithout(scene, filter, expected, actual);
  std::map<uint32_t, size_t> actualFace;
  for (size_t i = 0; i < actual.faces.size(); ++i) actualFace[actual.faces[i].id] = i;
  size_t dropped = 0, keptAsked = 0, notAsked = 0;
  for (const ScreenFace& face : expected.faces) {
    const auto asked = filter.asked.find(face.id);
    const auto kept = actualFace.find(face.id);
    if (asked != filter.asked.end() && face.id % 3 == 0) {
      EXPECT_TRUE(kept == actualFace.end()) << "face " << face.id << " was rejected";
      ++dropped;
      continue;
    }
    ASSERT_TRUE(kept != actualFace.end()) << "face " << face.id;
    const ScreenFace& other = actual.faces[kept->second];
    ASSERT_EQ(face.triangleCount, other.triangleCount);
    for (uint32_t t = 0; t < face.triangleCount; ++t) {
      const ScreenTriangle& x = expected.triangles[face.firstTriangle + t];
      const ScreenTriangle& y = actual.triangles[other.firstTriangle + t];
      EXPECT_TRUE(x.v[0] == y.v[0] && x.v[1] == y.v[1] && x.v[2] == y.v[2] && x.id == y.id &&
                  x.plane.loBits == y.plane.loBits && x.plane.c == y.plane.c)
          << face.id;
    }
    if (asked == filter.asked.end()) {
      ++notAsked;  // polygons and clipped faces take the general path
      continue;
    }
    ++keptAsked;
    // What the filter was told is what the pixel loops get: the corners, and the nearest
    // corner depth as the plane's clamp holds it, bit for bit.
    const ScreenTriangle& t = expected.triangles[face.firstTriangle];
    EXPECT_EQ(floatBits(asked->second.nearestDepth), uint32_t(t.plane.loBits)) << face.id;
    std::set<std::pair<int32_t, int32_t>> told, drawn;
    for (int i = 0; i < 3; ++i) {
      told.insert({asked->second.v[i].x, asked->second.v[i].y});
      drawn.insert({t.v[i].x, t.v[i].y});
    }
    EXPECT_EQ(told, drawn) << face.id;
  }
  // Faces that cover no sample centre (small ones, between centres) are dropped before the
  // filter is asked: here 17 dropped and 39 kept of those asked.
  EXPECT_GT(dropped, 10u);
  EXPECT_GT(keptAsked, 25u);
  EXPECT_GT(notAsked, 10u);
  EXPECT_EQ(actual.faces.size(), expected.faces.size() - dropped);
  EXPECT_EQ(expected.counters.backfaceCulled, actual.counters.backfaceCulled);
}

// Hides every face whose id is a multiple of 5: the same verdict from any thread.
class EveryFifthFilter : public TriangleFilter {
 public:
  bool hidden(const FixedPoint*, float, uint32_t faceId) override { return faceId % 5 == 0; }
};

// `parts` one after another as one geometry: each part's indices moved by what came before it.
FrameGeometry joinParts(const std::vector<FrameGeometry>& parts) {
  FrameGeometry out;
  for (const FrameGeometry& part : parts) {
    const uint32_t vertices = uint32_t(out.vertices.size()), faces = uint32_t(out.faces.size()),
                   triangles = uint32_t(out.triangles.size());
    out.vertices.insert(out.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (ScreenFace face : part.faces) {
      face.firstVertex += vertices;
      face.firstTriangle += triangles;
      out.faces.push_back(face);
    }
    for (ScreenTriangle t : part.triangles) {
      t.face += faces;
      out.triangles.push_back(t);
    }
    out.counters += part.counters;
  }
  return out;
}

TEST(FaceTransformer, InstancePartsOnSeveralThreadsJoinToOneThreadsInstance) {
  // A floor of 4900 faces (two chunks of the transform on several threads) in a grid that
  // crosses the near plane and leaves the image, with and without culling and a filter: an
  // instance's parts, joined, are its geometry on one thread, and so are its parts on one
  // thread (a single part); the geometry given beside the parts gets their counters.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTiltedFloor(70, true, p, f);
  SceneSettings s = test::tinySettings(90);
  s.grid = Grid{{3, 1, 2}, {4.0, 0.0, 5.0}};
  const Scene scene = makeScene(s, test::makeMesh(p, f));
  const Camera camera = floorGridCamera(s, scene, Vec3(0.3, 0.2, 1.0));
  EveryFifthFilter filter;
  for (bool cull : {true, false}) {
    for (TriangleFilter* asked :
         {static_cast<TriangleFilter*>(nullptr), static_cast<TriangleFilter*>(&filter)}) {
      for (int n : {1, 2, 3}) {
        FaceTransformer one(scene, 1, cull);
        one.beginFrame(camera);
        const Threads threads(n);
        FaceTransformer several(scene, 1, cull);
        several.setThreads(&threads);
        several.beginFrame(camera);
        size_t kept = 0;
        for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
          FrameGeometry expected;
          one.pull(FaceRequest::instance(k, asked), expected);
          std::vector<FrameGeometry> parts(7);  // more than it needs: resized
          FrameGeometry counted;                // gets the parts' counters
          several.pull(FaceRequest::instance(k, asked), counted, &parts);
          EXPECT_TRUE(counted.faces.empty() && counted.triangles.empty());
          EXPECT_EQ(counted.counters.filtered, expected.counters.filtered);
          EXPECT_EQ(counted.counters.backfaceCulled, expected.counters.backfaceCulled);
          if (n > 1 && !expected.faces.empty()) {
            EXPECT_GT(parts.size(), 1u);
          }
          if (n == 1) {
            EXPECT_EQ(parts.size(), 1u);
          }
          const std::string what = std::string(cull ? "culling" : "no culling") +
                                   (asked ? ", filter" : "") + ", " + std::to_string(n) +
                                   " threads, instance " + std::to_string(k);
          expectSameGeometry(expected, joinParts(parts), what);
          EXPECT_EQ(expected.counters.filtered, joinParts(parts).counters.filtered) << what;
          kept += expected.faces.size();
        }
        EXPECT_GT(kept, 4900u);  // not vacuous: more than one instance's worth of faces
      }
    }
  }
}

}  // namespace
}  // namespace zrender
