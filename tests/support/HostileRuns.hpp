#pragma once

// Helpers of the end-to-end hostile cases (e2e/): each case runs the built executable in a temp
// folder and must either exit 0 with a sensible picture or exit 2 with exactly one stderr line
// "zrender: error: ..." naming the file and line or key; never crash, hang or take more than a
// few seconds.

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "support/CommandLineRuns.hpp"
#include "support/TestSupport.hpp"

namespace zrender::test {

// Sanitizer builds run the executable several times slower; the time limits scale with them.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 6.0;
#else
constexpr double kSlowdown = 1.0;
#endif
// Whether a failed allocation throws std::bad_alloc: the sanitizers' operator new ends the
// process instead.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kBadAllocThrown = false;
#else
constexpr bool kBadAllocThrown = true;
#endif
// What "a few seconds" means for one run of a small case.
constexpr double kQuickSeconds = 5.0;
// The width and height of the pictures of renderModel() and of writeScene()'s scene.
constexpr int kImageSize = 32;

using Outcome = RunResult;

// test::runZrender with an alarm that kills a hanging run, scaled for sanitizer builds, and
// optionally a file size limit so that writing the output fails part way.
Outcome runLimited(const std::vector<std::string>& args, const std::string& dir,
                   double timeoutSeconds = 60, unsigned long fileSizeLimit = 0);

// Runs zrender with `args` in `dir`, where the folder `dir`/`small` is a file system of `bytes`
// bytes (a tmpfs in a mount namespace of the run's own, through unshare(1)) that starts with
// what `small` held; afterwards `small` holds what the run left in it. nullopt when this machine
// cannot make one (no unshare, or no user namespaces), with the reason in `why`.
std::optional<Outcome> runOnSmallDisk(const std::vector<std::string>& args, const TempDir& dir,
                                      const std::string& small, size_t bytes, std::string& why);

// Exit 2, one stderr line starting "zrender: error: " that contains every piece of `mustName`,
// in a few seconds.
void expectQuickCleanError(const Outcome& r, const std::vector<std::string>& mustName,
                           double seconds = kQuickSeconds);

// Exit 0 (warnings allowed) and a PNG of the given size; returns it (BGR).
cv::Mat expectPicture(const Outcome& r, const std::string& path, int width, int height,
                      double seconds = kQuickSeconds);

// Pixels that are not black.
int coveredPixels(const cv::Mat& image);

bool sameImage(const cv::Mat& a, const cv::Mat& b);

// Files in a folder, sorted.
std::vector<std::string> listFolder(const std::string& dir);

// Renders `model` (written to the temp folder as m.obj, a model file as SCENE: defaults and
// fit) with one algorithm at kImageSize x kImageSize into out.png.
Outcome renderModel(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra = {});

// A settings.json with one scene "s": `model`, kImageSize x kImageSize, and the JSON members in
// `keys`.
void writeScene(const TempDir& dir, const std::string& keys, const std::string& model = "m.obj");

// Renders writeScene()'s scene "s" with one algorithm into out.png.
Outcome renderScene(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra = {});

// A grid of w x h quads split in two triangles: 2 (w - 1) (h - 1) faces.
std::string gridModel(int w, int h);

}  // namespace zrender::test
