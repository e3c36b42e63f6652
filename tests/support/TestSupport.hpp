#pragma once

// Helpers shared by the test files: tiny meshes built in code, rendering a scene with a named
// algorithm, and the reference models when setup has linked them.

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/SceneValidation.hpp"
#include "zrender/transform/GeometrySource.hpp"

namespace zrender::test {

// A mesh of the given polygons (0-based position indices), no normals or texcoords.
std::shared_ptr<const Mesh> makeMesh(const std::vector<Vec3>& positions,
                                     const std::vector<std::vector<int>>& faces);

// Settings for a tiny scene: `size` x `size` pixels, eye on +Z at distance 2 looking at the
// origin with a 90 degree field of view, so the plane z = 0 shows x, y in [-2, 2] across the
// image; near 0.1, far 10.
SceneSettings tinySettings(int size);

struct Rendered {
  FrameBuffer buffer;
  cv::Mat color;
  RenderStats stats;
};

// Renders one frame of the scene with the algorithm named (makeAlgorithm).
Rendered render(const Scene& scene, const std::string& algorithm);

// Convenience: mesh + settings -> scene -> render.
Rendered render(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                const std::string& algorithm);

// `count` random triangles in the cube [-1, 1]^3 with fixed seed; with `coplanarDuplicates`
// every 7th triangle is repeated exactly (same vertices), so ties must go to the smaller id.
std::shared_ptr<const Mesh> randomSoup(unsigned seed, int count, bool coplanarDuplicates);

// A reference model from models/ (bunny, spot, teapot), or null when setup has not linked it.
std::shared_ptr<const Mesh> referenceModel(const std::string& name);

// The project's settings.json entry for a scene (path resolved), for tests on real scenes.
SceneSettings projectScene(const std::string& name);

// What a run printed on stderr besides its last line, the summary of what it wrote
// ("zrender: wrote ..."): its warnings.
std::string beyondSummary(const std::string& err);

// The bytes of a file ("" when it cannot be read).
std::string readFile(const std::string& path);

// Result of running the zrender executable.
struct RunResult {
  int status = -1;       // exit status (128 + signal when killed)
  std::string out, err;  // standard output and error
  double seconds = 0.0;  // wall time
};

// Limits put on the child process.
struct RunLimits {
  unsigned alarmSeconds = 0;  // SIGALRM kills a run still going after this long; 0: none
  // Largest file the run may write, bytes (writes past it fail with EFBIG); 0: no limit.
  unsigned long fileSizeLimit = 0;
  // A signal sent to the run after `signalAfterSeconds`, if it is still going; 0: none.
  int signal = 0;
  double signalAfterSeconds = 0.0;
};

// Changes to the environment of a child process: each variable set to its value, or removed
// where the value is nullopt.
using Environment = std::vector<std::pair<std::string, std::optional<std::string>>>;

// Runs `argv` (argv[0] a path, or a name looked up in PATH; each one argument, no shell quoting
// needed) in the working directory `dir` (the project's folder when empty), with `environment`
// applied.
RunResult runProgram(const std::vector<std::string>& argv, const std::string& dir = "",
                     const RunLimits& limits = RunLimits(),
                     const Environment& environment = Environment());

// Runs the built zrender with `args`, as runProgram.
RunResult runZrender(const std::vector<std::string>& args, const std::string& dir = "",
                     const RunLimits& limits = RunLimits(),
                     const Environment& environment = Environment());

// A fresh empty folder under the system temp folder, removed by the destructor.
struct TempDir {
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string path;
  std::string file(const std::string& name) const { return path + "/" + name; }
  // Writes `text` to `name` inside the folder and returns its path.
  std::string write(const std::string& name, const std::string& text) const;
};

// GoogleTest expectations that `r` equals the reference `ref` bit for bit: keys (depth and
// face ids) and colors; `label` names the case in failures.
void expectSameFrame(const Rendered& ref, const Rendered& r, const std::string& label);

// Number of samples some face covers.
size_t coveredSamples(const FrameBuffer& fb);

// A GeometrySource for algorithms run on a FrameGeometry built by the test: its pulls add
// nothing, as the faces are already in the geometry the algorithm is given.
class GivenGeometry : public GeometrySource {
 public:
  void beginFrame(const Camera&) override {}
  void pull(const FaceRequest&, FrameGeometry&, std::vector<FrameGeometry>*) override {}
  InstanceView viewOfInstance(uint32_t) const override { return InstanceView(); }
  double transformMs() const override { return 0.0; }
};

// Number of samples whose keys differ.
size_t countDifferences(const FrameBuffer& a, const FrameBuffer& b);

}  // namespace zrender::test
