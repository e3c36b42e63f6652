#include "zrender/visibility/HierarchicalAlgorithm.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/raster/RowBands.hpp"
#include "zrender/raster/TriangleFill.hpp"
#include "zrender/transform/ScreenRows.hpp"

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

// The transform's filter with several threads: the tiles of each band's pyramid where an
// instance's nearest depth is behind, marked by the algorithm before the instance is pulled
// (markInstance), as the bands draw the instance before it while its faces are transformed; no
// face is asked alone (the bands' tests drop such faces then).
class BandTilesFilter : public TriangleFilter {
 public:
  BandTilesFilter(const std::vector<HzbRasterizer>& rasterizers, const RowBands& bands,
                  const FrameBuffer& fb)
      : rasterizers_(rasterizers), bands_(bands) {
    const int tilesX = (fb.width() + DepthPyramid::kTileSize - 1) >> DepthPyramid::kTileShift;
    const int tilesY = (fb.height() + DepthPyramid::kTileSize - 1) >> DepthPyramid::kTileShift;
    hiddenTiles_.assign(size_t(tilesX) * size_t(tilesY), 0);
    tilesX_ = tilesX;
  }
  // As PyramidFilter's beginInstance(), each band marking its own rows of tiles, for the
  // instance seen as `view`, from the pyramids as they are now: the pull asks beginInstance()
  // for these marks under the same conditions (inside the view volume, nearest depth > 0).
  void markInstance(const InstanceView& view) {
    if (view.outside || !(view.nearest > 0.0f)) return;
    mark(marked_, 0);
    marked_ = view.area;
    mark(view.area, makeDepthKey(view.nearest, 0));
  }
  HiddenTiles beginInstance(float, const SampleRect&) override {
    return HiddenTiles{hiddenTiles_.data(), DepthPyramid::kTileShift, tilesX_};
  }
  bool hidden(const FixedPoint*, float, uint32_t) override { return false; }
  bool asksFaces() const override { return false; }

 private:
  // Sets the tiles of `area` to whether `key` is behind them (0: to 0).
  void mark(const SampleRect& area, DepthKey key) {
    if (area.maxX < area.minX || area.maxY < area.minY) return;
    for (int b = bands_.bandOf(area.minY); b <= bands_.bandOf(area.maxY); ++b) {
      const int minY = std::max(area.minY, bands_.rowBegin(b));
      const int maxY = std::min(area.maxY, bands_.rowEnd(b) - 1);
      rasterizers_[size_t(b)].pyramid().tilesBehind(key, area.minX, minY, area.maxX, maxY,
                                                    hiddenTiles_);
    }
  }

  const std::vector<HzbRasterizer>& rasterizers_;
  const RowBands& bands_;
  std::vector<uint8_t> hiddenTiles_;  // per tile of the image
  int tilesX_ = 0;
  SampleRect marked_;  // where hiddenTiles_ may hold nonzero bytes
};

}  // namespace

void HierarchicalAlgorithm::orderInstances(const FrameInput& input) {
  const Scene& scene = input.scene;
  // Nearest instance first (by the centre of its box), which fills the pyramid with what hides
  // the others; the order never changes the result.
  const Vec3 eye = input.camera.eye;
  instances_.resize(scene.instanceCount());
  std::vector<double> distance(instances_.size());
  for (uint32_t k = 0; k < scene.instanceCount(); ++k) {
    const Mat4& model = scene.modelMatrix(k);
    const Vec3 centre = scene.modelOf(k).box.centre();
    const Vec4 c = model * Vec4(centre[0], centre[1], centre[2], 1.0);
    const Vec3 d(c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]);
    distance[k] = d.dot(d);
    instances_[k] = k;
  }
  std::stable_sort(instances_.begin(), instances_.end(),
                   [&](uint32_t a, uint32_t b) { return distance[a] < distance[b]; });
}

void HierarchicalAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  orderInstances(input);
  if (input.parallel()) {
    renderBands(input, fb, stats);
    return;
  }
  FrameGeometry& g = input.geometry;
  rasterizer_.begin(fb);
  PyramidFilter filter(rasterizer_, stats);
  for (size_t i = 0; i < instances_.size(); ++i) {
    const size_t firstTriangle = g.triangles.size();
    // The first instance finds the pyramid empty: nothing to ask it.
    input.source.pull(FaceRequest::instance(instances_[i], i > 0 ? &filter : nullptr), g);

    // Band order keeps the z-buffer's cache locality; in the last instance, the rows above a
    // band are final once it starts (no later triangle starts above it).
    const bool last = i + 1 == instances_.size();
    const GeometryVector<ScreenTriangle>& triangles =
        bands_.sort(g, firstTriangle, fb.width(), fb.height());
    for (int band = 0; band < bands_.bandCount(); ++band) {
      const int bandTop = band << TriangleBands::kBandShift;
      if (last && bandTop > 0) {
        rasterizer_.finishRows(bandTop);
        input.rowsDone(bandTop - (1 << TriangleBands::kBandShift), bandTop);
      }
      for (uint32_t t = bands_.bandStart(band); t < bands_.bandStart(band + 1); ++t)
        rasterizer_.drawTriangle(triangles[t], stats);
    }
  }
  rasterizer_.finish();
  stats.trianglesHzbCulled += g.counters.filtered;
}

void HierarchicalAlgorithm::renderBands(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const Threads& threads = *input.threads;
  FrameGeometry& g = input.geometry;
  // The bands share out the rows the instances cover, where the work is.
  const RowSpan busy = screenRows(input.scene, input.camera, fb.height());
  const RowBands bands(fb.height(), threads.count() * kBandsPerThread, DepthPyramid::kTileSize,
                       busy.begin, busy.end);
  bandRasterizers_.resize(size_t(bands.count()));
  for (int b = 0; b < bands.count(); ++b)
    bandRasterizers_[size_t(b)].begin(fb, bands.rowBegin(b), bands.rowEnd(b));
  bandStats_.assign(size_t(bands.count()), RenderStats());
  BandTilesFilter filter(bandRasterizers_, bands, fb);
  // Band b's triangles of the instance listed last.
  const auto drawBand = [&](size_t b) {
    const ScreenTriangle* const* t = bandTriangles_.items(int(b));
    for (size_t k = 0; k < bandTriangles_.size(int(b)); ++k)
      bandRasterizers_[b].drawTriangle(*t[k], bandStats_[b]);
  };
  // Each instance is drawn while the next one is transformed: the pull one task, the bands that
  // hold the instance's triangles one task each. The next one's filter marks its tiles before,
  // from the pyramids as the instances before the one being drawn left them.
  instanceParts_.resize(instances_.size());
  FaceParts faces;  // every part of the instances pulled so far
  std::vector<size_t> segments;
  std::vector<size_t> busyBands;  // bands with triangles of the instance listed last
  for (size_t i = 0; i < instances_.size(); ++i) {
    std::vector<FrameGeometry>& parts = instanceParts_[i];
    if (i > 0) filter.markInstance(input.source.viewOfInstance(instances_[i]));
    const FaceRequest request = FaceRequest::instance(instances_[i], i > 0 ? &filter : nullptr);
    threads.forEach(busyBands.size() + 1, [&](size_t j) {
      if (j == 0)
        input.source.pull(request, g, &parts);
      else
        drawBand(busyBands[j - 1]);
    });
    segments.clear();
    for (const FrameGeometry& part : parts) {
      faces.push_back(&part);
      segments.push_back(part.triangles.size());
    }
    // The instance's triangles in each band they reach.
    bandTriangles_.build(
        segments, bands, threads,
        [&](size_t s, size_t t, int& top, int& bottom) {
          const FixedPoint* v = parts[s].triangles[t].v;
          const SampleRect r = sampleBounds(v[0], v[1], v[2], fb.width(), fb.height());
          top = r.minY;
          bottom = r.maxY;
          return !r.empty();
        },
        [&](size_t s, size_t t) { return &parts[s].triangles[t]; });
    busyBands.clear();
    for (int b = 0; b < bands.count(); ++b)
      if (bandTriangles_.size(b) > 0) busyBands.push_back(size_t(b));
  }
  // The parts hold every face that can be in the buffer: the shader prepares them, then the
  // bands draw the last instance and are finished and shaded, each by the thread that drew it,
  // while its keys are in that thread's cache.
  input.facesGathered(faces);
  bandOrder_.forEachBand(threads, bands, [&](size_t b) {
    if (!instances_.empty()) drawBand(b);
    bandRasterizers_[b].finish();
    input.rowsDone(bands.rowBegin(int(b)), bands.rowEnd(int(b)));
  });
  for (const RenderStats& s : bandStats_) stats += s;
  stats.trianglesHzbCulled += g.counters.filtered;
}

}  // namespace zrender
