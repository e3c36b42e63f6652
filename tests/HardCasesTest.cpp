// Hostile input end to end (issue 6, SPEC §8): each case runs the built executable in a temp
// folder and must either exit 0 with a sensible picture or exit 2 with exactly one stderr line
// "zrender: error: ..." naming the file and line or key; never crash, hang or take more than a
// few seconds. Cases that render loop over algorithmNames(), so new algorithms are covered as
// they are registered. The FuzzRegression and FuzzCorpus tests replay what the fuzz targets
// found (fuzz/corpus/*), in process.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "../fuzz/RenderCase.hpp"
#include "TestSupport.hpp"
#include "zrender/io/ObjLoader.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::RunResult;
using test::TempDir;

// Sanitizer builds run the executable several times slower; the time limits scale with them.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 6.0;
#else
constexpr double kSlowdown = 1.0;
#endif
// What "a few seconds" means for one run of a small case.
constexpr double kQuickSeconds = 5.0;

using Outcome = RunResult;

// test::runZrender with an alarm that kills a hanging run, scaled for sanitizer builds, and
// optionally a file size limit so that writing the output fails part way.
Outcome run(const std::vector<std::string>& args, const std::string& dir,
            double timeoutSeconds = 60, unsigned long fileSizeLimit = 0) {
  test::RunLimits limits;
  limits.alarmSeconds = unsigned(timeoutSeconds * kSlowdown) + 1;
  limits.fileSizeLimit = fileSizeLimit;
  return test::runZrender(args, dir, limits);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Exit 2, one stderr line starting "zrender: error: " that contains every piece of `mustName`,
// in a few seconds.
void expectCleanError(const Outcome& r, const std::vector<std::string>& mustName,
                      double seconds = kQuickSeconds) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("zrender: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n');
  for (const auto& piece : mustName) EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, seconds * kSlowdown);
}

// Exit 0 (warnings allowed) and a PNG of the given size; returns it (BGR).
cv::Mat expectPicture(const Outcome& r, const std::string& path, int width, int height,
                      double seconds = kQuickSeconds) {
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_LT(r.seconds, seconds * kSlowdown);
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
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

// Files in a folder, sorted.
std::vector<std::string> listFolder(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A unit square facing +z (counter-clockwise seen from +z), as two triangles.
const char* kSquare = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
constexpr int kSize = 32;

// Renders `model` (written to the temp folder as m.obj, a model file as SCENE: defaults and
// fit) with one algorithm at kSize x kSize into out.png.
Outcome renderModel(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"m.obj",   "-a", algorithm,  "-o", "out.png",
                                   "--width", "32", "--height", "32"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run(args, dir.path);
}

// A settings.json with one scene "s": `model`, 32 x 32, and the JSON members in `keys`.
void writeScene(const TempDir& dir, const std::string& keys, const std::string& model = "m.obj") {
  dir.write("settings.json", R"({"s": {"path": ")" + model + R"(", "width": 32, "height": 32)" +
                                 (keys.empty() ? "" : ", " + keys) + "}}");
}

Outcome renderScene(const TempDir& dir, const std::string& algorithm,
                    const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"s", "-a", algorithm, "-o", "out.png"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run(args, dir.path);
}

// ---------------------------------------------------------------------------------------------
// Files

// The same square written in every way an exporter might: each renders the same picture.
TEST(HardFiles, EncodingVariantsRenderTheSamePicture) {
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"crlf", "v -1 -1 0\r\nv 1 -1 0\r\nv 1 1 0\r\nv -1 1 0\r\nf 1 2 3\r\nf 1 3 4\r\n"},
      {"lone cr", "v -1 -1 0\rv 1 -1 0\rv 1 1 0\rv -1 1 0\rf 1 2 3\rf 1 3 4\r"},
      {"tabs", "v\t-1\t-1 0\nv 1\t\t-1 0\t\n\tv 1 1 0\nv -1 1 0\nf\t1 2\t3\nf 1 3 4\n"},
      {"no final newline", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4"},
      {"utf-8 bom", std::string("\xEF\xBB\xBF") + kSquare},
      {"non-utf-8 comments",
       std::string("# caf\xE9 \xFF\xFE\x80\n") + kSquare + "g gr\xFCn\n# \x01\x02\x7F\n"},
      {"blank lines and trailing blanks", std::string("\n\n   \n") + kSquare + "   \n\n"},
  };
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", kSquare);
    const cv::Mat reference =
        expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kSize, kSize);
    ASSERT_GT(coveredPixels(reference), kSize * kSize / 4);  // fit leaves a margin
    for (const auto& [name, text] : variants) {
      SCOPED_TRACE(name);
      dir.write("m.obj", text);
      const Outcome r = renderModel(dir, algorithm);
      EXPECT_EQ(r.err, "");
      EXPECT_TRUE(sameImage(expectPicture(r, dir.file("out.png"), kSize, kSize), reference));
    }
  }
}

