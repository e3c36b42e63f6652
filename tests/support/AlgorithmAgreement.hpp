#pragma once

// Every algorithm against the z-buffer: bit-identical keys (depth + id) and colors.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"

namespace zrender::test {

// The algorithms that test triangles against the z-pyramid, and the scan-line ones.
extern const std::vector<std::string> kPyramidAlgorithms;   // hierarchical, octree
extern const std::vector<std::string> kScanlineAlgorithms;  // scanline, interval

struct Compared {
  size_t covered = 0;              // samples zbuffer covered
  std::vector<RenderStats> stats;  // per entry of the algorithms compared
};

// Renders `scene` with zbuffer and each of `algorithms`; keys and colors must be equal. `what`
// names the case in failures.
Compared expectSameAsZBuffer(const Scene& scene, const std::vector<std::string>& algorithms,
                             const std::string& what);
Compared expectSameAsZBuffer(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                             const std::vector<std::string>& algorithms, const std::string& what);

// A reference scene of settings.json at `size` x `size`, or null (the caller skips the test)
// when setup has not linked its model.
std::shared_ptr<const Mesh> referenceScene(const std::string& name, int size,
                                           SceneSettings& settings);

// An algorithm's own counter (RenderStats::extra) named `name`; 0 when it has none.
uint64_t extraCounter(const RenderStats& stats, const std::string& name);

// Renders with `interval` only and returns one of its counters (to check that a test reaches
// the code path it is meant for).
uint64_t intervalCounter(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                         const std::string& name);

// Loads `obj` (OBJ text), renders it with every algorithm as the render fuzz target does and
// expects them to agree; returns zbuffer's frame.
Rendered expectAgreement(const std::string& obj, const SceneSettings& settings);

// Whether no sample holds a face.
bool allBackground(const FrameBuffer& buffer);

}  // namespace zrender::test
