#include "zrender/Triangulation.hpp"

namespace zrender {

namespace {

// True when p lies inside or on the boundary of the positively oriented triangle (a, b, c).
bool insideOrOn(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c,
                const FixedPoint& p) {
  return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

void emit(const FixedPoint* pts, uint32_t i, uint32_t j, uint32_t k,
          std::vector<std::array<uint32_t, 3>>& out) {
  const int64_t o = orient2d(pts[i], pts[j], pts[k]);
  if (o > 0)
    out.push_back({i, j, k});
  else if (o < 0)
    out.push_back({i, k, j});
}

}  // namespace

bool triangulatePolygon(const FixedPoint* pts, uint32_t count,
                        std::vector<std::array<uint32_t, 3>>& out, std::vector<uint32_t>& ring) {
  if (count < 3) return true;
  if (count == 3) {
    emit(pts, 0, 1, 2, out);
    return true;
  }
  // Orientation of the whole polygon (twice the signed area), in 128 bits: a polygon of
  // thousands of corners at 2^28 could overflow 64.
  __int128 area = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const FixedPoint& a = pts[i];
    const FixedPoint& b = pts[(i + 1) % count];
    area += __int128(int64_t(a.x) * b.y - int64_t(b.x) * a.y);
  }
  if (area == 0) return true;  // no area: nothing to cover
  const int sign = area > 0 ? 1 : -1;

  // Convex (every turn the same way or straight): a fan is a triangulation.
  bool convex = true;
  for (uint32_t i = 0; i < count && convex; ++i) {
    const int64_t o = orient2d(pts[i], pts[(i + 1) % count], pts[(i + 2) % count]);
    convex = o * sign >= 0;
  }
  if (convex) {
    for (uint32_t i = 1; i + 1 < count; ++i) emit(pts, 0, i, i + 1, out);
    return true;
  }

  // Ear clipping on the ring of remaining corners.
  ring.resize(count);
  for (uint32_t i = 0; i < count; ++i) ring[i] = i;
  size_t i = 0;
  size_t failures = 0;
  while (ring.size() > 3) {
    const size_t n = ring.size();
    const uint32_t ip = ring[(i + n - 1) % n], ic = ring[i % n], in = ring[(i + 1) % n];
    const int64_t turn = orient2d(pts[ip], pts[ic], pts[in]) * sign;
    bool ear = false;
    if (turn == 0) {
      // A straight corner (or a spike) adds no area: drop it.
      ring.erase(ring.begin() + long(i % n));
      failures = 0;
      continue;
    }
    if (turn > 0) {
      ear = true;
      const FixedPoint& a = pts[sign > 0 ? ip : in];
      const FixedPoint& c = pts[sign > 0 ? in : ip];
      for (size_t j = 0; j < n && ear; ++j) {
        const uint32_t q = ring[j];
        if (q == ip || q == ic || q == in) continue;
        if (pts[q] == pts[ip] || pts[q] == pts[ic] || pts[q] == pts[in]) continue;
        if (insideOrOn(a, pts[ic], c, pts[q])) ear = false;
      }
    }
    if (ear) {
      emit(pts, ip, ic, in, out);
      ring.erase(ring.begin() + long(i % n));
      failures = 0;
      if (i > 0) --i;
    } else {
      i = (i + 1) % n;
      if (++failures > n) return false;  // a full lap without an ear: not simple
    }
  }
  emit(pts, ring[0], ring[1], ring[2], out);
  return true;
}

}  // namespace zrender
