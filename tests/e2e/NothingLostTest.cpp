// Nothing lost, nothing overwritten that is not zrender's (docs/design.md, Outputs and Limits):
// planted links, full disks, interrupts, face ids past 32 bits, unbounded reads and messages,
// two outputs at one path, long names. Each case runs the built executable.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/HostileRuns.hpp"
#include "support/TestImages.hpp"
#include "zrender/base/Error.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using namespace test;

// Entries of `folder` that are neither in `keep` nor ".zrender-*" folders... are reported by
// listFolder; these helpers say what a case expects to find.
std::vector<std::string> hiddenEntries(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.path().filename().string().front() == '.') out.push_back(e.path().filename());
  return out;
}

// A model whose pictures do not compress: random colors per face on a 40 x 40 grid.
void writeNoisyModel(const TempDir& dir) {
  dir.write("m.obj", gridModel(40, 40));
}

const std::vector<std::string> kNoisy = {"--shading", "random",   "--width",
                                         "400",       "--height", "400"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// 1. Links planted at the names earlier versions used for their temporary files
// (".out.tmp-PID.png", ".out.probe-PID.png") for the next PIDs, and a link at the target:
// nothing is written through any of them.
TEST(NothingLost, PlantedLinksAreNeverWrittenThrough) {
  TempDir dir;
  writeNoisyModel(dir);
  dir.write("victim", "precious\n");
  int next = 0;
  std::ifstream("/proc/sys/kernel/ns_last_pid") >> next;
  for (int pid = next + 1; pid < next + 300; ++pid) {
    for (const char* tag : {"tmp", "probe"}) {
      fs::create_symlink(dir.file("victim"),
                         dir.file(".out." + std::string(tag) + "-" + std::to_string(pid) + ".png"));
    }
  }
  fs::create_symlink(dir.file("victim"), dir.file("out.png"));
  const Outcome r = runLimited(with({"m.obj", "-o", "out.png"}, kNoisy), dir.path);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readFile(dir.file("victim")), "precious\n");
  EXPECT_FALSE(fs::is_symlink(dir.file("out.png")));  // replaced, not written through
  EXPECT_FALSE(test::imread(dir.file("out.png")).empty());
  for (const std::string& name : hiddenEntries(dir.path))
    EXPECT_TRUE(fs::is_symlink(dir.file(name))) << name;  // only the planted links
}

