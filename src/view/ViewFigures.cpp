#include "zrender/view/ViewFigures.hpp"

#include <cstdio>

namespace zrender {

std::vector<std::string> viewFigures(const ViewState& state, const FrameTimes& times,
                                     const RenderStats& stats) {
  std::vector<std::string> lines;
  lines.push_back(state.algorithm + "  " + shadingModeName(state.shading) + "  msaa " +
                  std::to_string(state.msaa) + "  cull " + (state.cull ? "on" : "off") +
                  (state.paused ? "  paused" : ""));
  char text[160];
  std::snprintf(text, sizeof text, "frame %.2f ms (median of %zu)  %.1f fps", times.medianFrameMs(),
                times.count(), times.framesPerSecond());
  lines.push_back(text);
  std::snprintf(text, sizeof text, "culled: %llu back-facing, %llu clipped, %llu by the z-pyramid",
                static_cast<unsigned long long>(stats.trianglesBackfaceCulled),
                static_cast<unsigned long long>(stats.trianglesClippedAway),
                static_cast<unsigned long long>(stats.trianglesHzbCulled));
  lines.push_back(text);
  std::snprintf(text, sizeof text, "drawn: %llu triangles; octree nodes: %llu of %llu culled",
                static_cast<unsigned long long>(stats.trianglesRasterized),
                static_cast<unsigned long long>(stats.octreeNodesCulled),
                static_cast<unsigned long long>(stats.octreeNodesVisited));
  lines.push_back(text);
  return lines;
}

}  // namespace zrender
