#include "zrender/shading/SurfaceKernel.hpp"

#include "SurfaceSample.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

void shadeSurfaceRunScalar(const SurfaceFrame& frame, const FaceSurface& face,
                           const SurfaceFan* fans, int x, int y, int count, uint32_t* out) {
  for (int i = 0; i < count; ++i) out[i] = surface::shadeSample(frame, face, fans, x + i, y);
}

void shadeSurfaceRowScalar(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                           uint32_t background, uint32_t* out) {
  for (int x = 0; x < width;) {
    const int end = runEndScalar(keys, x, width);
    const uint32_t id = keyFaceId(keys[x]);
    if (id == kBackgroundId) {
      for (int i = x; i < end; ++i) out[i] = background;
    } else {
      const FaceSurface& face = setup.surface(id);
      shadeSurfaceRunScalar(setup.frame(), face, setup.fans(face), x, y, end - x, out + x);
    }
    x = end;
  }
}

SurfaceRowFunction surfaceRow() {
  if (!cpuHasAvx2()) return shadeSurfaceRowScalar;
  return cpuGathersQuickly() ? shadeSurfaceRowAvx2Gathers : shadeSurfaceRowAvx2;
}

SurfaceBgrRowFunction surfaceBgrRow() {
  if (!cpuHasAvx2()) return nullptr;
  return cpuGathersQuickly() ? shadeSurfaceBgrRowAvx2Gathers : shadeSurfaceBgrRowAvx2;
}

}  // namespace zrender
