// The AVX2 surface kernel: eight samples at a time, lane by lane the operations of the scalar
// one (SurfaceSample.hpp), fused multiply-adds where it fuses them, so the same bits.

#include <immintrin.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "SurfaceSample.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/SurfaceKernel.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

namespace {

// How the four texels of each lane are read (the same texels, so the same bits, either way).
enum class TexelReads {
  Loads,   // two 64-bit loads, each a pair of texels side by side
  Gathers  // four gathers, each one texel of every lane
};

using F = __m256;
using I = __m256i;

ZRENDER_AVX2 inline F splat(float x) {
  return _mm256_set1_ps(x);
}
ZRENDER_AVX2 inline bool allSet(F mask) {
  return _mm256_movemask_ps(mask) == 0xFF;
}
ZRENDER_AVX2 inline bool anySet(F mask) {
  return _mm256_movemask_ps(mask) != 0;
}
ZRENDER_AVX2 inline F select(F mask, F ifTrue, F ifFalse) {
  return _mm256_blendv_ps(ifFalse, ifTrue, mask);
}

// A plane along a run of one row: its row value (rowValue) and its a, in every lane.
struct RowPlane {
  F row, a;
};

ZRENDER_AVX2 inline F at(const RowPlane& p, F sx) {
  return _mm256_fmadd_ps(p.a, sx, p.row);
}

// The fan's planes along row sy: their eight row values in one operation.
struct RowPlanes {
  alignas(32) float row[kSurfacePlanes];
  const SurfaceFan* fan;
  ZRENDER_AVX2 RowPlanes(const SurfaceFan& f, float sy) : fan(&f) {
    _mm256_store_ps(row,
                    _mm256_fmadd_ps(_mm256_load_ps(f.b), _mm256_set1_ps(sy), _mm256_load_ps(f.c)));
  }
  ZRENDER_AVX2 RowPlane operator[](int k) const {
    return RowPlane{_mm256_broadcast_ss(row + k), _mm256_broadcast_ss(fan->a + k)};
  }
};

// blend3's operations.
ZRENDER_AVX2 inline F blend3(float a, float b, float c, F w0, F u, F v) {
  return _mm256_fmadd_ps(splat(c), v, _mm256_fmadd_ps(splat(b), u, _mm256_mul_ps(splat(a), w0)));
}

// Byte `byte` of each 32-bit lane (0: B, 1: G, 2: R of 0x00RRGGBB), as a float 0..255.
ZRENDER_AVX2 inline F channel(I texels, int byte) {
  const I pick = _mm256_set1_epi32(int(0xFFFFFF00u | unsigned(byte)));  // -1 bytes give 0
  return _mm256_cvtepi32_ps(_mm256_shuffle_epi8(
      texels, _mm256_add_epi32(pick, _mm256_setr_epi32(0, 4, 8, 12, 0, 4, 8, 12))));
}

// The texels at index[k] + offset and the next one, for the eight lanes k: one 64-bit load
// each, split into the left texels and the right ones.
ZRENDER_AVX2 inline void loadPairs(const uint32_t* texels, const int32_t index[8], int offset,
                                   I& left, I& right) {
  long long p[8];
  for (int k = 0; k < 8; ++k) std::memcpy(&p[k], texels + index[k] + offset, 8);
  const __m256 lo = _mm256_castsi256_ps(_mm256_setr_epi64x(p[0], p[1], p[2], p[3]));
  const __m256 hi = _mm256_castsi256_ps(_mm256_setr_epi64x(p[4], p[5], p[6], p[7]));
  // Even 32-bit halves (the left texels) and odd ones, lanes in order.
  left = _mm256_castpd_si256(
      _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0x88)), 0xD8));
  right = _mm256_castpd_si256(
      _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0xDD)), 0xD8));
}

