#pragma once

// The rasterization rules (docs/design.md, Rasterization rules), in one place, used by every
// visibility algorithm so that they agree bit for bit: sub-pixel snapping, exact integer edge
// functions with the top-left rule, the depth of a face at a sample centre, and the (depth, face
// id) ordering.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#endif

namespace zrender {

// Window positions are stored in fixed point, 1/256 of a sample (a pixel without MSAA).
constexpr int kSubpixelBits = 8;
constexpr int32_t kSubpixel = 1 << kSubpixelBits;
constexpr int32_t kHalfSubpixel = kSubpixel / 2;  // offset of a sample centre in its cell

// Positions are clipped to +-kGuardBand samples (2D, after the near/far clip) so that edge
// functions fit comfortably in int64: |coordinate| <= 2^28 units, products <= 2^58.
constexpr double kGuardBand = double(1 << 20);

struct FixedPoint {
  int32_t x;  // 1/256 sample units, right
  int32_t y;  // 1/256 sample units, down
  bool operator==(const FixedPoint& o) const { return x == o.x && y == o.y; }
  bool operator!=(const FixedPoint& o) const { return !(*this == o); }
};

// Rounds to the nearest 1/256 (ties to even, the current rounding mode), as std::lrint does:
// on x86-64 with the one instruction glibc's lrint is made of, as an inline call (GCC calls
// libm for lrint while errno is on), since the transform snaps every vertex.
inline int32_t snapToSubpixel(double v) {
#if defined(__SSE2__) && defined(__x86_64__)
  return static_cast<int32_t>(_mm_cvtsd_si64(_mm_set_sd(v * kSubpixel)));
#else
  return static_cast<int32_t>(std::lrint(v * kSubpixel));
#endif
}

// Centre of sample column `i` (or row) in fixed point.
inline int64_t sampleCentre(int i) {
  return int64_t(i) * kSubpixel + kHalfSubpixel;
}

// Floor and ceiling of a / b for b > 0, exact for negative a too.
inline int64_t floorDiv(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
inline int64_t ceilDiv(int64_t a, int64_t b) {
  return a >= 0 ? (a + b - 1) / b : -((-a) / b);
}

// First and last sample index whose centre lies in [lo, hi] (fixed point); first > last if none.
// kSubpixel is a power of two, so these are arithmetic shifts (a floor for negative values too):
// ceilDiv and floorDiv without their sign branches, for every triangle.
inline int firstSampleAtOrAfter(int64_t lo) {
  return int((lo - kHalfSubpixel + (kSubpixel - 1)) >> kSubpixelBits);
}
inline int lastSampleAtOrBefore(int64_t hi) {
  return int((hi - kHalfSubpixel) >> kSubpixelBits);
}

// Twice the signed area of (a, b, c) in fixed point; > 0 when c lies to the right of a->b as
// seen in the image (y down), i.e. the turn a->b->c is clockwise on screen.
inline int64_t orient2d(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c) {
  return int64_t(b.x - a.x) * int64_t(c.y - a.y) - int64_t(b.y - a.y) * int64_t(c.x - a.x);
}

// The edge a->b of a polygon whose interior lies on its positive side (orient2d > 0).
// E(p) = dx * (p.y - a.y) - dy * (p.x - a.x), exact in int64. A sample centre on the edge
// (E == 0) is covered only for a left edge (E grows to the right, stepX > 0) or a top edge
// (horizontal, E grows downward): the top-left rule. Equivalently a sample is covered when the
// point (x + e, y + e^2) is strictly inside for an infinitesimal e > 0. Since E is an integer,
// the rule is folded into `value` (minus one on other edges) so that coverage is value >= 0.
struct EdgeFunction {
  int64_t stepX;  // change of E per sample to the right (= -dy * 256)
  int64_t stepY;  // change of E per sample downward (= dx * 256)
  int64_t value;  // E - bias at the centre of sample (originX, originY)

  EdgeFunction() = default;
  EdgeFunction(const FixedPoint& a, const FixedPoint& b, int originX, int originY) {
    const int64_t dx = int64_t(b.x) - a.x, dy = int64_t(b.y) - a.y;
    stepX = -dy * kSubpixel;
    stepY = dx * kSubpixel;
    // Not top-left: 1, as a value rather than a branch (triangle after triangle, an edge's
    // direction follows no pattern a branch predictor could learn).
    const int64_t notTopLeft = int64_t((dy > 0) | ((dy == 0) & (dx <= 0)));
    value = dx * (sampleCentre(originY) - a.y) - dy * (sampleCentre(originX) - a.x) - notTopLeft;
  }
  bool covers(int64_t v) const { return v >= 0; }
};

// A rectangle of samples, inclusive; empty when min > max.
struct SampleRect {
  int minX = 0, minY = 0, maxX = -1, maxY = -1;
  bool empty() const { return minX > maxX || minY > maxY; }
};

// The samples whose centres may be covered by a triangle with corners a, b, c, inside the
// width x height image: TriangleSetup::bounds, written with two-operand min and max, which
// measured faster in the pyramid's tests but slower in the z-buffer's set-up.
inline SampleRect sampleBounds(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c,
                               int width, int height) {
  SampleRect r;
  r.minX = std::max(firstSampleAtOrAfter(std::min(std::min(a.x, b.x), c.x)), 0);
  r.maxX = std::min(lastSampleAtOrBefore(std::max(std::max(a.x, b.x), c.x)), width - 1);
  r.minY = std::max(firstSampleAtOrAfter(std::min(std::min(a.y, b.y), c.y)), 0);
  r.maxY = std::min(lastSampleAtOrBefore(std::max(std::max(a.y, b.y), c.y)), height - 1);
  return r;
}

// Triangle setup shared by the triangle-based algorithms: the three edge functions of a
// positively oriented triangle and its sample bounding box clipped to the image.
struct TriangleSetup {
  EdgeFunction edge[3];
  int minX, minY, maxX, maxY;  // inclusive sample bounds inside the image; empty if min > max

  // Returns false when the triangle covers no sample centre of the image (zero area or off
  // screen). `v` must be positively oriented (orient2d(v0, v1, v2) > 0).
  bool setup(const FixedPoint v[3], int width, int height) {
    if (!bounds(v, width, height)) return false;
    edges(v);
    return true;
  }
  // The two halves of setup(), for callers that may reject the triangle from its bounds alone:
  // the sample bounds (false when empty), then the edge functions from (minX, minY).
  bool bounds(const FixedPoint v[3], int width, int height) { return bounds(v, width, 0, height); }
  // The same for sample rows [rowBegin, rowEnd) of the image only (a band of it: the edge
  // functions are exact, so each sample is decided as in the whole image).
  bool bounds(const FixedPoint v[3], int width, int rowBegin, int rowEnd) {
    const int32_t x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
    const int32_t y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
    minX = std::max(firstSampleAtOrAfter(x0), 0);
    maxX = std::min(lastSampleAtOrBefore(x1), width - 1);
    minY = std::max(firstSampleAtOrAfter(y0), rowBegin);
    maxY = std::min(lastSampleAtOrBefore(y1), rowEnd - 1);
    return minX <= maxX && minY <= maxY;
  }
  void edges(const FixedPoint v[3]) {
    edge[0] = EdgeFunction(v[0], v[1], minX, minY);
    edge[1] = EdgeFunction(v[1], v[2], minX, minY);
    edge[2] = EdgeFunction(v[2], v[0], minX, minY);
  }
};

inline uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}
inline float bitsToFloat(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// std::nextafter(f, 0.0f) for f >= 0 or NaN-free zero, and std::nextafter(f, 1.0f) for
// f <= 1, not NaN: one step on the bits, inline (the transform steps the depth range of every
// front face; nextafterf is a libm call). Floats of one sign order like their bits.
inline float nextFloatTowardZero(float f) {
  return f > 0.0f ? bitsToFloat(floatBits(f) - 1u) : 0.0f;
}
inline float nextFloatTowardOne(float f) {
  if (f == 1.0f) return f;
  if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
  return bitsToFloat(f > 0.0f ? floatBits(f) + 1u : floatBits(f) - 1u);
}

constexpr int32_t kOneBits = 0x3F800000;  // the bits of 1.0f

// Window depth of a planar face as an affine function of the sample position:
// z = a * x + b * y + c with x, y in samples (centre of sample i at i + 0.5), z in 0..1,
// clamped to the range of the face's own corner depths [minDepth(), maxDepth()].
// Every algorithm evaluates it through rowBase() and at() so the float result is the same bits
// whatever the visiting order (the build disables FMA contraction for this reason).
//
// Why the clamp: coverage is decided on snapped corners, the plane comes from the unsnapped
// ones, so a sample can lie just outside the exact face, where the plane of a face seen almost
// edge-on extrapolates far beyond its corners. Clamped, no sample of a face is ever nearer
// than its nearest corner, which makes the octree's box test exact.
struct DepthPlane {
  double a = 0.0, b = 0.0, c = 1.0;
  int32_t loBits = 0;         // bits of the least corner depth (a float in [0, 1])
  int32_t hiBits = kOneBits;  // bits of the greatest

  double rowBase(int row) const { return b * (row + 0.5) + c; }
  float at(int column, double rowBase) const {
    // Clamped on the bits, as integers (non-negative floats order like their bits): branch
    // free, and -0.0 or a NaN cannot slip through as a negative float whose key would sort
    // above the background. (column + 0.5 is exact in a double.)
    const int32_t bits =
        static_cast<int32_t>(floatBits(static_cast<float>(a * (column + 0.5) + rowBase)));
    return bitsToFloat(static_cast<uint32_t>(std::min(std::max(bits, loBits), hiBits)));
  }
  float minDepth() const { return bitsToFloat(uint32_t(loBits)); }
  float maxDepth() const { return bitsToFloat(uint32_t(hiBits)); }
};

// A sample's visibility as one ordered 64-bit key: the float depth's bits (monotonic for
// non-negative floats) above the face id. Smaller key wins, so the nearer face wins and at
// equal depth the smaller id wins (docs/design.md, Rasterization rules), with a single unsigned
// comparison.
using DepthKey = uint64_t;
constexpr uint32_t kBackgroundId = 0xFFFFFFFFu;

inline DepthKey makeDepthKey(float depth, uint32_t faceId) {
  return (DepthKey(floatBits(depth)) << 32) | faceId;
}
inline float keyDepth(DepthKey k) {
  return bitsToFloat(uint32_t(k >> 32));
}
inline uint32_t keyFaceId(DepthKey k) {
  return uint32_t(k);
}

// The cleared state: depth 1 (the far plane) and no face.
constexpr DepthKey kClearKey = (DepthKey(0x3F800000u) << 32) | kBackgroundId;

}  // namespace zrender