TEST(HardFiles, EmptyAndCommentsOnlyAreCleanErrors) {
  TempDir dir;
  dir.write("m.obj", "");
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
  dir.write("m.obj", "# only\n# comments\r\n#\n");
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
  dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");  // vertices but no faces
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

std::string utf16(const std::string& ascii, bool bigEndian) {
  std::string out = bigEndian ? "\xFE\xFF" : "\xFF\xFE";
  for (char c : ascii) {
    if (bigEndian) out += '\0';
    out += c;
    if (!bigEndian) out += '\0';
  }
  return out;
}

TEST(HardFiles, Utf16IsACleanError) {
  TempDir dir;
  dir.write("m.obj", utf16(kSquare, false));
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj:1:", "UTF-16"});
  dir.write("m.obj", utf16(kSquare, true));
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj:1:", "UTF-16"});
  // Without a byte order mark the NUL bytes cut every line: still a clean error.
  dir.write("m.obj", utf16(kSquare, false).substr(2));
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HardFiles, BinaryGarbageIsACleanError) {
  TempDir dir;
  std::mt19937 rng(6);
  for (int trial = 0; trial < 8; ++trial) {
    SCOPED_TRACE(trial);
    std::string bytes(size_t(4096) << trial, '\0');
    for (char& c : bytes) c = char(rng());
    dir.write("m.obj", bytes);
    expectCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
    // After a valid model, garbage lines are statements zrender does not know (ignored, as
    // OBJ readers do) unless one happens to start with v, vt, vn or f: a picture or an error.
    dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + bytes);
    const Outcome r = renderModel(dir, "zbuffer");
    if (r.status == 0) {
      EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kSize, kSize)), 0);
      fs::remove(dir.file("out.png"));
    } else {
      expectCleanError(r, {"m.obj"});
    }
  }
}

TEST(HardFiles, LinesOfSeveralMegabytes) {
  TempDir dir;
  // A 6 MB comment, then a 6 MB group name: read past, the square renders.
  dir.write("m.obj", "# " + std::string(6 << 20, 'x') + "\n" + "g " + std::string(6 << 20, 'y') +
                         "\n" + kSquare);
  const Outcome ok = renderModel(dir, "zbuffer");
  EXPECT_GT(coveredPixels(expectPicture(ok, dir.file("out.png"), kSize, kSize)), 0);
  // A 6 MB number: an error that quotes only the start of it.
  dir.write("m.obj", "v 0 0 " + std::string(6 << 20, '7') + "x\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Outcome bad = renderModel(dir, "zbuffer");
  expectCleanError(bad, {"m.obj:1:"});
  EXPECT_LT(bad.err.size(), 400u);
}

TEST(HardFiles, FacesWithOneOrTwoVerticesAreSkipped) {
  // Faces 0 and 1 are degenerate and keep their ids: the triangle is face 2 (id image: 3).
  const std::string model = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1\nf 1 2\nf 1 2 3\n";
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", model);
    const Outcome r = renderModel(dir, algorithm, {"--ids", "ids.png"});
    expectPicture(r, dir.file("out.png"), kSize, kSize);
    const cv::Mat ids = cv::imread(dir.file("ids.png"), cv::IMREAD_COLOR);
    ASSERT_FALSE(ids.empty());
    EXPECT_EQ(ids.at<cv::Vec3b>(kSize / 2, kSize / 2), cv::Vec3b(0, 0, 3));  // BGR: red = 3
  }
}

TEST(HardFiles, AllFacesDegenerateRenderTheBackground) {
  // Zero area: repeated corners, collinear corners, one or two corners.
  const std::string model =
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\nf 4 4 4\n"
      "f 1 2\nf 3\nf 1 2 3 2\n";
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", model);
    const cv::Mat image = expectPicture(renderModel(dir, algorithm, {"--no-cull"}),
                                        dir.file("out.png"), kSize, kSize);
    EXPECT_EQ(coveredPixels(image), 0);
  }
}

TEST(HardFiles, PolygonOf300000VerticesIsRefusedQuickly) {
  TempDir dir;
  std::string text;
  text.reserve(8 << 20);
  const int n = 300000;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * CV_PI * i / n;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  text += "f";
  for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
  text += "\n";
  dir.write("m.obj", text);
  const Outcome r = renderModel(dir, "zbuffer");
  expectCleanError(r, {"m.obj:300001:", std::to_string(kMaxFaceCorners)}, 3.0);
  // The largest accepted polygon draws (a circle: convex) with every algorithm.
  text.clear();
  const uint32_t m = kMaxFaceCorners;
  for (uint32_t i = 0; i < m; ++i) {
    const double a = 2.0 * CV_PI * i / m;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  text += "f";
  for (uint32_t i = 1; i <= m; ++i) text += " " + std::to_string(i);
  dir.write("m.obj", text + "\n");
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    const Outcome ok = renderModel(dir, algorithm);
    EXPECT_GT(coveredPixels(expectPicture(ok, dir.file("out.png"), kSize, kSize)),
              kSize * kSize / 2);
  }
}

