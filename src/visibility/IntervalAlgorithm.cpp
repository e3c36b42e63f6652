#include "zrender/visibility/IntervalAlgorithm.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

namespace {

// Longest run of samples decided one by one before trying the end-value proof again.
constexpr int kMaxSampleChunk = 64;

bool samePlane(const DepthPlane& p, const DepthPlane& q) {
  return p.a == q.a && p.b == q.b && p.c == q.c;
}

// The key a face leaves at a sample when it is the nearest: the z-buffer writes only keys below
// the cleared key (a NaN or -0 depth never is), so the winner is capped by kClearKey.
inline DepthKey capped(DepthKey k) {
  return std::min(k, kClearKey);
}

}  // namespace

void IntervalAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  const int width = fb.width(), height = fb.height();
  if (!input.parallel()) {
    input.source.pull(FaceRequest::frame(), input.geometry);
    const FrameGeometry& g = input.geometry;
    whole_.tables_.build(g, width, height);
    stats.trianglesRasterized += whole_.tables_.triangleCount;
    whole_.drawRows(height, input, fb, stats);
    return;
  }
  perThread_.resize(size_t(input.threads->count()));
  bands_.draw(
      input, width, height, stats,
      [&](int thread) -> PolygonTables& { return perThread_[size_t(thread)].tables_; },
      [&](int thread, int rowEnd, RenderStats& bandStats) {
        perThread_[size_t(thread)].drawRows(rowEnd, input, fb, bandStats);
      });
}

void IntervalAlgorithm::Band::drawRows(int rowEnd, const FrameInput& input, FrameBuffer& fb,
                                       RenderStats& stats) {
  const int width = fb.width();
  inPosition_.assign(tables_.polygons.size(), -1);
  inside_.clear();
  activeEdges_.clear();
  steppers_.resize(tables_.edges.size());
  counters_ = Counters();

  size_t activePolygons = 0, maxActiveEdges = 0, maxActivePolygons = 0;
  for (int y = tables_.rowBegin; y < rowEnd; ++y) {
    const int r = y - tables_.rowBegin;
    activePolygons += tables_.polygonBucket[r + 1] - tables_.polygonBucket[r];
    maxActivePolygons = std::max(maxActivePolygons, activePolygons);
    // The table is still sorted from the last row but for edges that crossed while stepping:
    // a few adjacent swaps (insertion sort).
    for (size_t k = 1; k < activeEdges_.size(); ++k) {
      if (activeEdges_[k - 1].column <= activeEdges_[k].column) continue;
      const ActiveEdge e = activeEdges_[k];
      size_t j = k;
      for (; j > 0 && activeEdges_[j - 1].column > e.column; --j)
        activeEdges_[j] = activeEdges_[j - 1];
      activeEdges_[j] = e;
    }
    // Edges whose first row is y join the table: sorted among themselves, then merged in.
    const uint32_t firstNew = tables_.edgeBucket[r], endNew = tables_.edgeBucket[r + 1];
    if (firstNew < endNew) {
      newEdges_.clear();
      for (uint32_t k = firstNew; k < endNew; ++k) {
        const ClassifiedEdge& e = tables_.edges[k];
        steppers_[k].start(e.top, e.bottom, y);
        newEdges_.push_back(ActiveEdge{steppers_[k].column, e.polygon, k, e.lastRow});
      }
      const auto byColumn = [](const ActiveEdge& a, const ActiveEdge& b) {
        return a.column < b.column;
      };
      std::sort(newEdges_.begin(), newEdges_.end(), byColumn);
      merged_.resize(activeEdges_.size() + newEdges_.size());
      std::merge(activeEdges_.begin(), activeEdges_.end(), newEdges_.begin(), newEdges_.end(),
                 merged_.begin(), byColumn);
      activeEdges_.swap(merged_);
    }
    maxActiveEdges = std::max(maxActiveEdges, activeEdges_.size());

    // Walk the crossings left to right; the span [pos, column) lies before each one.
    DepthKey* row = fb.row(y);
    int pos = 0;
    for (const ActiveEdge& e : activeEdges_) {
      const int column = std::min(std::max(e.column, 0), width);
      if (column > pos) {
        fillSpan(pos, column, y, row);
        pos = column;
      }
      // Even-odd: each crossing flips the polygon between outside and inside.
      int32_t& at = inPosition_[e.polygon];
      if (at < 0) {
        at = int32_t(inside_.size());
        inside_.push_back(e.polygon);
      } else {
        inPosition_[inside_.back()] = at;
        inside_[size_t(at)] = inside_.back();
        inside_.pop_back();
        at = -1;
      }
    }
    if (pos < width) fillSpan(pos, width, y, row);   // inside_ is empty here
    for (uint32_t p : inside_) inPosition_[p] = -1;  // a closed polygon crosses evenly: none
    inside_.clear();

    // Edges ending on this row leave; the others step to the next row, order kept.
    size_t m = 0;
    for (size_t k = 0; k < activeEdges_.size(); ++k) {
      ActiveEdge e = activeEdges_[k];
      if (e.lastRow == y) continue;
      EdgeStepper& step = steppers_[e.slot];
      step.step();
      e.column = step.column;
      activeEdges_[m++] = e;
    }
    activeEdges_.resize(m);
    activePolygons -= tables_.polygonsEnding[size_t(r)];
    input.rowFinished(y);
  }

  // No per-sample depth test: every covered sample is decided and written exactly once.
  stats.pixelsTested += counters_.samplesWritten;
  stats.pixelsWritten += counters_.samplesWritten;
  stats.extra.emplace_back("spans", counters_.spans);
  stats.extra.emplace_back("spans_multi", counters_.multiSpans);
  stats.extra.emplace_back("spans_split", counters_.splitSpans);
  stats.extra.emplace_back("samples_one_by_one", counters_.samplesOneByOne);
  stats.extra.emplace_back("keys_compared_one_by_one", counters_.keysCompared);
  stats.extra.emplace_back("max_active_edges", maxActiveEdges);
  stats.extra.emplace_back("max_active_polygons", maxActivePolygons);
}

