#include "zrender/cli/Report.hpp"

#include <algorithm>
#include <memory>
#include <sstream>

namespace zrender {

void printWarnings(Warnings& warnings, std::ostream& err) {
  for (const auto& w : warnings) err << "zrender: warning: " << messageLine(w) << "\n";
  warnings.clear();
}

Json::Value statsToJson(const RenderStats& s) {
  Json::Value j(Json::objectValue);
  j["triangles_backface_culled"] = Json::UInt64(s.trianglesBackfaceCulled);
  j["triangles_clipped_away"] = Json::UInt64(s.trianglesClippedAway);
  j["triangles_degenerate"] = Json::UInt64(s.trianglesDegenerate);
  j["triangles_rasterized"] = Json::UInt64(s.trianglesRasterized);
  j["triangles_hzb_culled"] = Json::UInt64(s.trianglesHzbCulled);
  j["octree_nodes_visited"] = Json::UInt64(s.octreeNodesVisited);
  j["octree_nodes_culled"] = Json::UInt64(s.octreeNodesCulled);
  j["pixels_tested"] = Json::UInt64(s.pixelsTested);
  j["pixels_written"] = Json::UInt64(s.pixelsWritten);
  for (const auto& [name, value] : s.extra) j[name] = Json::UInt64(value);
  return j;
}

std::string toJsonLine(const Json::Value& value) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "";
  builder["precision"] = 3;
  builder["precisionType"] = "decimal";
  return Json::writeString(builder, value);
}

void printStats(const RenderStats& s, const FrameTimings& times, std::ostream& out) {
  out << "triangles: " << s.trianglesRasterized << " rasterized, " << s.trianglesBackfaceCulled
      << " back-facing, " << s.trianglesClippedAway << " clipped away, " << s.trianglesDegenerate
      << " degenerate, " << s.trianglesHzbCulled << " rejected by the z-pyramid\n";
  out << "octree: " << s.octreeNodesVisited << " nodes visited, " << s.octreeNodesCulled
      << " rejected\n";
  out << "samples: " << s.pixelsTested << " depth tests, " << s.pixelsWritten << " written";
  if (s.pixelsTested)
    out << " (" << (100.0 * double(s.pixelsWritten) / double(s.pixelsTested)) << "% won)";
  out << "\n";
  for (const auto& [name, value] : s.extra) out << name << ": " << value << "\n";
  std::ostringstream ms;
  ms.setf(std::ios::fixed);
  ms.precision(3);
  ms << "time: " << times.transformMs << " ms transform, " << times.visibilityMs
     << " ms visibility, " << times.shadeMs << " ms shading (raster " << times.rasterMs()
     << " ms, frame " << times.frameMs() << " ms)\n";
  out << ms.str();
}

}  // namespace zrender