struct BadObj {
  const char* name;
  std::string text;
  std::vector<std::string> mustName;
};

TEST(HardFiles, MalformedModelsNameTheFileAndLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<BadObj> cases = {
      {"index 0", tri + "f 1 2 0\n", {"m.obj:4:", "index 0"}},
      {"index past the end", tri + "f 1 2 4\n", {"m.obj:4:", "vertex index 4 out of range"}},
      {"huge index", tri + "f 1 2 99999999999999999999\n", {"m.obj:4:", "out of range"}},
      {"negative before the start", tri + "f -1 -2 -4\n", {"m.obj:4:", "-4 out of range"}},
      {"negative index refers back from its line",
       "v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n",
       {"m.obj:2:", "out of range"}},
      {"letters in a vertex", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n", {"m.obj:2:", "abc"}},
      {"letters in a face", tri + "f 1 x 3\n", {"m.obj:4:", "'x'"}},
      {"dangling slash", tri + "f 1/ 2/ 3/\n", {"m.obj:4:"}},
      {"too few coordinates", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", {"m.obj:1:"}},
      {"NaN", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", {"m.obj:2:", "NaN or infinite"}},
      {"infinity", tri + "v inf 0 0\nf 1 2 4\n", {"m.obj:4:", "NaN or infinite"}},
      {"overflow to infinity", "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n", {"m.obj:2:"}},
      {"texture coordinate out of range",
       tri + "vt 0 0\nf 1/1 2/2 3/1\n",
       {"m.obj:5:", "texture coordinate index 2 out of range"}},
      {"normal out of range",
       tri + "vn 0 0 1\nf 1//1 2//1 3//-2\n",
       {"m.obj:5:", "normal index -2 out of range"}},
      {"bare f", tri + "f\n", {"m.obj:4:"}},
  };
  TempDir dir;
  for (const BadObj& c : cases) {
    SCOPED_TRACE(c.name);
    dir.write("m.obj", c.text);
    expectCleanError(renderModel(dir, "zbuffer"), c.mustName);
  }
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HardFiles, HugeCoordinatesRenderOrFailCleanly) {
  // 1e30 is finite in double: fit frames it and every algorithm draws the same picture.
  for (const std::string scale : {"1e30", "1e150"}) {
    SCOPED_TRACE(scale);
    TempDir dir;
    dir.write("m.obj", "v -" + scale + " -" + scale + " 0\nv " + scale + " -" + scale + " 0\nv 0 " +
                           scale + " 0\nf 1 2 3\n");
    cv::Mat reference;
    for (const std::string& algorithm : algorithmNames()) {
      SCOPED_TRACE(algorithm);
      const cv::Mat image =
          expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kSize, kSize);
      EXPECT_GT(coveredPixels(image), kSize * kSize / 8);
      if (reference.empty()) reference = image;
      EXPECT_TRUE(sameImage(image, reference));
    }
  }
  // 1e300 overflows the bounding sphere and the projection: a clean error, not an empty image.
  TempDir dir;
  dir.write("m.obj", "v -1e300 -1e300 0\nv 1e300 -1e300 0\nv 0 1e300 0\nf 1 2 3\n");
  expectCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
  // Mixed scales: the small triangle is lost in the big one's frame, but nothing breaks.
  dir.write("m.obj",
            "v -1e30 -1e30 0\nv 1e30 -1e30 0\nv 0 1e30 0\nv 0 0 1\nv 1e-30 0 1\n"
            "v 0 1e-30 1\nf 1 2 3\nf 4 5 6\n");
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kSize, kSize);
  }
}

