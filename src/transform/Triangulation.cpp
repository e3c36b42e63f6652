#include "zrender/transform/Triangulation.hpp"

#include <algorithm>

namespace zrender {

namespace {

// True when p lies inside or on the boundary of the positively oriented triangle (a, b, c).
bool insideOrOn(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c,
                const FixedPoint& p) {
  return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

int signOf(int64_t v) {
  return (v > 0) - (v < 0);
}

// A direction between two fixed-point positions; components below 2^30, so products fit.
struct Direction {
  int64_t x, y;
};

Direction direction(const FixedPoint& from, const FixedPoint& to) {
  return {int64_t(to.x) - from.x, int64_t(to.y) - from.y};
}

int64_t cross(const Direction& a, const Direction& b) {
  return a.x * b.y - a.y * b.x;
}

// True when the polygon (the corners pts[ring[0]], pts[ring[1]], ..., spikes removed) is
// simple: no two edges meet except neighbours at their shared corner. Only then is the union
// of an ear-clipping triangulation the polygon's even-odd interior, which the scan-line
// algorithms fill: through a crossing, a repeated corner or a corner lying on another edge
// (where the boundary touches itself: two lobes, or the overlapping edges with which clipping
// joins the separate parts of a concave face) ears can still be found that cover something
// else. The caller skips a polygon that is not simple, so every algorithm treats it the same.
// Quadratic, with bounding-box tests first; faces have at most kMaxFaceCorners corners.
bool isSimple(const FixedPoint* pts, const std::vector<uint32_t>& ring) {
  const uint32_t count = uint32_t(ring.size());
  const auto at = [&](uint32_t i) -> const FixedPoint& { return pts[ring[i]]; };
  const auto next = [count](uint32_t i) { return i + 1 == count ? 0 : i + 1; };
  for (uint32_t i = 0; i < count; ++i) {
    const FixedPoint& a = at(i);
    const FixedPoint& b = at(next(i));
    const int32_t minX = std::min(a.x, b.x), maxX = std::max(a.x, b.x);
    const int32_t minY = std::min(a.y, b.y), maxY = std::max(a.y, b.y);
    for (uint32_t j = 0; j < count; ++j) {
      const FixedPoint& c = at(j);
      if (j > i && c == a) return false;  // a position visited twice
      // Corner j on edge i, away from its ends.
      if (c != a && c != b && minX <= c.x && c.x <= maxX && minY <= c.y && c.y <= maxY &&
          orient2d(a, b, c) == 0) {
        return false;
      }
      // Edge j (after i, not a neighbour) crossing edge i at a point inside both.
      if (j < i + 2 || (i == 0 && j + 1 == count)) continue;
      const FixedPoint& d = at(next(j));
      if (std::max(c.x, d.x) < minX || std::min(c.x, d.x) > maxX || std::max(c.y, d.y) < minY ||
          std::min(c.y, d.y) > maxY) {
        continue;
      }
      if (signOf(orient2d(a, b, c)) * signOf(orient2d(a, b, d)) < 0 &&
          signOf(orient2d(c, d, a)) * signOf(orient2d(c, d, b)) < 0) {
        return false;
      }
    }
  }
  return true;
}

// Fills `ring` with the corners of the polygon without its spikes (the boundary running
// straight back, or a corner repeated next to itself). They have no area and the even-odd rule
// ignores them, but a fan or an ear beside one would cover the area next to it. Removing one
// can expose another, so the ring is built as a stack, then closed across the seam.
void removeSpikes(const FixedPoint* pts, uint32_t count, std::vector<uint32_t>& ring) {
  const auto spike = [pts](uint32_t a, uint32_t b, uint32_t c) {
    if (pts[a] == pts[b] || pts[b] == pts[c]) return true;
    const Direction in = direction(pts[a], pts[b]), out = direction(pts[b], pts[c]);
    return cross(in, out) == 0 && in.x * out.x + in.y * out.y < 0;
  };
  ring.clear();
  for (uint32_t k = 0; k < count; ++k) {
    ring.push_back(k);
    while (ring.size() >= 3 && spike(ring[ring.size() - 3], ring[ring.size() - 2], ring.back())) {
      ring.erase(ring.end() - 2);
    }
  }
  while (ring.size() >= 3) {
    const size_t n = ring.size();
    if (spike(ring[n - 2], ring[n - 1], ring[0])) {
      ring.pop_back();
    } else if (spike(ring[n - 1], ring[0], ring[1])) {
      ring.erase(ring.begin());
    } else {
      break;
    }
  }
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
  removeSpikes(pts, count, ring);
  if (ring.size() < 3) return true;  // nothing but spikes
  if (!isSimple(pts, ring)) return false;

  // Convex (every turn the same way, or straight on): a fan is a triangulation, unless the
  // polygon winds more than once (its y direction then changes sign more than twice).
  const uint32_t m = uint32_t(ring.size());
  bool convex = true;
  int ySignChanges = 0, lastYSign = 0;
  for (uint32_t i = 0; i <= m && convex; ++i) {
    const FixedPoint& a = pts[ring[i % m]];
    const FixedPoint& b = pts[ring[(i + 1) % m]];
    convex = orient2d(a, b, pts[ring[(i + 2) % m]]) * sign >= 0;
    const int ySign = signOf(int64_t(b.y) - a.y);
    if (ySign != 0) {
      if (lastYSign != 0 && ySign != lastYSign) ++ySignChanges;
      lastYSign = ySign;
    }
  }
  // Edges 0..m-1 then 0 again: every cyclic change is counted, except the wrap-around one when
  // edge 0 is horizontal, and missing one cannot bring 4 (twice around) down to 2.
  if (convex && ySignChanges <= 2) {
    for (uint32_t i = 1; i + 1 < m; ++i) emit(pts, ring[0], ring[i], ring[i + 1], out);
    return true;
  }

  // Ear clipping on the ring of remaining corners.
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
