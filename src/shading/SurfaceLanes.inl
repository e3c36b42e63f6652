// The vector surface kernel, written once for every vector width: SurfaceKernel.cpp includes it
// in a namespace per width, after defining there the lane types F (floats), I (32-bit
// integers) and M (a lane mask), kLanes, the operations used below (splat, iota, add, ..., each
// one vector instruction or a fixed short sequence), and ZRENDER_LANES, the functions' target
// attribute. Lane by lane, every function does what its scalar twin in SurfaceKernel.cpp does,
// operation for operation.

// A plane along a run of one row: its row value and its a, in every lane.
struct RowPlane {
  F row, a;
};

ZRENDER_LANES inline RowPlane rowPlane(const SamplePlane& p, float sy) {
  return RowPlane{splat(rowValue(p, sy)), splat(p.a)};
}

ZRENDER_LANES inline F at(const RowPlane& p, F sx) {
  return add(p.row, mul(p.a, sx));
}

// (a * w0 + b * u) + c * v for one attribute's three corner values.
ZRENDER_LANES inline F blend3(float a, float b, float c, F w0, F u, F v) {
  return add(add(mul(splat(a), w0), mul(splat(b), u)), mul(splat(c), v));
}

// sampleTexture's operations: R, G, B in 0..255.
ZRENDER_LANES inline void sampleTextureLanes(const SurfaceFrame& f, F u, F v, F rgb[3]) {
  const F zero = splat(0.0f), one = splat(1.0f), half = splat(0.5f);
  F uu = sub(u, floor(u)), vv = sub(v, floor(v));
  uu = min(max(uu, zero), one);
  vv = min(max(vv, zero), one);
  const F tx = sub(mul(uu, splat(float(f.textureWidth))), half);
  const F ty = sub(mul(sub(one, vv), splat(float(f.textureHeight))), half);
  const F fx0 = floor(tx), fy0 = floor(ty);
  const F fx = sub(tx, fx0), fy = sub(ty, fy0);
  const I x0 = wrapNegative(cvtt(fx0), f.textureWidth);
  const I y0 = wrapNegative(cvtt(fy0), f.textureHeight);
  const I stride = isplat(f.textureWidth + 1);
  const I index0 = iadd(imul(y0, stride), x0);
  const I index1 = iadd(index0, stride);
  I a, b, c, d;  // texels (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1)
  gatherPairs(f.texels, index0, a, b);
  gatherPairs(f.texels, index1, c, d);
  const F ofx = sub(one, fx), ofy = sub(one, fy);
  for (int i = 0; i < 3; ++i) {
    const int shift = 16 - 8 * i;  // R, G, B
    const F top = add(mul(channel(a, shift), ofx), mul(channel(b, shift), fx));
    const F bottom = add(mul(channel(c, shift), ofx), mul(channel(d, shift), fx));
    rgb[i] = add(mul(top, ofy), mul(bottom, fy));
  }
}

ZRENDER_LANES inline I toBytes(F t) {
  return cvtt(min(max(t, splat(0.5f)), splat(255.5f)));
}