// 2. Face ids past 32 bits: refused before any work, naming the count and the limit.
TEST(NothingLost, FaceIdsPast32BitsAreRefused) {
  TempDir dir;
  dir.write("m.obj", gridModel(2149, 2));  // 4,296 faces
  for (const std::string alg : {"zbuffer", "octree", "hierarchical"}) {
    SCOPED_TRACE(alg);
    writeScene(dir, R"("grid": {"count": [1000, 1000, 1], "spacing": [3, 3, 3]}, )"
                    R"("shading": "phong", "fit": true)");
    const Outcome r = runLimited({"s", "-a", alg, "-o", "out.png"}, dir.path);
    expectQuickCleanError(r, {"4296 faces x 1000000 instances = 4296000000 faces", "4294967295"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
  }
}

// 3-5, 9. A full disk: the writer's failure is one line naming the file and why, the old file
// stays whole, and nothing else is left. Through a real small file system where this machine
// can make one, and always through a file size limit (writes past it fail with EFBIG).
constexpr size_t kSmallDisk = 64 * 1024;

struct FullDiskCase {
  std::vector<std::string> args;  // written into the folder "small"
  std::string output;             // the file in "small"
  bool othersToo = false;         // also writes larger files outside "small"
};

std::vector<FullDiskCase> fullDiskCases() {
  return {
      {with({"m.obj", "--turntable", "12", "-o", "small/v.mp4"}, kNoisy), "v.mp4"},
      {with({"m.obj", "--turntable", "12", "-o", "small/v.avi"}, kNoisy), "v.avi"},
      {with({"m.obj", "-o", "small/c.bmp"}, kNoisy), "c.bmp"},
      {with({"m.obj", "-o", "small/c.ppm"}, kNoisy), "c.ppm"},
      {with({"m.obj", "-o", "small/c.png"}, kNoisy), "c.png"},
      {with({"m.obj", "-o", "small/c.jpg"}, kNoisy), "c.jpg"},
      {with({"m.obj", "-o", "c.png", "--depth", "small/d.tif"}, kNoisy), "d.tif", true},
      {with({"m.obj", "-o", "c.png", "--depth", "small/d.exr"}, kNoisy), "d.exr", true},
      {with({"m.obj", "-o", "c.png", "--ids", "small/i.png"}, kNoisy), "i.png", true},
      {with({"m.obj", "--turntable", "4", "-o", "f%d.png", "--contact-sheet", "small/s.png"},
            kNoisy),
       "s.png", true},
      {{"bench", "s", "--repeat", "1", "--markdown", "small/t.md"}, "t.md"},
      {{"bench", "s", "--repeat", "1", "--json", "small/t.json"}, "t.json"},
  };
}

// The disk holds the old file and a filler, and has no room left for more.
void fillDisk(const TempDir& dir, const std::string& output) {
  fs::remove_all(dir.file("small"));
  fs::create_directories(dir.file("small"));
  dir.write("small/" + output, "the old file\n");
  dir.write("small/filler", std::string(kSmallDisk - 4096, 'f'));
}

void expectOldFileKept(const Outcome& r, const TempDir& dir, const std::string& output,
                       const std::vector<std::string>& keep, const std::string& reason) {
  expectQuickCleanError(r, {"small/" + output, "cannot write file", reason}, 30);
  EXPECT_EQ(readFile(dir.file("small/" + output)), "the old file\n");
  std::vector<std::string> sorted = keep;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(listFolder(dir.file("small")), sorted);
  EXPECT_TRUE(hiddenEntries(dir.file("small")).empty());
}

bool isVideo(const std::string& output) {
  return output.rfind("v.", 0) == 0;
}

TEST(NothingLost, AFullDiskKeepsTheOldFile) {
  TempDir dir;
  writeNoisyModel(dir);
  writeScene(dir, R"("fit": true)", "m.obj");
  for (const FullDiskCase& c : fullDiskCases()) {
    SCOPED_TRACE(c.output);
    fillDisk(dir, c.output);
    std::string why;
    const std::optional<Outcome> r = runOnSmallDisk(c.args, dir, "small", kSmallDisk, why);
    if (!r) GTEST_SKIP() << why;
    // A video writer says no reason: the container is found unfinished and the disk full.
    expectOldFileKept(*r, dir, c.output, {"filler", c.output},
                      isVideo(c.output) ? "(no space left on device)" : "No space left on device");
  }
}

TEST(NothingLost, AWriteCutShortKeepsTheOldFile) {
  TempDir dir;
  writeNoisyModel(dir);
  writeScene(dir, R"("fit": true)", "m.obj");
  for (const FullDiskCase& c : fullDiskCases()) {
    if (c.othersToo) continue;  // the limit is on every file: those others would fail first
    SCOPED_TRACE(c.output);
    fs::remove_all(dir.file("small"));
    fs::create_directories(dir.file("small"));
    dir.write("small/" + c.output, "the old file\n");
    // Above every input and the old file; below every output (a bench table is about 1 KB).
    const Outcome r = runLimited(c.args, dir.path, 60, c.args[0] == "bench" ? 200 : 8192);
    expectOldFileKept(r, dir, c.output, {c.output},
                      isVideo(c.output) ? "the video" : "File too large");
  }
}

// 6. A model that is a device, or larger than the limit: refused at once.
TEST(NothingLost, ModelReadsAreBounded) {
  TempDir dir;
  dir.write(
      "settings.json",
      R"({"z": {"path": "/dev/zero", "fit": true}, "big": {"path": "big.obj", "fit": true}})");
  expectQuickCleanError(runLimited({"z"}, dir.path), {"/dev/zero", "device"});
  { std::ofstream big(dir.file("big.obj")); }
  fs::resize_file(dir.file("big.obj"), (uintmax_t(2) << 30) + 1);  // sparse: no disk used
  expectQuickCleanError(runLimited({"big"}, dir.path), {"big.obj", "too large", "2048 MiB"});
}

// A PNG of 1 x 1 pixel whose header says width x height.
std::string pngClaiming(uint32_t width, uint32_t height) {
  std::vector<uchar> bytes;
  test::imencode(".png", cv::Mat(1, 1, CV_8UC3, cv::Scalar(1, 2, 3)), bytes);
  const auto put = [&](size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = uchar(v >> (24 - 8 * i));
  };
  put(16, width), put(20, height);  // IHDR's data starts at byte 16
  uint32_t crc = 0xFFFFFFFFu;       // over the chunk type and data, bytes 12 to 29
  for (size_t i = 12; i < 29; ++i) {
    crc ^= bytes[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  put(29, ~crc);
  return std::string(bytes.begin(), bytes.end());
}

// A JPEG of 8 x 8 pixels whose frame header says width x height.
std::string jpegClaiming(uint16_t width, uint16_t height) {
  std::vector<uchar> bytes;
  test::imencode(".jpg", cv::Mat(8, 8, CV_8UC3, cv::Scalar(1, 2, 3)), bytes);
  for (size_t i = 2; i + 9 < bytes.size(); ++i) {
    if (bytes[i] == 0xFF && bytes[i + 1] == 0xC0) {  // SOF0: length, precision, height, width
      bytes[i + 5] = uchar(height >> 8), bytes[i + 6] = uchar(height);
      bytes[i + 7] = uchar(width >> 8), bytes[i + 8] = uchar(width);
      break;
    }
  }
  return std::string(bytes.begin(), bytes.end());
}

// 7. A texture's size is checked before its pixels are allocated: the scene's own texture is
// an error, a material's a warning, and both come at once.
TEST(NothingLost, HugeTexturesAreRefusedBeforeAllocating) {
  TempDir dir;
  dir.write("m.obj",
            "mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
            "usemtl a\nf 1/1 2/2 3/3\n");
  for (const auto& [name, bytes] :
       {std::pair<std::string, std::string>{"big.png", pngClaiming(20000, 10000)},
        {"big.jpg", jpegClaiming(20000, 10000)}}) {
    SCOPED_TRACE(name);
    dir.write(name, bytes);
    writeScene(dir, R"("fit": true, "shading": "texture", "texture": ")" + name + "\"");
    expectQuickCleanError(runLimited({"s", "-o", "out.png"}, dir.path), {name, "too large"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));

    dir.write("m.mtl", "newmtl a\nmap_Kd " + name + "\n");
    writeScene(dir, R"("fit": true, "shading": "texture")");
    const Outcome r = runLimited({"s", "-o", "out.png"}, dir.path);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.rfind("zrender: warning: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(name + ": texture is too large"), std::string::npos) << r.err;
    EXPECT_LT(r.seconds, kQuickSeconds * kSlowdown);
    fs::remove(dir.file("out.png"));
  }
}

// 8. Interrupted runs remove what they were writing: frames already done stay whole.
TEST(NothingLost, InterruptedRunsLeaveNoPartialFiles) {
  TempDir dir;
  writeNoisyModel(dir);
  const std::vector<std::pair<int, std::string>> cases = {{SIGINT, "f%03d.png"},
                                                          {SIGTERM, "f%03d.png"},
                                                          {SIGINT, "v.mp4"},
                                                          {SIGTERM, "v.avi"},
                                                          {SIGHUP, "f%03d.png"}};
  int round = 0;
  for (const auto& [signal, output] : cases) {
    for (double after : {0.15, 0.3, 0.45, 0.6}) {
      SCOPED_TRACE(output + " after " + std::to_string(after) + " s, signal " +
                   std::to_string(signal));
      const std::string folder = "run" + std::to_string(round++);
      RunLimits limits;
      limits.signal = signal;
      limits.signalAfterSeconds = after * kSlowdown;
      limits.alarmSeconds = unsigned(60 * kSlowdown);
      const Outcome r = runZrender(
          with({"m.obj", "--turntable", "2000", "-o", folder + "/" + output, "--threads", "2"},
               kNoisy),
          dir.path, limits);
      EXPECT_EQ(r.status, 128 + signal) << r.err;
      if (!fs::exists(dir.file(folder))) continue;  // stopped before the first output
      EXPECT_TRUE(hiddenEntries(dir.file(folder)).empty());
      for (const std::string& name : listFolder(dir.file(folder))) {
        EXPECT_EQ(name.rfind("f", 0), 0u) << name;  // no video: it was not finished
        EXPECT_FALSE(test::imread(dir.file(folder + "/" + name)).empty()) << name;
      }
    }
  }
}

// 11. Messages stay one bounded line, whatever the length of a path or a list.
TEST(NothingLost, MessagesAreBounded) {
  TempDir dir;
  const std::string longPath = std::string(1 << 20, 'p') + ".obj";
  dir.write("settings.json", R"({"s": {"fit": true, "path": ")" + longPath + R"("}})");
  Outcome r = runLimited({"s"}, dir.path);
  expectQuickCleanError(r, {"pppp ... pppp", "pppp.obj: cannot open file"});
  EXPECT_LE(r.err.size(), std::string("zrender: error: \n").size() + kMaxMessageBytes);

  std::string many = "{";
  for (int i = 0; i < 100000; ++i)
    many += (i ? ", " : "") + std::string("\"scene") + std::to_string(i) +
            R"(": {"path": "m.obj", "fit": true})";
  dir.write("settings.json", many + "}");
  r = runLimited({"nothing"}, dir.path);
  expectQuickCleanError(r, {"unknown scene 'nothing'", "and 99980 more"});
  EXPECT_LE(r.err.size(), std::string("zrender: error: \n").size() + kMaxMessageBytes);
}

// 12. Two outputs at one file, however spelled, are refused before any work.
TEST(NothingLost, TwoOutputsAtOneFileAreRefused) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  fs::create_directories(dir.file("sub"));
  const std::vector<std::vector<std::string>> runs = {
      {"m.obj", "-o", "x.png", "--ids", "x.png"},
      {"m.obj", "-o", "x.png", "--depth", "./x.png"},
      {"m.obj", "-o", "sub/x.png", "--ids", "sub/../sub/x.png"},
      {"m.obj", "--turntable", "3", "-o", "f%d.png", "--contact-sheet", "f2.png"},
      {"bench", "--markdown", "t.out", "--json", "./t.out"},
  };
  for (const auto& args : runs) {
    SCOPED_TRACE(args[2] + " " + args[3] + " " + args[4]);
    expectQuickCleanError(runLimited(args, dir.path), {"command line:", "both name"});
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{"m.obj", "sub"}));
  }
}

// 13. An output name as long as the file system allows.
TEST(NothingLost, OutputNamesUpToTheSystemLimitWork) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  const std::string name = std::string(size_t(NAME_MAX) - 4, 'n') + ".png";
  const std::string ids = std::string(size_t(NAME_MAX) - 4, 'i') + ".png";
  const Outcome r =
      runLimited({"m.obj", "-o", name, "--ids", ids, "--width", "8", "--height", "8"}, dir.path);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{ids, "m.obj", name}));
}

}  // namespace
}  // namespace zrender