// sampleTexture's operations: R, G, B in 0..255, the texels read as `reads` says.
template <TexelReads reads>
ZRENDER_AVX2 inline void sampleTexture(const SurfaceTexture& t, F u, F v, F rgb[3]) {
  const F zero = _mm256_setzero_ps();
  const F uu = _mm256_max_ps(_mm256_sub_ps(u, _mm256_floor_ps(u)), zero);
  const F vv = _mm256_max_ps(_mm256_sub_ps(v, _mm256_floor_ps(v)), zero);
  const F tx = _mm256_fmadd_ps(uu, splat(float(t.width)), splat(-0.5f));
  const F ty = _mm256_fmadd_ps(vv, splat(-float(t.height)), splat(float(t.height) - 0.5f));
  const F fx0 = _mm256_floor_ps(tx), fy0 = _mm256_floor_ps(ty);
  const F fx = _mm256_sub_ps(tx, fx0), fy = _mm256_sub_ps(ty, fy0);
  const int stride = t.width + 2;
  const I index0 = _mm256_add_epi32(
      _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvttps_epi32(fy0), _mm256_set1_epi32(stride)),
                       _mm256_cvttps_epi32(fx0)),
      _mm256_set1_epi32(stride + 1));
  I a, b, c, d;  // texels (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1)
  if (reads == TexelReads::Gathers) {
    const int* texels = reinterpret_cast<const int*>(t.texels);
    a = _mm256_i32gather_epi32(texels, index0, 4);
    b = _mm256_i32gather_epi32(texels + 1, index0, 4);
    c = _mm256_i32gather_epi32(texels + stride, index0, 4);
    d = _mm256_i32gather_epi32(texels + stride + 1, index0, 4);
  } else {
    alignas(32) int32_t index[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(index), index0);
    loadPairs(t.texels, index, 0, a, b);
    loadPairs(t.texels, index, stride, c, d);
  }
  for (int i = 0; i < 3; ++i) {
    const int byte = 2 - i;  // R, G, B
    const F ca = channel(a, byte), cb = channel(b, byte);
    const F cc = channel(c, byte), cd = channel(d, byte);
    const F top = _mm256_fmadd_ps(_mm256_sub_ps(cb, ca), fx, ca);
    const F bottom = _mm256_fmadd_ps(_mm256_sub_ps(cd, cc), fx, cc);
    rgb[i] = _mm256_fmadd_ps(_mm256_sub_ps(bottom, top), fy, top);
  }
}

// A channel plus 0.5 to its byte, as truncateToInt(minOf(t, kTopChannel)).
ZRENDER_AVX2 inline I toByte(F t) {
  return _mm256_cvttps_epi32(_mm256_min_ps(t, splat(surface::kTopChannel)));
}

// The face ids of keys[x, x + 8), in order.
ZRENDER_AVX2 inline I idsAt(const DepthKey* keys) {
  const __m256 a = _mm256_loadu_ps(reinterpret_cast<const float*>(keys));
  const __m256 b = _mm256_loadu_ps(reinterpret_cast<const float*>(keys + 4));
  return _mm256_castpd_si256(
      _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(a, b, 0x88)), 0xD8));
}

// Where a row's colors go, eight lanes at a time: lanes past the row's end, or past a run's
// end, may be written with anything; a later run of the row writes over the latter.
// As packed colors (0x00RRGGBB), with room for 8 past the row's end.
struct ColorSink {
  uint32_t* out;
  ZRENDER_AVX2 void store(I rgb, int i) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i), rgb);
  }
  ZRENDER_AVX2 void polygon(const uint32_t* colors, int x, int count) const {
    std::copy(colors, colors + count, out + x);
  }
};

// As the image's B, G, R bytes, nothing past the row's end: the row that follows may be
// another thread's.
struct BgrSink {
  uint8_t* bgr;
  int width;
  ZRENDER_AVX2 void store(I rgb, int i) const {
    // The halves' 12 bytes of pixels joined: 24 bytes of pixels and 8 zeros.
    const I packed =
        _mm256_permutevar8x32_epi32(squeezeBgr(rgb), _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 7, 7));
    if (i + 11 <= width) {  // all 32 bytes inside the row
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(bgr + 3 * i), packed);
      return;
    }
    alignas(32) uint8_t last[32];
    _mm256_store_si256(reinterpret_cast<__m256i*>(last), packed);
    std::memcpy(bgr + 3 * i, last, size_t(3 * std::min(8, width - i)));
  }
  ZRENDER_AVX2 void polygon(const uint32_t* colors, int x, int count) const {
    packBgrScalar(colors, count, bgr + 3 * x);
  }
};

