#include "zrender/cli/ViewPlan.hpp"

#include <cctype>
#include <cstdint>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

// A whole number of at most 18 digits, the whole of `text`; false otherwise.
bool parseCount(const std::string& text, size_t& out) {
  if (text.empty() || text.size() > 18) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  out = size_t(std::stoull(text));
  return true;
}

// --frames A:B, either end optional: views [A, B) of `count`.
void applyFrames(const std::string& text, size_t count, size_t& first, size_t& end) {
  const size_t colon = text.find(':');
  const std::string a = text.substr(0, colon);
  const std::string b = colon == std::string::npos ? "" : text.substr(colon + 1);
  size_t lo = 0, hi = count;
  const bool ok = colon != std::string::npos && (a.empty() || parseCount(a, lo)) &&
                  (b.empty() || parseCount(b, hi)) && lo < hi && hi <= count;
  if (!ok) {
    throw InputError(
        "command line: --frames: expected A:B with 0 <= A < B <= " + std::to_string(count) +
        " (views A to B - 1 of " + std::to_string(count) + "), got '" + text + "'");
  }
  first = lo;
  end = hi;
}

// --shard I/N: the I-th of N contiguous parts of [first, end), as even as whole views allow.
void applyShard(const std::string& text, size_t& first, size_t& end) {
  const size_t slash = text.find('/');
  size_t index = 0, parts = 0;
  const bool ok = slash != std::string::npos && parseCount(text.substr(0, slash), index) &&
                  parseCount(text.substr(slash + 1), parts) && parts >= 1 && index < parts;
  if (!ok) {
    throw InputError(
        "command line: --shard: expected I/N with 0 <= I < N (the I-th of N parts), "
        "got '" +
        text + "'");
  }
  const size_t count = end - first;
  const size_t lo = first + size_t(uint64_t(count) * index / parts);
  const size_t hi = first + size_t(uint64_t(count) * (index + 1) / parts);
  first = lo;
  end = hi;
}

}  // namespace

ViewPlan planViews(const RenderOptions& options, const SceneSettings& settings) {
  ViewPlan plan;
  if (options.turntable > 0) {
    plan.multiView = plan.turntable = true;
    for (int k = 0; k < options.turntable; ++k) {
      ViewSpec view;
      // The model turns the other way; an --azimuth of 0 leaves the turn's bits as they are.
      view.azimuth = options.azimuth.value_or(0.0) + -(360.0 * k / options.turntable);
      view.elevation = options.elevation.value_or(0.0);
      view.zoom = options.zoom.value_or(1.0);
      plan.views.push_back(view);
      plan.origins.push_back("command line: --turntable frame " + std::to_string(k));
    }
  } else if (options.orbit > 0) {
    plan.multiView = true;
    const std::vector<double> rings = options.orbitElevations.empty()
                                          ? std::vector<double>{options.elevation.value_or(0.0)}
                                          : options.orbitElevations;
    for (double elevation : rings) {
      for (int k = 0; k < options.orbit; ++k) {
        ViewSpec view;
        view.azimuth = options.azimuth.value_or(0.0) + 360.0 * k / options.orbit;
        view.elevation = elevation;
        view.zoom = options.zoom.value_or(1.0);
        plan.views.push_back(view);
        plan.origins.push_back("command line: --orbit view " + std::to_string(k));
      }
    }
  } else if (!settings.views.empty()) {
    plan.multiView = true;
    for (size_t i = 0; i < settings.views.size(); ++i) {
      ViewSpec view = settings.views[i];
      view.azimuth += options.azimuth.value_or(0.0);
      view.elevation += options.elevation.value_or(0.0);
      view.zoom *= options.zoom.value_or(1.0);
      plan.views.push_back(view);
      plan.origins.push_back(
          (settings.where.empty() ? "scene '" + settings.name + "'" : settings.where) +
          ": key 'views[" + std::to_string(i) + "]'");
    }
  } else {
    ViewSpec view;
    view.azimuth = options.azimuth.value_or(0.0);
    view.elevation = options.elevation.value_or(0.0);
    view.zoom = options.zoom.value_or(1.0);
    plan.views.push_back(view);
    plan.origins.push_back("command line");
  }
  plan.end = plan.views.size();
  if (options.frames) applyFrames(*options.frames, plan.views.size(), plan.first, plan.end);
  if (options.shard) applyShard(*options.shard, plan.first, plan.end);
  return plan;
}

}  // namespace zrender
