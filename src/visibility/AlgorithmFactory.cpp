#include <functional>
#include <utility>

#include "zrender/base/Error.hpp"
#include "zrender/visibility/HierarchicalAlgorithm.hpp"
#include "zrender/visibility/IntervalAlgorithm.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"
#include "zrender/visibility/ScanlineAlgorithm.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

namespace zrender {

namespace {

using Maker = std::function<std::unique_ptr<VisibilityAlgorithm>()>;

// The registry, in the order of docs/design.md, The algorithms. A new algorithm adds one line here.
const std::vector<std::pair<std::string, Maker>>& registry() {
  static const std::vector<std::pair<std::string, Maker>> makers = {
      {"zbuffer", [] { return std::make_unique<ZBufferAlgorithm>(); }},
      {"scanline", [] { return std::make_unique<ScanlineAlgorithm>(); }},
      {"interval", [] { return std::make_unique<IntervalAlgorithm>(); }},
      {"hierarchical", [] { return std::make_unique<HierarchicalAlgorithm>(); }},
      {"octree", [] { return std::make_unique<OctreeAlgorithm>(); }},
  };
  return makers;
}

}  // namespace

const std::vector<std::string>& algorithmNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& entry : registry()) n.push_back(entry.first);
    return n;
  }();
  return names;
}

std::unique_ptr<VisibilityAlgorithm> makeAlgorithm(const std::string& name) {
  for (const auto& entry : registry())
    if (entry.first == name) return entry.second();
  std::string list;
  for (const auto& n : algorithmNames()) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown algorithm '" + name + "' (choose from: " + list + ")");
}

}  // namespace zrender
