#include "zrender/visibility/CoincidentTriangles.hpp"

#include <cstring>

namespace zrender {

namespace {

uint64_t mix(uint64_t h, uint64_t word) {
  // One splitmix64 step per word: every input bit reaches every output bit.
  h += word + 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

uint64_t doubleBits(double d) {
  uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  return u;
}

// Same coverage and the same depth at every sample. Planes are compared by their bits, so a
// plane computed the same way from the same corners matches, and no other.
bool sameSamples(const ScreenTriangle& t, const FixedPoint* v, const DepthPlane& p) {
  return t.v[0] == v[0] && t.v[1] == v[1] && t.v[2] == v[2] &&
         doubleBits(t.plane.a) == doubleBits(p.a) && doubleBits(t.plane.b) == doubleBits(p.b) &&
         doubleBits(t.plane.c) == doubleBits(p.c) && t.plane.loBits == p.loBits &&
         t.plane.hiBits == p.hiBits;
}

uint64_t hashOf(const ScreenTriangle& t) {
  uint64_t h = 0;
  for (const FixedPoint& p : t.v) h = mix(h, uint64_t(uint32_t(p.x)) << 32 | uint32_t(p.y));
  h = mix(h, doubleBits(t.plane.a));
  h = mix(h, doubleBits(t.plane.b));
  h = mix(h, doubleBits(t.plane.c));
  h = mix(h, uint64_t(uint32_t(t.plane.loBits)) << 32 | uint32_t(t.plane.hiBits));
  return h | 1;  // never 0, the empty slot's mark
}

}  // namespace

void CoincidentTriangles::clear() {
  if (used_ == 0) return;
  for (Entry& e : slots_) e.hash = 0;
  used_ = 0;
}

bool CoincidentTriangles::hiddenByEarlier(const ScreenTriangle& t) {
  if (2 * (used_ + 1) > slots_.size()) grow();
  const uint64_t h = hashOf(t);
  const size_t mask = slots_.size() - 1;
  for (size_t i = size_t(h) & mask;; i = (i + 1) & mask) {
    Entry& e = slots_[i];
    if (e.hash == 0) {
      e = Entry{{t.v[0], t.v[1], t.v[2]}, t.id, t.plane, h};
      ++used_;
      return false;
    }
    if (e.hash == h && sameSamples(t, e.v, e.plane)) {
      if (e.id < t.id) return true;
      e.id = t.id;
      return false;
    }
  }
}

void CoincidentTriangles::grow() {
  std::vector<Entry> old;
  old.swap(slots_);
  slots_.assign(old.empty() ? 64 : 2 * old.size(), Entry{});
  const size_t mask = slots_.size() - 1;
  for (const Entry& e : old) {
    if (e.hash == 0) continue;
    size_t i = size_t(e.hash) & mask;
    while (slots_[i].hash != 0) i = (i + 1) & mask;
    slots_[i] = e;
  }
}

}  // namespace zrender
