#include "support/HostileRuns.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "support/TestImages.hpp"

namespace zrender::test {

namespace fs = std::filesystem;

Outcome runLimited(const std::vector<std::string>& args, const std::string& dir,
                   double timeoutSeconds, unsigned long fileSizeLimit) {
  RunLimits limits;
  limits.alarmSeconds = unsigned(timeoutSeconds * kSlowdown) + 1;
  limits.fileSizeLimit = fileSizeLimit;
  return runZrender(args, dir, limits);
}

std::optional<Outcome> runOnSmallDisk(const std::vector<std::string>& args, const TempDir& dir,
                                      const std::string& small, size_t bytes, std::string& why) {
  // Exit 97: the file system could not be made, before zrender ran.
  const char* script = R"(d=$1; size=$2; shift 2
    cp -a "$d/." "$d.seed/" && mount -t tmpfs -o "size=$size" none "$d" && cp -a "$d.seed/." "$d/" || exit 97
    "$@"; rc=$?
    cp -a "$d/." "$d.after/" || exit 97
    exit $rc)";
  const std::string folder = dir.file(small);
  fs::create_directories(folder + ".seed");
  fs::create_directories(folder + ".after");
  std::vector<std::string> argv = {
      "unshare", "-Urm", "sh", "-c", script, "sh", folder, std::to_string(bytes), ZRENDER_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  RunLimits limits;
  limits.alarmSeconds = unsigned(60 * kSlowdown);
  const Outcome r = runProgram(argv, dir.path, limits);
  fs::remove_all(folder + ".seed");
  if (r.status == 97 || (r.status == 1 && r.err.rfind("unshare:", 0) == 0)) {
    why = "cannot make a small file system here: " + r.err;
    fs::remove_all(folder + ".after");
    return std::nullopt;
  }
  fs::remove_all(folder);
  fs::rename(folder + ".after", folder);
  return r;
}

void expectQuickCleanError(const Outcome& r, const std::vector<std::string>& mustName,
                           double seconds) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("zrender: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n');
  for (const auto& piece : mustName) EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, seconds * kSlowdown);
}

cv::Mat expectPicture(const Outcome& r, const std::string& path, int width, int height,
                      double seconds) {
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_LT(r.seconds, seconds * kSlowdown);
  const cv::Mat image = test::imread(path, cv::IMREAD_COLOR);
  EXPECT_FALSE(image.empty()) << path;
  if (image.empty()) return image;
  EXPECT_EQ(image.cols, width);
  EXPECT_EQ(image.rows, height);
  return image;
}

int coveredPixels(const cv::Mat& image) {
  int n = 0;
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) n += image.at<cv::Vec3b>(y, x) != cv::Vec3b(0, 0, 0);
  return n;
}

bool sameImage(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

std::vector<std::string> listFolder(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

Outcome renderModel(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"m.obj",   "-a", algorithm,  "-o", "out.png",
                                   "--width", "32", "--height", "32"};
  args.insert(args.end(), extra.begin(), extra.end());
  return runLimited(args, dir.path);
}

void writeScene(const TempDir& dir, const std::string& keys, const std::string& model) {
  dir.write("settings.json", R"({"s": {"path": ")" + model + R"(", "width": 32, "height": 32)" +
                                 (keys.empty() ? "" : ", " + keys) + "}}");
}

Outcome renderScene(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"s", "-a", algorithm, "-o", "out.png"};
  args.insert(args.end(), extra.begin(), extra.end());
  return runLimited(args, dir.path);
}

std::string gridModel(int w, int h) {
  std::string text;
  text.reserve(size_t(w) * h * 60);
  char line[96];
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      std::snprintf(line, sizeof line, "v %d %d %d\n", i, j, (i * j) % 7);
      text += line;
    }
  }
  for (int j = 0; j + 1 < h; ++j) {
    for (int i = 0; i + 1 < w; ++i) {
      const int a = j * w + i + 1;
      std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, a + 1, a + w + 1, a,
                    a + w + 1, a + w);
      text += line;
    }
  }
  return text;
}

}  // namespace zrender::test
