#include "zrender/raster/TriangleFill.hpp"

#include <immintrin.h>

#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

TriangleFillFunction triangleFill() {
  return cpuHasAvx2() ? fillTriangleAvx2 : fillTriangleScalar;
}

SpanFillFunction spanFill() {
  return cpuHasAvx2() ? fillSpanAvx2 : fillSpanScalar;
}

void fillTriangleScalar(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                        FrameBuffer& fb, RenderStats& stats) {
  int64_t e0 = s.edge[0].value, e1 = s.edge[1].value, e2 = s.edge[2].value;
  const int64_t x0 = s.edge[0].stepX, x1 = s.edge[1].stepX, x2 = s.edge[2].stepX;
  for (int y = s.minY; y <= s.maxY; ++y) {
    int64_t r0 = e0, r1 = e1, r2 = e2;
    int x = s.minX;
    // The covered samples of a row are contiguous: step to the first, then to the end of the
    // run, and depth-test the run as the scan-line z-buffer does a span.
    while (x <= s.maxX && (r0 | r1 | r2) < 0) {
      r0 += x0;
      r1 += x1;
      r2 += x2;
      ++x;
    }
    int end = x;
    while (end <= s.maxX && (r0 | r1 | r2) >= 0) {
      r0 += x0;
      r1 += x1;
      r2 += x2;
      ++end;
    }
    stats.pixelsTested += uint64_t(end - x);
    stats.pixelsWritten += fillSpanScalar(fb.row(y), x, end, plane, plane.rowBase(y), faceId);
    e0 += s.edge[0].stepY;
    e1 += s.edge[1].stepY;
    e2 += s.edge[2].stepY;
  }
}

namespace {

// What fillTriangleAvx2 keeps fixed over a triangle, broadcast to the four lanes, and its
// counters.
struct Avx2Triangle {
  __m256i minusOne, id;
  __m256d a;
  __m128i loBits, hiBits;
  // Minus the number of samples tested and won, per lane (compare masks are -1 where true).
  __m256i testedLanes, writtenLanes;
};

// The constants of a face, counters at zero.
ZRENDER_AVX2 inline Avx2Triangle avx2Face(const DepthPlane& plane, uint32_t faceId) {
  Avx2Triangle t;
  t.minusOne = _mm256_set1_epi64x(-1);
  t.id = _mm256_set1_epi64x(int64_t(faceId));
  t.a = _mm256_set1_pd(plane.a);
  t.loBits = _mm_set1_epi32(plane.loBits);
  t.hiBits = _mm_set1_epi32(plane.hiBits);
  t.testedLanes = t.writtenLanes = _mm256_setzero_si256();
  return t;
}

// Lanes k = 0..3 of the block starting at sample x that lie at or before maxX (-1 where true).
ZRENDER_AVX2 inline __m256i lanesUpTo(int x, int maxX) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(int64_t(maxX) - x + 1),
                            _mm256_setr_epi64x(0, 1, 2, 3));
}

// Depth-tests the samples of `cell` (four keys) whose edge values r0..r2 are all >= 0 and whose
// lane is in `inBounds`, at sample centres xCentre, and writes the winners. A block reads and
// writes back all four keys, unchanged where no sample wins; `lastOfRow`: the block may reach
// past the row's end, into the next row, which another thread may be drawing (bands of rows):
// it then touches the keys of `inBounds` only.
ZRENDER_AVX2 inline void fillBlock(Avx2Triangle& t, DepthKey* cell, __m256i inBounds, __m256i r0,
                                   __m256i r1, __m256i r2, __m256d xCentre, __m256d rowBase,
                                   bool lastOfRow = false) {
  const __m256i outside = _mm256_or_si256(_mm256_or_si256(r0, r1), r2);  // sign bit: outside
  const __m256i cover = _mm256_and_si256(_mm256_cmpgt_epi64(outside, t.minusOne), inBounds);
  const __m256d z = _mm256_add_pd(_mm256_mul_pd(t.a, xCentre), rowBase);
  __m128i bits = _mm_castps_si128(_mm256_cvtpd_ps(z));
  bits = _mm_min_epi32(_mm_max_epi32(bits, t.loBits), t.hiBits);
  const __m256i key = _mm256_or_si256(_mm256_slli_epi64(_mm256_cvtepu32_epi64(bits), 32), t.id);
  __m256i* p = reinterpret_cast<__m256i*>(cell);
  long long* q = reinterpret_cast<long long*>(cell);
  const __m256i old = lastOfRow ? _mm256_maskload_epi64(q, inBounds) : _mm256_loadu_si256(p);
  const __m256i wins = _mm256_and_si256(cover, _mm256_cmpgt_epi64(old, key));
  if (lastOfRow)
    _mm256_maskstore_epi64(q, wins, key);
  else
    _mm256_storeu_si256(p, _mm256_blendv_epi8(old, key, wins));
  t.testedLanes = _mm256_add_epi64(t.testedLanes, cover);
  t.writtenLanes = _mm256_add_epi64(t.writtenLanes, wins);
}