TEST(HardFiles, MissingMaterialFileOrTextureIsAWarning) {
  TempDir dir;
  // A missing .mtl: warning, exit 0, the model still renders.
  dir.write("m.obj", std::string("mtllib nope.mtl\nusemtl red\n") + kSquare);
  Outcome r = renderModel(dir, "zbuffer");
  EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kSize, kSize)), 0);
  EXPECT_NE(r.err.find("zrender: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nope.mtl"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;

  // A material whose map_Kd is missing: warning, exit 0, even with texture shading.
  dir.write("m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd missing.png\n");
  dir.write("m.obj", std::string("mtllib m.mtl\nvt 0 0\nvt 1 0\nvt 1 1\nusemtl red\n") +
                         "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
  r = renderModel(dir, "zbuffer", {"--shading", "texture"});
  EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kSize, kSize)), 0);
  EXPECT_EQ(r.err.rfind("zrender: warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(HardFiles, MissingTextureOfTheSettingsIsAnError) {
  // The scene's own "texture" key is a value the user chose (SPEC §3, §8): a file that is
  // not there, or a folder, is an error naming it and the key, and nothing is written. Only
  // zrender's line: none from OpenCV, which would print one for a file it cannot open.
  TempDir dir;
  dir.write("m.obj", "vt 0 0\nvt 1 0\nvt 1 1\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
  std::filesystem::create_directories(dir.file("folder.png"));
  for (const std::string name : {"nope.png", "folder.png"}) {
    SCOPED_TRACE(name);
    writeScene(dir, R"("eye": [0, 0, 3], "shading": "texture", "texture": ")" + name + "\"");
    expectCleanError(renderScene(dir, "zbuffer"),
                     {name + ": texture cannot be opened", "key 'texture' of scene 's'"});
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
  }
}

// A PNG signature and header claiming `width` x `height`, then nothing: a truncated image.
std::string truncatedPng(uint32_t width, uint32_t height) {
  std::string s = "\x89PNG\r\n\x1a\n";
  s += std::string("\0\0\0\x0dIHDR", 8);
  for (uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xFF);
  s += std::string("\x08\x02\0\0\0", 5);  // 8-bit RGB
  s += std::string("\0\0\0\0", 4);        // CRC (wrong on purpose)
  return s;
}

TEST(HardFiles, MaterialTextureThatIsNotAnImageIsAWarning) {
  const std::vector<std::pair<std::string, std::string>> textures = {
      {"text", "this is not an image\n"},
      {"empty", ""},
      {"truncated png", truncatedPng(64, 64)},
      {"png claiming 1000000 x 1000000 pixels", truncatedPng(1000000, 1000000)},
  };
  for (const auto& [name, bytes] : textures) {
    SCOPED_TRACE(name);
    TempDir dir;
    dir.write("tex.png", bytes);
    dir.write("m.mtl", "newmtl t\nmap_Kd tex.png\n");
    dir.write("m.obj",
              "mtllib m.mtl\nusemtl t\nvt 0 0\nvt 1 0\nvt 1 1\n"
              "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
    const Outcome r = renderModel(dir, "zbuffer", {"--shading", "texture"});
    EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kSize, kSize)), 0);
    EXPECT_NE(r.err.find("zrender: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("tex.png"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    // The same file named by the settings' "texture" key, a value the user chose: an error.
    writeScene(dir, R"("eye": [0, 0, 3], "texture": "tex.png", "shading": "texture")");
    std::filesystem::remove(dir.file("out.png"));
    expectCleanError(renderScene(dir, "zbuffer"),
                     {"tex.png: texture cannot be read as an image", "key 'texture' of scene 's'"});
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
  }
}

// A grid of w x h quads split in two triangles: 2 (w - 1) (h - 1) faces.
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

// 2 million faces (a 1001 x 1001 vertex grid, 50 MB of text) with zbuffer: about 1.5 s in
// Release, most of it parsing the text. Every algorithm on it would add 5 runs of that (and
// ten times as much under ASan), so the agreement check runs on 200,000 faces.
TEST(HardFiles, TwoMillionFaces) {
  TempDir dir;
  dir.write("m.obj", gridModel(1001, 1001));  // 2 * 1000 * 1000 faces
  const Outcome big =
      run({"m.obj", "-o", "out.png", "--width", "256", "--height", "256", "--json"}, dir.path, 60);
  const cv::Mat image = expectPicture(big, dir.file("out.png"), 256, 256, 20.0);
  EXPECT_GT(coveredPixels(image), 256 * 16);
  EXPECT_NE(big.out.find("\"faces\":2000000"), std::string::npos) << big.out;

  dir.write("m.obj", gridModel(317, 317));  // 200,000 faces
  cv::Mat reference;
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    const Outcome r =
        run({"m.obj", "-a", algorithm, "-o", "out.png", "--width", "128", "--height", "128"},
            dir.path, 60);
    const cv::Mat small = expectPicture(r, dir.file("out.png"), 128, 128, 10.0);
    if (reference.empty()) reference = small;
    EXPECT_TRUE(sameImage(small, reference));
  }
}

// ---------------------------------------------------------------------------------------------
// Cameras and scenes