// shadeSample's operations for the run of a triangle face (one fan) that starts at sample x
// of row y, eight lanes at a time, with what the run's samples share (the planes' row values,
// the ray's row) computed once. The run ends where `keys` (the row, `width` samples) holds
// another face id than keys[x], found block by block as the colors are computed; returns that
// end. The colors go to `sink` (ColorSink, BgrSink), the last block's with up to 7 past the
// run.
template <TexelReads reads, typename Sink>
[[gnu::always_inline]] ZRENDER_AVX2 inline int shadeTriangleRun(const SurfaceFrame& f,
                                                                const FaceSurface& face,
                                                                const SurfaceFan& fan,
                                                                const DepthKey* keys, int width,
                                                                int x, int y, const Sink& sink) {
  const float sy = float(y - face.originY);
  const RowPlanes planes(fan, sy);
  const RowPlane den = planes[kDen], pu = planes[kPu], pv = planes[kPv];
  const RowPlane normal[3] = {planes[kNormalX], planes[kNormalY], planes[kNormalZ]};
  RowPlane uv[2] = {};
  if (face.textured()) uv[0] = planes[kTextureU], uv[1] = planes[kTextureV];
  // A copy: the stores of colors below may alias the frame's table, not a local.
  const SurfaceTexture texture = face.textured() ? f.textures[face.texture] : SurfaceTexture();
  const bool lit = f.mode != ShadingMode::Normal;
  const float dyValue = std::fma(float(y), -f.rayScaleY, f.rayOriginY);
  const F dy = splat(dyValue), dyTerm = splat(std::fma(dyValue, dyValue, 1.0f));
  const F zero = _mm256_setzero_ps(), one = splat(1.0f);
  const F lane = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
  const I id = _mm256_set1_epi32(int(keyFaceId(keys[x])));
  for (int i = x;; i += 8) {
    // The lanes of the run: a prefix of the block.
    int count = 8;
    if (i + 8 <= width) {
      const unsigned same = unsigned(
          _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(idsAt(keys + i), id))));
      if (same != 0xFFu) count = __builtin_ctz(~same);
    } else {
      count = 0;
      while (i + count < width && keyFaceId(keys[i + count]) == keyFaceId(keys[x])) ++count;
    }
    // i - originX + lane and i + lane, exactly (small integers).
    const F sx = _mm256_add_ps(splat(float(i - face.originX)), lane);
    // attributesAt.
    const F d = at(den, sx), a = at(pu, sx), b = at(pv, sx);
    const F w = _mm256_sub_ps(_mm256_sub_ps(d, a), b);
    const F inside = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(d, zero, _CMP_GT_OQ), _mm256_cmp_ps(a, zero, _CMP_GE_OQ)),
        _mm256_and_ps(_mm256_cmp_ps(b, zero, _CMP_GE_OQ), _mm256_cmp_ps(w, zero, _CMP_GE_OQ)));
    F m[3], tu = zero, tv = zero;
    for (int k = 0; k < 3; ++k) m[k] = at(normal[k], sx);
    if (face.textured()) {
      const F inv = _mm256_div_ps(one, d);
      tu = _mm256_mul_ps(at(uv[0], sx), inv);
      tv = _mm256_mul_ps(at(uv[1], sx), inv);
    }
    // Samples outside the face are few; lanes past the run's end (their colors are not kept)
    // do not count.
    const F past = _mm256_cmp_ps(lane, splat(float(count)), _CMP_GE_OQ);
    if (!allSet(_mm256_or_ps(inside, past))) {
      F u = zero, v = zero;
      if (!fan.degenerate) {
        const F inv = _mm256_div_ps(one, d), huge = splat(surface::kHugeWeight);
        u = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(a, inv), zero), huge);
        v = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(b, inv), zero), huge);
        const F s = _mm256_add_ps(u, v);
        const F over = _mm256_cmp_ps(s, one, _CMP_GT_OQ);
        const F invS = _mm256_div_ps(one, s);
        u = select(over, _mm256_mul_ps(u, invS), u);
        v = select(over, _mm256_mul_ps(v, invS), v);
      }
      const F w0 = _mm256_sub_ps(_mm256_sub_ps(one, u), v);
      for (int k = 0; k < 3; ++k)
        m[k] = select(inside, m[k],
                      blend3(fan.cornerNormal[0][k], fan.cornerNormal[1][k], fan.cornerNormal[2][k],
                             w0, u, v));
      tu = select(inside, tu,
                  blend3(fan.cornerUv[0][0], fan.cornerUv[1][0], fan.cornerUv[2][0], w0, u, v));
      tv = select(inside, tv,
                  blend3(fan.cornerUv[0][1], fan.cornerUv[1][1], fan.cornerUv[2][1], w0, u, v));
    }
    F length2 = _mm256_fmadd_ps(m[0], m[0], _mm256_fmadd_ps(m[1], m[1], _mm256_mul_ps(m[2], m[2])));
    const F positive = _mm256_cmp_ps(length2, zero, _CMP_GT_OQ);
    if (!allSet(positive)) {  // +Z
      m[0] = select(positive, m[0], zero);
      m[1] = select(positive, m[1], zero);
      m[2] = select(positive, m[2], one);
      length2 = select(positive, length2, one);
    }
    F t[3];
    if (!lit) {
      const F scale = _mm256_div_ps(splat(127.5f), _mm256_sqrt_ps(length2));
      for (int k = 0; k < 3; ++k) t[k] = _mm256_fmadd_ps(m[k], scale, splat(128.0f));
    } else {
      const F px = _mm256_add_ps(splat(float(i)), lane);
      const F dx = _mm256_fmadd_ps(px, splat(f.rayScaleX), splat(f.rayOriginX));
      const F ray2 = _mm256_fmadd_ps(dx, dx, dyTerm);
      const F dot = _mm256_fnmadd_ps(m[0], dx, _mm256_fnmadd_ps(m[1], dy, m[2]));
      const F diffuse =
          _mm256_div_ps(_mm256_max_ps(dot, zero), _mm256_sqrt_ps(_mm256_mul_ps(length2, ray2)));
      const F noSpecular = splat(surface::kNoSpecular);
      const F shiny = _mm256_cmp_ps(diffuse, noSpecular, _CMP_GE_OQ);
      F shine = splat(0.5f);
      if (anySet(shiny)) {
        F specular = _mm256_max_ps(diffuse, noSpecular);  // no denormals in the other lanes
        for (int k = 0; k < 6; ++k) specular = _mm256_mul_ps(specular, specular);
        shine = select(shiny, _mm256_fmadd_ps(splat(76.5f), specular, shine), shine);
      }
      const F light = _mm256_fmadd_ps(splat(0.9f), diffuse, splat(0.1f));
      F base[3] = {splat(face.base[0]), splat(face.base[1]), splat(face.base[2])};
      if (face.textured()) sampleTexture<reads>(texture, tu, tv, base);
      for (int k = 0; k < 3; ++k) t[k] = _mm256_fmadd_ps(base[k], light, shine);
    }
    const I rgb = _mm256_or_si256(
        _mm256_or_si256(_mm256_slli_epi32(toByte(t[0]), 16), _mm256_slli_epi32(toByte(t[1]), 8)),
        toByte(t[2]));
    sink.store(rgb, i);
    if (count < 8) return i + count;
  }
}