// shadeSample's operations for a run of a triangle face (one fan), kLanes lanes at a time, with
// what the run's samples share (the planes' row values, the ray's row) computed once. The last
// block writes up to kLanes - 1 colors past the run: `out` must have room for them. Inline
// where runs are colored, so that successive blocks overlap.
ZRENDER_LANES [[gnu::always_inline]] inline void shadeTriangleRun(const SurfaceFrame& f,
                                                                  const FaceSurface& face,
                                                                  const SurfaceFan& fan, int x,
                                                                  int y, int count,
                                                                  uint32_t* out) {
  const float sy = float(y - face.originY);
  const RowPlane den = rowPlane(fan.den, sy), pu = rowPlane(fan.pu, sy), pv = rowPlane(fan.pv, sy);
  const RowPlane normal[3] = {rowPlane(fan.normal[0], sy), rowPlane(fan.normal[1], sy),
                              rowPlane(fan.normal[2], sy)};
  RowPlane uv[2] = {};
  if (face.textured) uv[0] = rowPlane(fan.uv[0], sy), uv[1] = rowPlane(fan.uv[1], sy);
  const bool lit = f.mode != ShadingMode::Normal;
  const float dyValue = f.rayOriginY - (float(y) + 0.5f) * f.rayScaleY;
  const F dy = splat(dyValue), dyTerm = splat(dyValue * dyValue + 1.0f);
  const F zero = splat(0.0f), one = splat(1.0f), lane = iota();
  for (int i = 0; i < count; i += kLanes) {
    // x + i - originX + lane and x + i + lane, exactly (small integers).
    const F sx = add(splat(float(x + i - face.originX)), lane);
    // attributesAt.
    const F d0 = at(den, sx), a0 = at(pu, sx), b0 = at(pv, sx);
    const F sign = signOf(d0);
    const F d = flipBy(d0, sign), a = flipBy(a0, sign), b = flipBy(b0, sign);
    const F w = sub(sub(d, a), b);
    const M inside = mand(gt(d, zero), ge(min(min(a, b), w), zero));
    F m[3], tu = zero, tv = zero;
    for (int k = 0; k < 3; ++k) m[k] = flipBy(at(normal[k], sx), sign);
    if (face.textured) {
      const F inv = div(one, d0);
      tu = mul(at(uv[0], sx), inv);
      tv = mul(at(uv[1], sx), inv);
    }
    // Samples outside the face are few; lanes past the run's end (their colors are not kept)
    // do not count.
    if (!all(mor(inside, ge(lane, splat(float(count - i)))))) {
      F u = zero, v = zero;
      if (!fan.degenerate) {
        const F inv = div(one, d0), huge = splat(kHugeWeight);
        u = min(max(mul(a0, inv), zero), huge);
        v = min(max(mul(b0, inv), zero), huge);
        const F s = add(u, v);
        const M over = gt(s, one);
        const F invS = div(one, s);
        u = select(over, mul(u, invS), u);
        v = select(over, mul(v, invS), v);
      }
      const F w0 = sub(sub(one, u), v);
      for (int k = 0; k < 3; ++k)
        m[k] = select(inside, m[k],
                      blend3(fan.cornerNormal[0][k], fan.cornerNormal[1][k],
                             fan.cornerNormal[2][k], w0, u, v));
      if (face.textured) {
        tu = select(inside, tu,
                    blend3(fan.cornerUv[0][0], fan.cornerUv[1][0], fan.cornerUv[2][0], w0, u, v));
        tv = select(inside, tv,
                    blend3(fan.cornerUv[0][1], fan.cornerUv[1][1], fan.cornerUv[2][1], w0, u, v));
      }
    }
    F length2 = add(add(mul(m[0], m[0]), mul(m[1], m[1])), mul(m[2], m[2]));
    const M positive = gt(length2, zero);  // else +Z
    m[0] = select(positive, m[0], zero);
    m[1] = select(positive, m[1], zero);
    m[2] = select(positive, m[2], one);
    length2 = select(positive, length2, one);
    F t[3];
    if (!lit) {
      const F scale = div(splat(127.5f), sqrt(length2));
      for (int k = 0; k < 3; ++k) t[k] = add(mul(m[k], scale), splat(128.0f));
    } else {
      if (face.flip)
        for (F& c : m) c = sub(zero, c);
      const F px = add(splat(float(x + i)), lane);
      const F dx = add(splat(f.rayOriginX), mul(add(px, splat(0.5f)), splat(f.rayScaleX)));
      const F ray2 = add(mul(dx, dx), dyTerm);
      const F dot = sub(m[2], add(mul(m[0], dx), mul(m[1], dy)));
      const F diffuse = div(max(dot, zero), sqrt(mul(length2, ray2)));
      const F noSpecular = splat(kNoSpecular);
      F specular = max(diffuse, noSpecular);
      for (int k = 0; k < 6; ++k) specular = mul(specular, specular);
      specular = select(ge(diffuse, noSpecular), specular, zero);
      const F light = add(splat(0.1f), mul(splat(0.9f), diffuse));
      const F shine = add(mul(splat(76.5f), specular), splat(0.5f));
      F base[3] = {splat(face.base[0]), splat(face.base[1]), splat(face.base[2])};
      if (face.textured) sampleTextureLanes(f, tu, tv, base);
      for (int k = 0; k < 3; ++k) t[k] = add(mul(base[k], light), shine);
    }
    store(out + i, ior(ior(ishl(toBytes(t[0]), 16), ishl(toBytes(t[1]), 8)), toBytes(t[2])));
  }
}

// shadeSurfaceRowScalar's work, the runs' loops inline: a row holds many short runs, and a call
// per run would cost more than its samples. Like a run, a background run may write up to
// kLanes - 1 colors past its end.
ZRENDER_LANES void shadeRow(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                            uint32_t background, uint32_t* out) {
  const SurfaceFrame& frame = setup.frame();
  for (int x = 0; x < width;) {
    const int end = runEndAvx2(keys, x, width);
    const uint32_t id = keyFaceId(keys[x]);
    if (id == kBackgroundId) {
      const I fill = isplat(int(background));
      for (int i = x; i < end; i += kLanes) store(out + i, fill);
    } else {
      const FaceSurface& face = setup.surface(id);
      const SurfaceFan* fans = setup.fans(face);
      if (face.fanCount != 1)  // polygons: the scalar path, the same bits
        shadeSurfaceRunScalar(frame, face, fans, x, y, end - x, out + x);
      else
        SHADE_SHORT_OR_LONG_RUN(frame, face, *fans, x, y, end - x, out + x);
    }
    x = end;
  }
}