// Steps the edge values r0..r2 and the sample centres to the next block of four samples.
ZRENDER_AVX2 inline void nextBlock(__m256i& r0, __m256i& r1, __m256i& r2, __m256d& xCentre,
                                   const __m256i blockStep[3], __m256d four) {
  r0 = _mm256_add_epi64(r0, blockStep[0]);
  r1 = _mm256_add_epi64(r1, blockStep[1]);
  r2 = _mm256_add_epi64(r2, blockStep[2]);
  xCentre = _mm256_add_pd(xCentre, four);
}

ZRENDER_AVX2 inline uint64_t laneSum(__m256i v) {
  alignas(32) int64_t lanes[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), v);
  return uint64_t(lanes[0] + lanes[1] + lanes[2] + lanes[3]);
}

}  // namespace

// The scalar loop four samples wide. Bit-identical because every step is the same IEEE
// operation: b * (y + 0.5) + c, a * xCentre and + rowBase in double (no FMA: not enabled for
// this function and contraction is off), one rounding to float, the clamp on the bits as
// signed integers, and a signed 64-bit key comparison (keys are below 2^63: depth bits <= those
// of 1.0f). A block reads and writes back all four keys, unchanged where no sample wins, so a
// block may run up to three samples past maxX, but not past the row's end (fillBlock).
ZRENDER_AVX2 void fillTriangleAvx2(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                                   FrameBuffer& fb, RenderStats& stats) {
  static_assert(FrameBuffer::kPadding >= 3, "a block of four may pass the last sample by three");
  Avx2Triangle t = avx2Face(plane, faceId);
  // Edge values of the row's first block, and their steps per block and per row.
  __m256i rowStart[3], blockStep[3], rowStep[3];
  for (int i = 0; i < 3; ++i) {
    const int64_t v = s.edge[i].value, sx = s.edge[i].stepX;
    rowStart[i] = _mm256_setr_epi64x(v, v + sx, v + 2 * sx, v + 3 * sx);
    blockStep[i] = _mm256_set1_epi64x(4 * sx);
    rowStep[i] = _mm256_set1_epi64x(s.edge[i].stepY);
  }
  const __m256d b = _mm256_set1_pd(plane.b), c = _mm256_set1_pd(plane.c);
  const __m256d four = _mm256_set1_pd(4.0), one = _mm256_set1_pd(1.0);
  const __m256d firstCentre =
      _mm256_add_pd(_mm256_set1_pd(double(s.minX)), _mm256_setr_pd(0.5, 1.5, 2.5, 3.5));
  __m256d rowCentre = _mm256_set1_pd(s.minY + 0.5);
  const int blocks = (s.maxX - s.minX) / 4 + 1;
  // Two row loops, kept apart on purpose: merged (one row loop choosing per row, the block
  // stepping shared) they measured slower (docs/performance.md).
  if (blocks <= 3) {
    // Small triangles (most of a mesh's): every block of the bounds, without a branch.
    const __m256i inBounds[3] = {lanesUpTo(s.minX, s.maxX), lanesUpTo(s.minX + 4, s.maxX),
                                 lanesUpTo(s.minX + 8, s.maxX)};
    for (int y = s.minY; y <= s.maxY; ++y) {
      const __m256d rowBase = _mm256_add_pd(_mm256_mul_pd(b, rowCentre), c);
      DepthKey* cell = fb.row(y) + s.minX;
      __m256i r0 = rowStart[0], r1 = rowStart[1], r2 = rowStart[2];
      __m256d xCentre = firstCentre;
      for (int j = 0; j < blocks; ++j) {
        fillBlock(t, cell + 4 * j, inBounds[j], r0, r1, r2, xCentre, rowBase,
                  s.minX + 4 * j + 3 >= fb.width());
        nextBlock(r0, r1, r2, xCentre, blockStep, four);
      }
      for (int i = 0; i < 3; ++i) rowStart[i] = _mm256_add_epi64(rowStart[i], rowStep[i]);
      rowCentre = _mm256_add_pd(rowCentre, one);
    }
  } else {
    // Larger ones skip the blocks before their span on a row and stop after it.
    for (int y = s.minY; y <= s.maxY; ++y) {
      const __m256d rowBase = _mm256_add_pd(_mm256_mul_pd(b, rowCentre), c);
      DepthKey* row = fb.row(y);
      __m256i r0 = rowStart[0], r1 = rowStart[1], r2 = rowStart[2];
      __m256d xCentre = firstCentre;
      bool reached = false;
      for (int x = s.minX; x <= s.maxX; x += 4) {
        const __m256i outside = _mm256_or_si256(_mm256_or_si256(r0, r1), r2);
        if (_mm256_movemask_pd(_mm256_castsi256_pd(outside)) != 0xF) {
          fillBlock(t, row + x, lanesUpTo(x, s.maxX), r0, r1, r2, xCentre, rowBase,
                    x + 3 >= fb.width());
          reached = true;
        } else if (reached) {
          break;  // a triangle's samples on a row are contiguous
        }
        nextBlock(r0, r1, r2, xCentre, blockStep, four);
      }
      for (int i = 0; i < 3; ++i) rowStart[i] = _mm256_add_epi64(rowStart[i], rowStep[i]);
      rowCentre = _mm256_add_pd(rowCentre, one);
    }
  }
  stats.pixelsTested += uint64_t(0) - laneSum(t.testedLanes);
  stats.pixelsWritten += uint64_t(0) - laneSum(t.writtenLanes);
}