// A polygon's run: the scalar kernel, compiled here with hardware fused multiply-adds.
ZRENDER_AVX2 void shadePolygonRun(const SurfaceFrame& frame, const FaceSurface& face,
                                  const SurfaceFan* fans, int x, int y, int count, uint32_t* out) {
  for (int i = 0; i < count; ++i) out[i] = surface::shadeSample(frame, face, fans, x + i, y);
}

// A run as shadeSurfaceRunAvx2 colors it.
template <TexelReads reads>
ZRENDER_AVX2 void shadeRun(const SurfaceFrame& frame, const FaceSurface& face,
                           const SurfaceFan* fans, int x, int y, int count, uint32_t* out) {
  if (face.fanCount != 1) {
    shadePolygonRun(frame, face, fans, x, y, count, out);
    return;
  }
  // A row of its own: the run's samples of one face, then one of another face that ends it.
  std::vector<DepthKey> keys(size_t(x + count) + 1, makeDepthKey(0.5f, 0));
  keys.back() = makeDepthKey(0.5f, 1);
  std::vector<uint32_t> colors(keys.size() + 8);
  shadeTriangleRun<reads>(frame, face, *fans, keys.data(), int(keys.size()), x, y,
                          ColorSink{colors.data()});
  std::copy(colors.begin() + x, colors.begin() + x + count, out);
}

