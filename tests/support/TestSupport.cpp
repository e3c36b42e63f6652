#include "support/TestSupport.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "zrender/io/obj/ObjLoader.hpp"

namespace zrender::test {

std::shared_ptr<const Mesh> makeMesh(const std::vector<Vec3>& positions,
                                     const std::vector<std::vector<int>>& faces) {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = positions;
  mesh->faceStart.push_back(0);
  for (const auto& f : faces) {
    for (int i : f) mesh->corners.push_back(Corner{i, -1, -1});
    mesh->faceStart.push_back(uint32_t(mesh->corners.size()));
    mesh->faceMaterial.push_back(-1);
  }
  return mesh;
}

SceneSettings tinySettings(int size) {
  SceneSettings s;
  s.name = "tiny";
  s.width = s.height = size;
  s.eye = Vec3(0, 0, 2);
  s.target = Vec3(0, 0, 0);
  s.fovy = 90.0;
  s.near = 0.1;
  s.far = 10.0;
  return s;
}

Rendered render(const Scene& scene, const std::string& algorithm) {
  Renderer renderer(scene, algorithm);
  const Camera camera = makeCamera(scene);
  renderer.renderFrame(camera);
  return Rendered{renderer.buffer(), renderer.color().clone(), renderer.stats()};
}

Rendered render(std::shared_ptr<const Mesh> mesh, const SceneSettings& settings,
                const std::string& algorithm) {
  Warnings warnings;
  const Scene scene = makeScene(settings, std::move(mesh));
  return render(scene, algorithm);
}

std::shared_ptr<const Mesh> randomSoup(unsigned seed, int count, bool coplanarDuplicates) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  for (int t = 0; t < count; ++t) {
    if (coplanarDuplicates && t % 7 == 6) {
      faces.push_back(faces.back());
      continue;
    }
    const int base = int(positions.size());
    for (int i = 0; i < 3; ++i) positions.emplace_back(coord(rng), coord(rng), coord(rng));
    faces.push_back({base, base + 1, base + 2});
  }
  return makeMesh(positions, faces);
}

std::shared_ptr<const Mesh> referenceModel(const std::string& name) {
  const SceneSettings s = projectScene(name);
  if (!std::filesystem::exists(s.modelPath)) return nullptr;
  Warnings warnings;
  return std::make_shared<const Mesh>(loadObj(s.modelPath, warnings));
}

SceneSettings projectScene(const std::string& name) {
  Warnings warnings;
  const SettingsFile file = loadSettings(ZRENDER_SOURCE_DIR "/settings.json", warnings);
  return file.scenes.at(name);
}

std::string beyondSummary(const std::string& err) {
  const std::string summary = "zrender: wrote ";
  const size_t last = err.empty() ? std::string::npos : err.rfind('\n', err.size() - 2);
  const size_t start = last == std::string::npos ? 0 : last + 1;
  if (err.compare(start, summary.size(), summary) != 0 || err.back() != '\n') return err;
  return err.substr(0, start);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

RunResult runProgram(const std::vector<std::string>& args, const std::string& dir,
                     const RunLimits& limits, const Environment& environment) {
  TempDir capture;
  const std::string outPath = capture.file("stdout"), errPath = capture.file("stderr");
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.empty() ? ZRENDER_SOURCE_DIR : dir.c_str()) != 0) _exit(127);
    if (!freopen(outPath.c_str(), "w", stdout) || !freopen(errPath.c_str(), "w", stderr))
      _exit(127);
    if (limits.fileSizeLimit) {
      signal(SIGXFSZ, SIG_IGN);  // so that write() fails with EFBIG instead of killing
      const rlimit limit{limits.fileSizeLimit, limits.fileSizeLimit};
      if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(127);
    }
    if (limits.alarmSeconds) alarm(limits.alarmSeconds);  // survives exec
    for (const auto& [name, value] : environment) {
      if (value) {
        setenv(name.c_str(), value->c_str(), 1);
      } else {
        unsetenv(name.c_str());
      }
    }
    std::vector<char*> argv;
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (limits.signal) {
    const auto due = start + std::chrono::duration<double>(limits.signalAfterSeconds);
    bool ended = false;
    while (!ended && std::chrono::steady_clock::now() < due) {
      ended = waitpid(pid, &status, WNOHANG) == pid;
      if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (!ended) kill(pid, limits.signal);
    if (!ended) waitpid(pid, &status, 0);
  } else {
    waitpid(pid, &status, 0);
  }
  RunResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

RunResult runZrender(const std::vector<std::string>& args, const std::string& dir,
                     const RunLimits& limits, const Environment& environment) {
  std::vector<std::string> argv = {ZRENDER_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return runProgram(argv, dir, limits, environment);
}

TempDir::TempDir() {
  // mkdtemp makes a folder no one else has: a name built from the process id could meet a
  // folder left by an earlier process with that id, files and all.
  std::string name = (std::filesystem::temp_directory_path() / "zrender-test-XXXXXX").string();
  if (mkdtemp(name.data()) == nullptr) {
    throw std::runtime_error("cannot make a folder from " + name + ": " + std::strerror(errno));
  }
  path = name;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
}

std::string TempDir::write(const std::string& name, const std::string& text) const {
  const std::string p = file(name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

void expectSameFrame(const Rendered& ref, const Rendered& r, const std::string& label) {
  EXPECT_EQ(countDifferences(ref.buffer, r.buffer), 0u) << label << ": keys";
  EXPECT_EQ(ref.color.size(), r.color.size()) << label;
  EXPECT_EQ(ref.color.type(), r.color.type()) << label;
  if (ref.color.size() == r.color.size() && ref.color.type() == r.color.type()) {
    cv::Mat diff;
    cv::absdiff(ref.color, r.color, diff);
    EXPECT_EQ(cv::countNonZero(diff.reshape(1)), 0) << label << ": color";
  }
}

size_t coveredSamples(const FrameBuffer& fb) {
  size_t n = 0;
  for (size_t i = 0; i < fb.size(); ++i) n += fb.data()[i] != kClearKey;
  return n;
}

size_t countDifferences(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a.data()[i] != b.data()[i];
  return n;
}

}  // namespace zrender::test