uint64_t fillSpanScalar(DepthKey* row, int left, int right, const DepthPlane& plane, double rowBase,
                        uint32_t faceId) {
  uint64_t written = 0;
  for (int x = left; x < right; ++x) {
    const DepthKey key = makeDepthKey(plane.at(x, rowBase), faceId);
    if (key < row[x]) {
      row[x] = key;
      ++written;
    }
  }
  return written;
}

// fillSpanScalar four samples at a time, with the same operations as fillTriangleAvx2 (and
// plane.at(x) = a * (x + 0.5) + rowBase, x + 0.5 exact in a double).
ZRENDER_AVX2 uint64_t fillSpanAvx2(DepthKey* row, int left, int right, const DepthPlane& plane,
                                   double rowBase, uint32_t faceId) {
  Avx2Triangle t = avx2Face(plane, faceId);
  const __m256d base = _mm256_set1_pd(rowBase), four = _mm256_set1_pd(4.0);
  __m256d xCentre = _mm256_add_pd(_mm256_set1_pd(double(left)), _mm256_setr_pd(0.5, 1.5, 2.5, 3.5));
  const __m256i zero = _mm256_setzero_si256();  // edge values: every lane inside
  for (int x = left; x < right; x += 4) {
    // The span's last block may reach past its end: the row's end, possibly.
    fillBlock(t, row + x, lanesUpTo(x, right - 1), zero, zero, zero, xCentre, base, x + 4 > right);
    xCentre = _mm256_add_pd(xCentre, four);
  }
  return uint64_t(0) - laneSum(t.writtenLanes);
}

}  // namespace zrender