TEST(HardCameras, ImpossibleCamerasNameTheKey) {
  TempDir dir;
  dir.write("m.obj", kSquare);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {R"("eye": [0, 0, 2], "target": [0, 0, 2])", {"'s'", "key 'eye'", "target"}},
      {R"("eye": [0, 0, 2], "up": [0, 0, -3])", {"'s'", "key 'up'", "parallel"}},
      {R"("eye": [1, 1, 1], "up": [2, 2, 2])", {"'s'", "key 'up'", "parallel"}},
      {R"("fit": true, "up": [0, 0, 1])", {"'s'", "key 'up'", "parallel"}},  // no eye: down -z
      {R"("eye": [0, 0, 2], "project": [0, 1, 0.1, 10])", {"'s'", "key 'project'", "fovy"}},
      {R"("eye": [0, 0, 2], "project": [180, 1, 0.1, 10])", {"'s'", "key 'project'", "180"}},
      {R"("eye": [0, 0, 2], "project": [270, 1, 0.1, 10])", {"'s'", "key 'project'", "270"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, 1, 1])", {"'s'", "key 'project'", "far"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, -2, 2])", {"'s'", "key 'project'", "far"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, 0, 2])", {"'s'", "key 'project'", "near"}},
      {R"("eye": [0, 0, 2], "msaa": 3)", {"'s'", "key 'msaa'"}},
      // Finite values whose projection overflows (found with the settings fuzz target's
      // camera check): 2 far near > 1e308, 1 / tan of a denormal fovy, f / a denormal aspect.
      {R"("eye": [0, 0, 2], "project": [45, 1, 1, 1e308])", {"'s'", "key 'project'", "overflow"}},
      {R"("eye": [0, 0, 2], "project": [1e-320, 1, 1, 10])", {"'s'", "key 'project'", "overflow"}},
      {R"("eye": [0, 0, 2], "project": [45, 1e-310, 1, 10])", {"'s'", "key 'project'", "overflow"}},
  };
  for (const auto& [keys, mustName] : cases) {
    SCOPED_TRACE(keys);
    writeScene(dir, keys);
    expectCleanError(renderScene(dir, "zbuffer"), mustName);
  }
  // The same on the command line, over a valid scene and over a model file.
  writeScene(dir, R"("eye": [0, 0, 2])");
  const std::vector<std::pair<std::vector<std::string>, std::string>> options = {
      {{"--eye", "0,0,2", "--target", "0,0,2"}, "key 'eye'"},
      {{"--up", "0,0,1"}, "key 'up'"},
      {{"--fov", "0"}, "key 'project'"},
      {{"--fov", "180"}, "key 'project'"},
      {{"--near", "5", "--far", "5"}, "key 'project'"},
      {{"--msaa", "3"}, "key 'msaa'"},
  };
  for (const auto& [extra, key] : options) {
    SCOPED_TRACE(extra[0]);
    expectCleanError(renderScene(dir, "zbuffer", extra), {"'s'", key});
    expectCleanError(renderModel(dir, "zbuffer", extra), {"m.obj", key});
  }
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HardCameras, SizeOutOfRangeNamesTheKey) {
  TempDir dir;
  dir.write("m.obj", kSquare);
  for (const std::string key : {"width", "height"}) {
    for (const std::string value : {"0", "16385", "-1", "1e9"}) {
      SCOPED_TRACE(key + " " + value);
      dir.write("settings.json",
                R"({"s": {"path": "m.obj", "eye": [0, 0, 2], ")" + key + "\": " + value + "}}");
      expectCleanError(renderScene(dir, "zbuffer"), {"settings.json", "'s'", "'" + key + "'"});
      writeScene(dir, R"("eye": [0, 0, 2])");
      const Outcome r = renderScene(dir, "zbuffer", {"--" + key, value});
      expectCleanError(r, {key});
    }
  }
  // The limits themselves are fine: a 1 x 16384 strip.
  writeScene(dir, R"("eye": [0, 0, 2])");
  expectPicture(renderScene(dir, "zbuffer", {"--width", "1", "--height", "16384"}),
                dir.file("out.png"), 1, 16384);
  EXPECT_FALSE(fs::exists(dir.file("sq.png")));
}

TEST(HardCameras, ModelEntirelyBehindTheCameraRendersTheBackground) {
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", kSquare);
    // Looking along +z from z = 2: the square at z = 0 is behind the eye.
    writeScene(dir, R"("eye": [0, 0, 2], "target": [0, 0, 5], "background": [10, 20, 30])");
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{}, {"--no-cull"}, {"--msaa", "4"}}) {
      const cv::Mat image =
          expectPicture(renderScene(dir, algorithm, extra), dir.file("out.png"), kSize, kSize);
      ASSERT_FALSE(image.empty());
      EXPECT_EQ(cv::countNonZero(image.reshape(1) != 0), kSize * kSize * 3);  // no black
      EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
      EXPECT_EQ(image.at<cv::Vec3b>(kSize / 2, kSize / 2), cv::Vec3b(30, 20, 10));
    }
  }
}

// Renders the scene with every algorithm and expects the same, non-empty picture from each.
void expectAgreeingPictures(const TempDir& dir, const std::vector<std::string>& extra,
                            int minCovered) {
  cv::Mat reference;
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    const Outcome r = renderScene(dir, algorithm, extra);
    EXPECT_EQ(r.err, "");
    const cv::Mat image = expectPicture(r, dir.file("out.png"), kSize, kSize);
    if (image.empty()) continue;
    EXPECT_GE(coveredPixels(image), minCovered);
    if (reference.empty()) reference = image;
    EXPECT_TRUE(sameImage(image, reference)) << algorithm << " differs from zbuffer";
  }
}

TEST(HardCameras, TriangleThroughTheEyePlane) {
  TempDir dir;
  // From z = 5 behind the eye (z = 2) to z = -5 in front; the near plane cuts it.
  dir.write("m.obj",
            "v -1 -1 5\nv 1 -1 5\nv 0 1 -5\nf 1 2 3\nf 3 2 1\n"
            "v -3 0 5\nv 3 0 5\nv 0 0.5 -20\nf 4 5 6\n");
  writeScene(dir, R"("eye": [0, 0, 2], "project": [90, 0, 0.1, 10])");
  for (const auto& extra : {std::vector<std::string>{}, {"--no-cull"}, {"--msaa", "4"}}) {
    expectAgreeingPictures(dir, extra, 10);
  }
}