void IntervalAlgorithm::Band::fillSpan(int left, int right, int y, DepthKey* row) {
  const size_t n = inside_.size();
  if (n == 0) {
    std::fill(row + left, row + right, kClearKey);
    return;
  }
  ++counters_.spans;
  counters_.samplesWritten += uint64_t(right - left);
  if (n == 1) {
    // The common case: one polygon covers the span and is visible all along it.
    const ClassifiedPolygon& p = tables_.polygons[inside_[0]];
    const double rowBase = p.plane.rowBase(y);
    for (int x = left; x < right; ++x) row[x] = capped(makeDepthKey(p.plane.at(x, rowBase), p.id));
    return;
  }
  ++counters_.multiSpans;
  candidates_.resize(n);
  const double rowCentre = y + 0.5;
  for (size_t i = 0; i < n; ++i) {
    const ClassifiedPolygon& p = tables_.polygons[inside_[i]];
    Candidate& c = candidates_[i];
    c.a = p.plane.a;
    c.rowBase = p.plane.rowBase(y);
    c.rowMagnitude = std::abs(p.plane.b * rowCentre) + std::abs(p.plane.c);
    c.plane = &p.plane;
    c.id = p.id;
  }
  resolveSpan(left, right - 1, row);
}

void IntervalAlgorithm::Band::resolveSpan(int left, int right, DepthKey* row) {
  const size_t n = candidates_.size();
  int x = left, chunk = 1, pieces = 0;
  while (x <= right) {
    ++pieces;
    // Exact keys at the sub-span's left end, depths at its right end.
    size_t w = 0;
    for (size_t i = 0; i < n; ++i) {
      Candidate& c = candidates_[i];
      c.zLeft = c.plane->at(x, c.rowBase);
      c.keyLeft = makeDepthKey(c.zLeft, c.id);
      c.zRight = c.plane->at(right, c.rowBase);
      if (c.keyLeft < candidates_[w].keyLeft) w = i;
    }
    const int end = x < right ? provenExtent(w, x, right) : x;
    if (end >= x) {
      // w is the nearest on [x, end]: its keys fill the run.
      const Candidate& c = candidates_[w];
      for (int t = x; t <= end; ++t) row[t] = capped(makeDepthKey(c.plane->at(t, c.rowBase), c.id));
      x = end + 1;
      chunk = 1;
      continue;
    }
    // Not proven (near tie, crossing, clamped depth): decide a few samples from exact keys,
    // more at a time while the proof keeps failing.
    const int last = std::min(right, x + chunk - 1);
    for (int t = x; t <= last; ++t) {
      DepthKey best = kClearKey;
      for (const Candidate& c : candidates_)
        best = std::min(best, makeDepthKey(c.plane->at(t, c.rowBase), c.id));
      row[t] = best;
    }
    counters_.samplesOneByOne += uint64_t(last - x + 1);
    counters_.keysCompared += uint64_t(last - x + 1) * n;
    x = last + 1;
    chunk = std::min(chunk * 2, kMaxSampleChunk);
  }
  if (pieces > 1) ++counters_.splitSpans;
}

