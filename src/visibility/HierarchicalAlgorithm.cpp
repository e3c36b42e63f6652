#include "zrender/visibility/HierarchicalAlgorithm.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/raster/TriangleFill.hpp"

namespace zrender {

namespace {

// The transform's filter: a triangle face is dropped when the pyramid proves it hidden.
class PyramidFilter : public TriangleFilter {
 public:
  PyramidFilter(const HzbRasterizer& rasterizer, RenderStats& stats)
      : rasterizer_(rasterizer), stats_(stats) {}
  // The tiles of the instance's area where even its nearest depth (with the smallest id) is
  // behind; those of the previous instance's area are unmarked first, so that the work is
  // that of the instance's size on screen.
  HiddenTiles beginInstance(float nearestDepth, const SampleRect& area) override {
    const DepthPyramid& pyramid = rasterizer_.pyramid();
    if (marked_.maxX >= marked_.minX)
      pyramid.tilesBehind(0, marked_.minX, marked_.minY, marked_.maxX, marked_.maxY, hiddenTiles_);
    marked_ = area;
    if (area.maxX >= area.minX)
      pyramid.tilesBehind(makeDepthKey(nearestDepth, 0), area.minX, area.minY, area.maxX, area.maxY,
                          hiddenTiles_);
    else
      hiddenTiles_.resize(0);
    if (hiddenTiles_.empty()) return HiddenTiles();
    return HiddenTiles{hiddenTiles_.data(), DepthPyramid::kTileShift, pyramid.tilesX()};
  }
  bool hidden(const FixedPoint* v, float nearestDepth, uint32_t faceId) override {
    return rasterizer_.rejects(v, nearestDepth, faceId, stats_);
  }

 private:
  const HzbRasterizer& rasterizer_;
  RenderStats& stats_;
  std::vector<uint8_t> hiddenTiles_;  // per pyramid tile, for the current instance
  SampleRect marked_;                 // where hiddenTiles_ may hold nonzero bytes
};

}  // namespace

FaceBatches HierarchicalAlgorithm::prepare(const Scene& scene) {
  meshCentre_ = boundingBox(scene.mesh->positions).centre();
  return FaceBatches();
}

void HierarchicalAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const Scene& scene = input.scene;
  FrameGeometry& g = input.geometry;
  // Nearest instance first (by the centre of its box), which fills the pyramid with what hides
  // the others; the order never changes the result.
  const Vec3 eye = input.camera.eye;
  instances_.resize(scene.instanceCount());
  std::vector<double> distance(instances_.size());
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    const Mat4 model = scene.modelMatrix(k);
    const Vec4 c = model * Vec4(meshCentre_[0], meshCentre_[1], meshCentre_[2], 1.0);
    const Vec3 d(c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]);
    distance[k] = d.dot(d);
    instances_[k] = k;
  }
  std::stable_sort(instances_.begin(), instances_.end(),
                   [&](uint32_t a, uint32_t b) { return distance[a] < distance[b]; });

  rasterizer_.begin(fb);
  PyramidFilter filter(rasterizer_, stats);
  for (size_t i = 0; i < instances_.size(); ++i) {
    const size_t firstTriangle = g.triangles.size();
    // The first instance finds the pyramid empty: nothing to ask it.
    input.source.pullInstance(instances_[i], g, i > 0 ? &filter : nullptr);

    // Band order keeps the z-buffer's cache locality; in the last instance, the rows above a
    // band are final once it starts (no later triangle starts above it).
    const bool last = i + 1 == instances_.size();
    const GeometryVector<ScreenTriangle>& triangles =
        bands_.sort(g, firstTriangle, fb.width(), fb.height());
    for (int band = 0; band < bands_.bandCount(); ++band) {
      const int bandTop = band << TriangleBands::kBandShift;
      if (last && bandTop > 0) {
        rasterizer_.finishRows(bandTop);
        input.rowsFinal(bandTop);
      }
      for (uint32_t t = bands_.bandStart(band); t < bands_.bandStart(band + 1); ++t)
        rasterizer_.drawTriangle(triangles[t], stats);
    }
  }
  rasterizer_.finish();
  stats.trianglesHzbCulled += g.counters.filtered;
}

}  // namespace zrender