TEST(HardCameras, EyeInsideTheModel) {
  TempDir dir;
  // A cube around the eye, faces outward: from inside every face is a back face.
  dir.write("m.obj",
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
            "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  writeScene(dir,
             R"("eye": [0.1, 0.2, 0.3], "target": [0.5, 0.1, -1], "project": [100, 0, 0.01, 10])");
  expectAgreeingPictures(dir, {"--no-cull"}, kSize * kSize);  // walls everywhere
  expectAgreeingPictures(dir, {"--no-cull", "--msaa", "4"}, kSize * kSize);
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    EXPECT_EQ(coveredPixels(
                  expectPicture(renderScene(dir, algorithm), dir.file("out.png"), kSize, kSize)),
              0);  // culled
  }
}

// ---------------------------------------------------------------------------------------------
// Output files

TEST(HardOutput, ImpossiblePathsLeaveNothingBehind) {
  TempDir dir;
  dir.write("m.obj", kSquare);
  dir.write("file", "a regular file\n");
  fs::create_directory(dir.file("folder.png"));
  const std::vector<std::string> before = listFolder(dir.path);
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"/proc/zrender-nope/x.png", "/proc/zrender-nope/x.png"},
      {"file/x.png", "file/x.png"},                // parent is a regular file
      {"file/deeper/x.png", "file/deeper/x.png"},  // an ancestor is
      {"folder.png", "folder.png"},                // the output is a folder
      {"/proc/self/status.png", "/proc/self/status.png"},
  };
  for (const auto& [output, named] : outputs) {
    SCOPED_TRACE(output);
    const Outcome r = run({"m.obj", "-o", output, "--width", "8", "--height", "8"}, dir.path);
    expectCleanError(r, {named});
    EXPECT_EQ(listFolder(dir.path), before);  // no output, no temporary file
    EXPECT_TRUE(fs::is_directory(dir.file("folder.png")));
    EXPECT_TRUE(fs::is_empty(dir.file("folder.png")));
  }
}

TEST(HardOutput, ExistingOutputIsReplacedOnlyByACompleteFile) {
  TempDir dir;
  dir.write("m.obj", kSquare);
  const std::string old = "the previous picture\n";
  dir.write("out.png", old);
  const std::vector<std::string> before = listFolder(dir.path);
  // Random colors do not compress: a 256 x 256 PNG is far above the 4 KB file size limit, so
  // writing stops part way with EFBIG.
  const std::vector<std::string> args = {"m.obj",  "-o",       "out.png", "--width",
                                         "256",    "--height", "256",     "--shading",
                                         "random", "--msaa",   "4"};
  dir.write("m.obj", gridModel(40, 40));
  const Outcome failed = run(args, dir.path, 60, 4096);
  expectCleanError(failed, {"out.png"});
  EXPECT_EQ(readFile(dir.file("out.png")), old);
  EXPECT_EQ(listFolder(dir.path), before);

  // A failed render (bad model) leaves it alone too.
  dir.write("m.obj", "v 0 0 0\nf 1 2 3\n");
  expectCleanError(run(args, dir.path), {"m.obj"});
  EXPECT_EQ(readFile(dir.file("out.png")), old);

  // A successful one replaces it with a complete picture.
  dir.write("m.obj", gridModel(40, 40));
  const cv::Mat image = expectPicture(run(args, dir.path), dir.file("out.png"), 256, 256);
  EXPECT_GT(coveredPixels(image), 256 * 64);
  EXPECT_EQ(listFolder(dir.path), before);
}

// ---------------------------------------------------------------------------------------------
// What the fuzz targets found, replayed in process.

// Loads `obj`, renders it with every algorithm as the render fuzz target does and expects them
// to agree; returns zbuffer's frame.
test::Rendered expectAgreement(const std::string& obj, const SceneSettings& settings) {
  Warnings warnings;
  auto mesh = std::make_shared<const Mesh>(loadObjFromText(obj, "case.obj", warnings));
  const Scene scene = makeScene(settings, mesh);
  EXPECT_EQ(fuzz::checkAlgorithmsAgree(scene, true), "");
  return test::render(scene, "zbuffer");
}

bool allBackground(const FrameBuffer& buffer) {
  for (size_t i = 0; i < buffer.size(); ++i) {
    if (keyFaceId(buffer.data()[i]) != kBackgroundId) return false;
  }
  return true;
}

