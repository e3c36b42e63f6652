#pragma once

#include <vector>

#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/raster/PolygonEdges.hpp"
#include "zrender/visibility/PolygonBands.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// The interval (span) scan-line algorithm (docs/design.md, The algorithms: `interval`). Rows are
// processed from the top; one active edge table holds the edges of every polygon crossing the row,
// sorted by column. Between consecutive crossings lies a span; an in/out flag per polygon (toggled
// at its crossings, even-odd) gives the polygons covering the span. The visible polygon of a span
// is decided from the candidates' depths at the span's ends, and the span is split where their
// depths cross; no per-sample depth buffer is used. Where the end values do not prove the order
// of the rounded float keys (near ties, crossings), samples are decided one by one from the
// exact keys, so the result is bit-identical to the z-buffer. With several threads, the image is
// cut into bands of rows, each drawn by one thread from tables of its own (PolygonTables for a
// band).
class IntervalAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "interval"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  // An entry of the active edge table: small, so that sorting moves little memory; the
  // stepping state lives in steppers_[slot].
  struct ActiveEdge {
    int32_t column;    // = steppers_[slot].column on the current row
    uint32_t polygon;  // index into tables_.polygons
    uint32_t slot;     // index of the edge in tables_.edges (and steppers_)
    int32_t lastRow;   // the edge leaves the table after this row
  };
  // Per-span copy of a candidate, with its row constant and its depths at the span's ends.
  struct Candidate {
    double a, rowBase;    // depth = a * (x + 0.5) + rowBase before float rounding
    double rowMagnitude;  // |b * (y + 0.5)| + |c|, for the rounding error bound
    const DepthPlane* plane;
    uint32_t id;
    float zLeft, zRight;  // clamped float depths at the current sub-span's ends
    DepthKey keyLeft;
  };
  struct Counters {
    uint64_t spans = 0;            // spans covered by at least one polygon
    uint64_t multiSpans = 0;       // ... by two or more
    uint64_t splitSpans = 0;       // multi-candidate spans decided in more than one piece
    uint64_t samplesOneByOne = 0;  // samples decided sample by sample from the exact keys
    uint64_t keysCompared = 0;     // candidate keys compared in sample-by-sample decisions
    uint64_t samplesWritten = 0;   // samples covered by a polygon: decided, written once
  };

  // What drawing a band of rows needs (the whole image, with one thread).
  struct Band {
    // Draws rows [tables_.rowBegin, rowEnd) from tables_, which the caller has built.
    void drawRows(int rowEnd, const FrameInput& input, FrameBuffer& fb, RenderStats& stats);
    void fillSpan(int left, int right, int y, DepthKey* row);
    void resolveSpan(int left, int right, DepthKey* row);
    // Largest column e in [x, right] such that candidate w is proven nearer than every other
    // candidate on [x, e] from the end values; x - 1 when nothing beyond the exact column x
    // can be proven (then x is decided from its exact keys).
    int provenExtent(size_t w, int x, int right) const;

    PolygonTables tables_;
    std::vector<ActiveEdge> activeEdges_;        // the active edge table, sorted by column
    std::vector<ActiveEdge> newEdges_, merged_;  // edges joining on this row; merge scratch
    // Per classified edge, valid while it is active (written when it joins).
    std::vector<EdgeStepper, UninitializedAllocator<EdgeStepper>> steppers_;
    std::vector<int32_t> inPosition_;    // per polygon: index in inside_, or -1 when outside
    std::vector<uint32_t> inside_;       // polygons covering the current span
    std::vector<Candidate> candidates_;  // scratch for multi-candidate spans
    Counters counters_;
  };

  Band whole_;                   // one thread
  std::vector<Band> perThread_;  // several: each thread's
  PolygonBands bands_;           // several: how they are drawn
};

}  // namespace zrender