// A row as shadeSurfaceRowAvx2 colors it, into `sink`.
template <TexelReads reads, typename Sink>
ZRENDER_AVX2 void shadeRow(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                           uint32_t background, const Sink& sink) {
  const SurfaceFrame& frame = setup.frame();
  // The faces met first in the next row: misses of cache while this row is shaded, instead of
  // waiting for them there.
  setup.prefetchRow(y + 1);
  for (int x = 0; x < width;) {
    const uint32_t id = keyFaceId(keys[x]);
    if (id == kBackgroundId) {
      // Like a run, a background run may write up to 7 colors past its end.
      const int end = runEndAvx2(keys, x, width);
      const I fill = _mm256_set1_epi32(int(background));
      for (int i = x; i < end; i += 8) sink.store(fill, i);
      x = end;
      continue;
    }
    const FaceSurface& face = setup.surface(id);
    const SurfaceFan* fans = setup.fans(face);
    if (face.fanCount == 1) {
      x = shadeTriangleRun<reads>(frame, face, *fans, keys, width, x, y, sink);
      continue;
    }
    // A polygon's run, a piece at a time.
    const int end = runEndAvx2(keys, x, width);
    constexpr int kPiece = 64;
    uint32_t colors[kPiece];
    for (int i = x; i < end; i += kPiece) {
      const int count = std::min(kPiece, end - i);
      shadePolygonRun(frame, face, fans, i, y, count, colors);
      sink.polygon(colors, i, count);
    }
    x = end;
  }
}

}  // namespace

void shadeSurfaceRunAvx2(const SurfaceFrame& frame, const FaceSurface& face, const SurfaceFan* fans,
                         int x, int y, int count, uint32_t* out) {
  shadeRun<TexelReads::Loads>(frame, face, fans, x, y, count, out);
}

void shadeSurfaceRunAvx2Gathers(const SurfaceFrame& frame, const FaceSurface& face,
                                const SurfaceFan* fans, int x, int y, int count, uint32_t* out) {
  shadeRun<TexelReads::Gathers>(frame, face, fans, x, y, count, out);
}

void shadeSurfaceRowAvx2(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                         uint32_t background, uint32_t* out) {
  shadeRow<TexelReads::Loads>(setup, keys, width, y, background, ColorSink{out});
}

void shadeSurfaceRowAvx2Gathers(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                                uint32_t background, uint32_t* out) {
  shadeRow<TexelReads::Gathers>(setup, keys, width, y, background, ColorSink{out});
}

void shadeSurfaceBgrRowAvx2(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                            uint32_t background, uint8_t* bgr) {
  shadeRow<TexelReads::Loads>(setup, keys, width, y, background, BgrSink{bgr, width});
}

void shadeSurfaceBgrRowAvx2Gathers(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                                   uint32_t background, uint8_t* bgr) {
  shadeRow<TexelReads::Gathers>(setup, keys, width, y, background, BgrSink{bgr, width});
}

}  // namespace zrender