// fuzz/corpus/render/regression-self-crossing-polygon.bin: a non-planar hexagon that projects
// to a self-crossing polygon. zbuffer drew an ear-clipping triangulation of it, scanline its
// even-odd interior. Polygons whose boundary crosses itself are now skipped by every algorithm.
TEST(FuzzRegression, SelfCrossingPolygonIsSkippedByEveryAlgorithm) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // A bowtie (crosses in the middle) and a pentagram (winds twice, every turn the same way).
  std::string obj = "v -1 -1 0\nv 1 1 0\nv 1 -1 0\nv -1 1 0\nf 1 2 3 4\n";
  for (int i = 0; i < 5; ++i) {
    const double a = CV_PI / 2 + i * 4 * CV_PI / 5;
    obj += "v " + std::to_string(1.5 * std::cos(a)) + " " + std::to_string(1.5 * std::sin(a)) +
           " -0.5\n";
  }
  obj += "f 5 6 7 8 9\n";
  const test::Rendered r = expectAgreement(obj, s);
  EXPECT_EQ(r.stats.trianglesDegenerate, 2u + 3u);  // counted in triangles
  EXPECT_TRUE(allBackground(r.buffer));
}

// Found with the fix above: a spike (the boundary running out and straight back) has no area
// and the even-odd rule ignores it, but an ear beside it covered the area next to it. Spikes
// are now removed before ear clipping: the face covers exactly the square without the spike.
TEST(FuzzRegression, SpikesAddNothingToAPolygon) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  const std::string square =
      "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0 0.5\nv 1.8 0 0.5\n"
      "v 0.5 0.5 0.5\nv -0.5 0.5 0.5\nv 1.8 1.5 0.5\nv -1.5 0.2 0.5\n";
  const test::Rendered plain = expectAgreement(square + "f 1 2 3 5 6\n", s);
  // Out of the right side and back; diagonally out of a corner; two spikes, one on the seam.
  for (const std::string face :
       {"f 1 2 3 4 3 5 6\n", "f 1 2 3 5 7 5 6\n", "f 8 6 1 2 3 4 3 5 6\n"}) {
    SCOPED_TRACE(face);
    const test::Rendered spiky = expectAgreement(square + face, s);
    EXPECT_EQ(test::countDifferences(spiky.buffer, plain.buffer), 0u);
  }
}

// fuzz/corpus/render/regression-repeated-corner-crossing.bin and ...-touching.bin: a face
// naming one vertex twice, where the boundary crosses itself through that corner, or only
// touches itself there (two lobes). Ears were found in both, and they covered what the even-
// odd rule leaves empty (between the lobes, for the second). Such faces are now skipped.
TEST(FuzzRegression, PolygonThroughARepeatedCornerIsSkipped) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // Vertex 2 (0, 0) is visited twice. Face 0 crosses there from the lower-left to the upper-
  // right lobe (lobes of unequal area, so the total area is not zero); face 1 only touches.
  const std::string points =
      "v -1 -1 0\nv 0 0 0\nv 1.5 1.5 0\nv 1.5 -1.5 0\nv -1 1 0\nv 1 -1 0\nv 1 1 0\n";
  for (const std::string face : {"f 1 2 3 4 2 5\n", "f 1 2 6 7 2 5\n"}) {
    SCOPED_TRACE(face);
    const test::Rendered r = expectAgreement(points + face, s);
    EXPECT_EQ(r.stats.trianglesDegenerate, 4u);
    EXPECT_TRUE(allBackground(r.buffer));
  }
}

// fuzz/corpus/render/regression-overlapping-edges.bin: a polygon two of whose edges overlap
// along a line (the boundary touches itself without crossing). Ear clipping covered part of
// what the even-odd rule leaves empty. A concave face whose part before the near plane is in
// two pieces gets such edges from clipping, which joins the pieces along the cut: all these
// are skipped by every algorithm (concave faces are rare, and all algorithms must agree).
TEST(FuzzRegression, PolygonWhoseEdgesOverlapIsSkipped) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  // A U in the floor plane y = -0.5, its base nearer than the near plane.
  SceneSettings cut = s;
  cut.eye = Vec3(0, 0, 0);
  cut.target = Vec3(0, -0.3, -1);
  cut.near = 0.5;
  const std::string u =
      "v -2 -0.5 -0.2\nv 2 -0.5 -0.2\nv 2 -0.5 -5\nv 1 -0.5 -5\nv 1 -0.5 -0.3\n"
      "v -1 -0.5 -0.3\nv -1 -0.5 -5\nv -2 -0.5 -5\nf 1 2 3 4 5 6 7 8\n";
  for (const int msaa : {1, 4}) {
    cut.msaa = msaa;
    const test::Rendered r = expectAgreement(u, cut);
    EXPECT_EQ(r.stats.trianglesDegenerate, 6u);
    EXPECT_TRUE(allBackground(r.buffer));
  }
  // In the image plane: the edge from (1, 1) to (-1, -1) runs back over the one from
  // (-0.5, -0.5) to (0.5, 0.5); and a corner, (0, 1), lying on the top edge of its own face.
  const std::string overlap =
      "v 1 1 0\nv -1 -1 0\nv -1.5 0 0\nv -0.5 -0.5 0\nv 0.5 0.5 0\nv 1.5 0 0\n"
      "v -1 1 0.5\nv 1 1 0.5\nv 1 -1 0.5\nv 0 1 0.5\nv -1 -1 0.5\n"
      "f 1 2 3 4 5 6\nf 7 8 9 10 11\n";
  const test::Rendered r = expectAgreement(overlap, s);
  EXPECT_EQ(r.stats.trianglesDegenerate, 4u + 3u);
  EXPECT_TRUE(allBackground(r.buffer));
}

