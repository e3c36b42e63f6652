#include "zrender/raster/PolygonEdges.hpp"

#include <algorithm>

namespace zrender {

namespace {

// Stable counting sort of `in` by row (keyOf(item) in [0, rows)) into `out`. `bucket` holds
// the number of items of each row r at bucket[r + 1] (bucket[0] = 0), counted as the items were
// made, and receives the rows + 1 offsets. `moved(i, j)` is told that in[i] went to out[j].
template <typename Vector, typename KeyOf, typename Moved>
void sortByRow(const Vector& in, int rows, KeyOf keyOf, Vector& out, std::vector<uint32_t>& bucket,
               Moved moved) {
  for (int r = 0; r < rows; ++r) bucket[size_t(r) + 1] += bucket[size_t(r)];
  out.resize(in.size());
  // bucket[r] serves as the cursor of row r, then is shifted back into place.
  for (size_t i = 0; i < in.size(); ++i) {
    const uint32_t j = bucket[size_t(keyOf(in[i]))]++;
    out[j] = in[i];
    moved(i, j);
  }
  for (int r = rows; r > 0; --r) bucket[size_t(r)] = bucket[size_t(r) - 1];
  bucket[0] = 0;
}

}  // namespace

void PolygonTables::build(const FrameGeometry& g, int width, int height) {
  begin(height, 0, height);
  if (width > 0 && rowEnd_ > rowBegin)
    for (size_t f = 0; f < g.faces.size(); ++f) classify(g, uint32_t(f), width);
  sort();
}

void PolygonTables::build(const std::vector<const FrameGeometry*>& parts, int width, int height,
                          int bandBegin, int bandEnd, const PartFace* faces, size_t count) {
  begin(height, bandBegin, bandEnd);
  if (width > 0 && rowEnd_ > rowBegin)
    for (size_t i = 0; i < count; ++i) classify(*parts[faces[i].part], faces[i].face, width);
  sort();
}

void PolygonTables::begin(int height, int bandBegin, int bandEnd) {
  height_ = std::max(height, 0);
  rowEnd_ = std::min(bandEnd, height_);
  rowBegin = bandBegin;
  unsortedPolygons_.clear();
  unsortedEdges_.clear();
  triangleCount = 0;
  const size_t rows = size_t(std::max(rowEnd_ - rowBegin, 0));
  polygonsEnding.assign(rows, 0);
  polygonBucket.assign(rows + 1, 0);
  edgeBucket.assign(rows + 1, 0);
}

void PolygonTables::classify(const FrameGeometry& g, uint32_t f, int width) {
  const int height = height_, rowEnd = rowEnd_;
  const ScreenFace& face = g.faces[f];
  const FixedPoint* v = g.vertices.data() + face.firstVertex;
  const uint32_t n = face.vertexCount;
  // Horizontal extent first: a sample is covered only if its centre lies in [minX, maxX).
  int32_t minX = v[0].x, maxX = v[0].x;
  for (uint32_t k = 1; k < n; ++k) {
    minX = std::min(minX, v[k].x);
    maxX = std::max(maxX, v[k].x);
  }
  if (firstSampleAtOrAfter(minX) > width - 1 || lastSampleAtOrBefore(maxX) < 0) return;

  const uint32_t polygon = uint32_t(unsortedPolygons_.size());
  const uint32_t edgeBegin = uint32_t(unsortedEdges_.size());
  int32_t topRow = rowEnd, bottomRow = -1, imageTop = height;
  for (uint32_t k = 0; k < n; ++k) {
    const FixedPoint& a = v[k];
    const FixedPoint& b = v[k + 1 == n ? 0 : k + 1];
    if (a.y == b.y) continue;  // horizontal edges are never active
    const FixedPoint& top = a.y < b.y ? a : b;
    const FixedPoint& bottom = a.y < b.y ? b : a;
    // Active rows: centre in [top.y, bottom.y), i.e. centre <= bottom.y - 1.
    const int32_t imageFirst = std::max(firstSampleAtOrAfter(top.y), 0);
    const int32_t imageLast = std::min(lastSampleAtOrBefore(int64_t(bottom.y) - 1), height - 1);
    if (imageFirst <= imageLast) imageTop = std::min(imageTop, imageFirst);
    const int32_t first = std::max(imageFirst, rowBegin);
    const int32_t last = std::min(imageLast, rowEnd - 1);
    if (first > last) continue;
    unsortedEdges_.push_back(ClassifiedEdge{top, bottom, first, last, polygon});
    ++edgeBucket[size_t(first - rowBegin) + 1];
    topRow = std::min(topRow, first);
    bottomRow = std::max(bottomRow, last);
  }
  const uint32_t edgeCount = uint32_t(unsortedEdges_.size()) - edgeBegin;
  if (edgeCount == 0) return;
  unsortedPolygons_.push_back(ClassifiedPolygon{g.triangles[face.firstTriangle].plane, face.id,
                                                topRow, bottomRow, 0, edgeCount});
  ++polygonsEnding[size_t(bottomRow - rowBegin)];
  ++polygonBucket[size_t(topRow - rowBegin) + 1];
  if (imageTop >= rowBegin) triangleCount += face.triangleCount;
}

void PolygonTables::sort() {
  const int rows = std::max(rowEnd_ - rowBegin, 0);
  // CPT: polygons by top row; each gets its slots in the edge pool in that order.
  newIndex_.resize(unsortedPolygons_.size());
  sortByRow(
      unsortedPolygons_, rows, [&](const ClassifiedPolygon& p) { return p.topRow - rowBegin; },
      polygons, polygonBucket, [this](size_t i, uint32_t j) { newIndex_[i] = j; });
  uint32_t slot = 0;
  for (ClassifiedPolygon& p : polygons) {
    p.edgeBegin = slot;
    slot += p.edgeCount;
  }
  // CET: edges by first row, pointing at the sorted polygons.
  for (ClassifiedEdge& e : unsortedEdges_) e.polygon = newIndex_[e.polygon];
  sortByRow(
      unsortedEdges_, rows, [&](const ClassifiedEdge& e) { return e.firstRow - rowBegin; }, edges,
      edgeBucket, [](size_t, uint32_t) {});
}

}  // namespace zrender
