#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "zrender/cli/RenderCommand.hpp"
#include "zrender/scene/SceneSettings.hpp"

namespace zrender {

// The views of a render command (docs/design.md, Views) and the part of them this run renders.
struct ViewPlan {
  std::vector<ViewSpec> views;       // at least one
  std::vector<std::string> origins;  // per view, what a message about it names
  bool multiView = false;            // files per view: --orbit, --turntable or settings views
  bool turntable = false;            // --turntable
  size_t first = 0, end = 0;         // this run's views: [first, end)
  bool whole() const { return first == 0 && end == views.size(); }
};

// The views of `options` for the scene `settings`: --turntable N (the model turned, as the
// eye going the other way), --orbit N with --orbit-elevations, the scene's `views`, or the
// scene's camera; each with --azimuth, --elevation and --zoom on top. Then --frames and --shard
// choose the part. InputError for a bad range or shard.
ViewPlan planViews(const RenderOptions& options, const SceneSettings& settings);

}  // namespace zrender