// fuzz/corpus/render/regression-concave-near-clip-overflow.bin: a concave face cut by the near
// plane many times. Clipping wrote past buffers sized for a convex polygon (count + 2 corners;
// a concave one reaches 3/2 count per plane): a heap overflow under ASan.
TEST(FuzzRegression, ConcavePolygonCutManyTimesByTheNearPlane) {
  SceneSettings s = test::tinySettings(32);
  s.cull = false;
  s.eye = Vec3(0, 0, 0);
  s.target = Vec3(0, 0, -1);
  s.near = 0.5;
  // A zig-zag in the floor plane y = -0.5: corners alternately before (z = -0.1) and behind
  // (z = -3) the near plane, then the base. Same in a vertical plane, for the guard band.
  std::string obj;
  const int teeth = 40;
  for (int i = 0; i <= 2 * teeth; ++i) {
    obj += "v " + std::to_string(-2.0 + 4.0 * i / (2 * teeth)) + " -0.5 " +
           (i % 2 ? "-0.1" : "-3") + "\n";
  }
  obj += "v 2 -0.5 -4\nv -2 -0.5 -4\nf";
  for (int i = 1; i <= 2 * teeth + 3; ++i) obj += " " + std::to_string(i);
  obj += "\n";
  expectAgreement(obj, s);
  s.msaa = 4;
  expectAgreement(obj, s);
  // Far beyond the image sideways (the guard band cuts it many times too).
  std::string wide;
  for (int i = 0; i <= 2 * teeth; ++i) {
    wide += "v " + std::to_string(-1e7 + 2e7 * i / (2 * teeth)) + " " + (i % 2 ? "1e7" : "-0.2") +
            " -1\n";
  }
  wide += "v 1e7 -1e7 -1\nv -1e7 -1e7 -1\nf";
  for (int i = 1; i <= 2 * teeth + 3; ++i) wide += " " + std::to_string(i);
  expectAgreement(wide + "\n", s);
}

// Every input of the render fuzz target's corpus (seeds and the inputs it found): all
// algorithms agree, as the fuzz target checks.
TEST(FuzzCorpus, RenderInputsAgreeAcrossAlgorithms) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(ZRENDER_SOURCE_DIR "/fuzz/corpus/render")) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = readFile(entry.path().string());
    fuzz::RenderCase input;
    ASSERT_TRUE(fuzz::decodeRenderCase(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(),
                                       input));
    Warnings warnings;
    std::shared_ptr<const Mesh> mesh;
    try {
      mesh = std::make_shared<const Mesh>(loadObjFromText(input.obj, "case.obj", warnings));
    } catch (const InputError&) {
      continue;
    }
    const Scene scene = makeScene(input.settings, mesh);
    EXPECT_EQ(fuzz::checkAlgorithmsAgree(scene, input.twice), "");
    ++files;
  }
  EXPECT_GT(files, 5);
}

// Every input of the OBJ fuzz target's corpus loads or fails with a one-line InputError.
TEST(FuzzCorpus, ObjInputsLoadOrFailCleanly) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(ZRENDER_SOURCE_DIR "/fuzz/corpus/obj")) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = readFile(entry.path().string());
    Warnings warnings;
    try {
      const Mesh mesh =
          loadObjFromText(bytes.substr(0, bytes.find("\n#%MTL\n")), "case.obj", warnings);
      EXPECT_GT(mesh.faceCount(), 0u);
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("case.obj:", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    ++files;
  }
  EXPECT_GT(files, 5);
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// fuzz/corpus/settings/regression-denormal-fovy-with-fit.json and regression-tiny-fovy-with-fit
// .json: fovy 1e-320 and 1.4e-186 with fit passed validation (fit replaces near and far), then
// makeCamera failed naming the model instead of the settings key.
TEST(FuzzRegression, TinyFovyWithFitNamesTheProjectKey) {
  for (const char* name :
       {"regression-denormal-fovy-with-fit.json", "regression-tiny-fovy-with-fit.json"}) {
    SCOPED_TRACE(name);
    std::ifstream in(std::string(ZRENDER_SOURCE_DIR "/fuzz/corpus/settings/") + name);
    std::stringstream text;
    text << in.rdbuf();
    Warnings warnings;
    const SettingsFile file = parseSettings(text.str(), "fuzz.json", warnings);
    ASSERT_EQ(file.scenes.size(), 1u);
    try {
      validateScene(file.scenes.begin()->second, "fuzz.json: scene 'far'");
      ADD_FAILURE() << "validateScene accepted the tiny fovy";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("key 'project'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace zrender
