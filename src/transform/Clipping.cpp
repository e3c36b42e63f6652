#include "zrender/transform/Clipping.hpp"

namespace zrender {

namespace {

// One Sutherland–Hodgman pass against the half-space distance(p) >= 0.
template <typename Point, typename Distance>
size_t clipAgainst(const Point* in, size_t count, Point* out, Distance distance) {
  size_t n = 0;
  for (size_t i = 0; i < count; ++i) {
    const Point& a = in[i];
    const Point& b = in[(i + 1) % count];
    const double da = distance(a), db = distance(b);
    const bool aIn = da >= 0.0, bIn = db >= 0.0;
    if (aIn != bIn) {
      // Interpolate from the inside point toward the outside one, whatever the edge's
      // direction, so neighbouring faces get the same bits for their shared edge.
      const Point& pIn = aIn ? a : b;
      const Point& pOut = aIn ? b : a;
      const double dIn = aIn ? da : db, dOut = aIn ? db : da;
      const double t = dIn / (dIn - dOut);
      out[n++] = pIn + (pOut - pIn) * t;
    }
    if (bIn) out[n++] = b;
  }
  return n;
}

}  // namespace

size_t clipNearFar(const Vec4* in, size_t count, Vec4* out, Vec4* scratch) {
  const size_t n = clipAgainst(in, count, scratch, [](const Vec4& p) { return p[2] + p[3]; });
  if (n < 3) return 0;
  const size_t m = clipAgainst(scratch, n, out, [](const Vec4& p) { return p[3] - p[2]; });
  return m < 3 ? 0 : m;
}

size_t clipGuardBand(const Vec3* in, size_t count, double guard, Vec3* out, Vec3* scratch) {
  size_t n = clipAgainst(in, count, scratch, [guard](const Vec3& p) { return p[0] + guard; });
  if (n < 3) return 0;
  n = clipAgainst(scratch, n, out, [guard](const Vec3& p) { return guard - p[0]; });
  if (n < 3) return 0;
  n = clipAgainst(out, n, scratch, [guard](const Vec3& p) { return p[1] + guard; });
  if (n < 3) return 0;
  n = clipAgainst(scratch, n, out, [guard](const Vec3& p) { return guard - p[1]; });
  return n < 3 ? 0 : n;
}

}  // namespace zrender