// Why the proof is sound. For a candidate at column t let D(t) = a (t + 0.5) + b (y + 0.5) + c
// (exact reals), f(t) the unclamped float that DepthPlane::at computes (three double roundings,
// one float rounding) and z(t) = clamp(f(t), lo, hi) the depth in the key, [lo, hi] being the
// face's own corner depth range (DepthPlane::minDepth/maxDepth).
//  1. Every rounding step is monotone, so f is monotone in t: its value at the run's ends
//     bounds it on the whole run.
//  2. |f - D| <= 2^-23 M + 2^-149 with M = |a| max|t + 0.5| + |b (y + 0.5)| + |c|; bound()
//     returns twice that (slack for the double arithmetic of the test itself).
//  3. If lo_W < z_W < hi_W and z_C > lo_C at both ends, then by 1. f_W < hi_W and f_C > lo_C on
//     the run, so z_W = max(f_W, lo_W) >= f_W and z_C = min(f_C, hi_C) <= f_C (no -0, no NaN:
//     those fail the tests).
//  4. The exact gap g = D_C - D_W is affine; at each end g >= (z_C - z_W) - (E_W + E_C), so on
//     the run g >= h - (E_W + E_C), h the linear interpolation of the end gaps of the keys.
//  5. Where h > 2 (E_W + E_C): f_C - f_W >= g - (E_W + E_C) > 0, hence (by 3.) z_C > z_W and
//     C's key is larger whatever the ids. Ties and ulp-sized swaps fail this test and are left
//     to the exact keys.
int IntervalAlgorithm::Band::provenExtent(size_t w, int x, int right) const {
  const Candidate& win = candidates_[w];
  const float winLo = win.plane->minDepth(), winHi = win.plane->maxDepth();
  if (!(win.zLeft > winLo && win.zLeft < winHi && win.zRight > winLo && win.zRight < winHi))
    return x - 1;
  const double xMax = std::max(std::abs(x + 0.5), std::abs(right + 0.5));
  const auto bound = [xMax](const Candidate& c) {
    return 0x1p-22 * (std::abs(c.a) * xMax + c.rowMagnitude) + 0x1p-140;
  };
  const double winBound = bound(win);
  int end = right;
  for (size_t i = 0; i < candidates_.size(); ++i) {
    if (i == w) continue;
    const Candidate& c = candidates_[i];
    // The same plane gives the same float depth at every sample: the smaller id wins all along.
    if (samePlane(*c.plane, *win.plane) && win.id < c.id) continue;
    const float cLo = c.plane->minDepth();
    if (!(c.zLeft > cLo && c.zRight > cLo)) return x - 1;
    const double threshold = 2.0 * (winBound + bound(c));
    const double gapLeft = double(c.zLeft) - double(win.zLeft);
    const double gapRight = double(c.zRight) - double(win.zRight);
    if (!(gapLeft > threshold)) return x - 1;
    if (gapRight > threshold) continue;
    // h > thr for t < t*; one column of margin covers the rounding of t* itself.
    const double crossing = x + (gapLeft - threshold) / (gapLeft - gapRight) * double(right - x);
    const double lastProven = std::floor(crossing) - 1.0;
    end = lastProven >= x ? std::min(end, int(lastProven)) : x;
    if (end == x) break;
  }
  return end;
}

}  // namespace zrender
