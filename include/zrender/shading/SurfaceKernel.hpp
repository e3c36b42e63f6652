#pragma once

#include <cstdint>

#include "zrender/raster/RasterRules.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

// The per-sample part of the shading modes that interpolate attributes over a face (`normal`
// with vertex normals, `phong`, `texture`), in float: a scalar version (the reference) and an
// AVX2 one, eight samples at a time, doing the same IEEE operations in the same order (fused
// multiply-adds included), so that they give the same bits (tested on random faces).
// docs/design.md, Shading, gives the formulas and why float is close enough to the
// double-precision shader the tests keep as the reference.

// A fan triangle of a face (corners 0, j and j + 1). The view ray through a sample meets the
// triangle's plane at (1 - u - v) p0 + u pj + v pj+1 with u = pu / den and v = pv / den, three
// planes, signed so that den > 0 where the ray meets the plane in front of the eye. An
// attribute interpolated there, (1 - u - v) A0 + u Aj + v Aj+1, is then
// (A0 den + (Aj - A0) pu + (Aj+1 - A0) pv) / den, a plane over den (the attribute over w, in
// the usual words). A sample inside the triangle reads the attributes' planes; one outside it
// (beyond the face's snapped edge) gets the attributes of the nearest point of the triangle,
// from the corners'.
//
// A plane is an affine function of the sample position relative to its face's origin
// (FaceSurface), fma(a, sx, fma(b, sy, c)): from a nearby origin the float terms stay small,
// and the inner term is the same along a row. The eight planes' terms are stored side by side,
// so that a row's eight inner terms are one vector operation.
enum SurfacePlane {
  kDen,
  kPu,
  kPv,
  kNormalX,  // the normal over den, view space; turned to the eye's side for a back face in
  kNormalY,  // the lit modes
  kNormalZ,
  kTextureU,  // the texture coordinates over den
  kTextureV,
  kSurfacePlanes
};
struct SurfaceFan {
  alignas(32) float a[kSurfacePlanes];
  alignas(32) float b[kSurfacePlanes];
  alignas(32) float c[kSurfacePlanes];
  float cornerNormal[3][3];  // unit normals of corners 0, j, j + 1, as the normal's planes
  float cornerUv[3][2];      // their texture coordinates (0 where the face has none)
  bool degenerate;           // zero area: corner 0's attributes everywhere
};

// A texture as the samples read it: 0x00RRGGBB, row 0 at the top (v = 1), framed by a copy of
// its last column and row before the first and of its first after the last: (width + 2) x
// (height + 2) texels, texel (x, y) at (y + 1) (width + 2) + x + 1.
struct SurfaceTexture {
  const uint32_t* texels = nullptr;
  int width = 0, height = 0;
};

// What a face shares over its samples. 32 bytes, so that a triangle's record (its surface and
// its fan, SurfaceSetup) is three cache lines: the set-up writes every face's record and the rows
// read it, and the records' bytes weigh on both (docs/performance.md, Shading).
struct FaceSurface {
  int32_t originX = 0, originY = 0;  // samples: where its planes are evaluated from
  uint32_t firstFan = 0, fanCount = 0;
  float base[3] = {204.0f, 204.0f, 204.0f};  // diffuse RGB, 0..255 (material Kd times 255)
  // Its texture, SurfaceFrame::textures[texture], whose color at the sample's uv takes the
  // place of `base`; -1: none.
  int32_t texture = -1;
  bool textured() const { return texture >= 0; }
};

// What every sample of a frame shares.
struct SurfaceFrame {
  ShadingMode mode = ShadingMode::Phong;  // Normal, Phong or Texture
  // The view-space ray through the centre of sample (x, y) is (fma(x, rayScaleX, rayOriginX),
  // fma(y, -rayScaleY, rayOriginY), -1).
  float rayOriginX = 0.0f, rayOriginY = 0.0f, rayScaleX = 0.0f, rayScaleY = 0.0f;
  const SurfaceTexture* textures = nullptr;  // the faces' textures (FaceSurface::texture)
};

// Colors samples [x, x + count) of row y, all covered by the face `face` (whose fans are
// fans[0, face.fanCount)), into out[0, count) as 0x00RRGGBB.
void shadeSurfaceRunScalar(const SurfaceFrame& frame, const FaceSurface& face,
                           const SurfaceFan* fans, int x, int y, int count, uint32_t* out);
// Eight samples at a time. Call only when cpuHasAvx2(). The texture's texels are read by
// loads, or by gathers (the same bits): faster where gathers are (cpuGathersQuickly()).
void shadeSurfaceRunAvx2(const SurfaceFrame& frame, const FaceSurface& face, const SurfaceFan* fans,
                         int x, int y, int count, uint32_t* out);
void shadeSurfaceRunAvx2Gathers(const SurfaceFrame& frame, const FaceSurface& face,
                                const SurfaceFan* fans, int x, int y, int count, uint32_t* out);

class SurfaceSetup;

// Colors sample row y, keys[0, width), into out[0, width) (`out` has room for 8 more, which
// the vector version may overwrite): the background as `background`, each run of a face's
// samples as the run functions above, with the faces' surfaces from `setup` (set up on first
// sight).
void shadeSurfaceRowScalar(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                           uint32_t background, uint32_t* out);
void shadeSurfaceRowAvx2(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                         uint32_t background, uint32_t* out);
void shadeSurfaceRowAvx2Gathers(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                                uint32_t background, uint32_t* out);

// The same row written straight into an image row as B, G, R bytes, bgr[0, 3 width), nothing
// past it: the bytes that packBgrScalar makes of the colors above, without a second pass over
// the row.
void shadeSurfaceBgrRowAvx2(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                            uint32_t background, uint8_t* bgr);
void shadeSurfaceBgrRowAvx2Gathers(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                                   uint32_t background, uint8_t* bgr);

using SurfaceRowFunction = void (*)(SurfaceSetup&, const DepthKey*, int, int, uint32_t, uint32_t*);
using SurfaceBgrRowFunction = void (*)(SurfaceSetup&, const DepthKey*, int, int, uint32_t,
                                       uint8_t*);
// The AVX2 version where the CPU runs it (with gathers where they are quick), else the scalar
// one.
SurfaceRowFunction surfaceRow();
// The AVX2 version where the CPU runs it, else none (the colors, then packBgr()).
SurfaceBgrRowFunction surfaceBgrRow();

}  // namespace zrender
