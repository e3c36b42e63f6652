// Hostile model files end to end (docs/design.md, Errors): encodings, garbage, huge lines,
// numbers and polygons, degenerate and malformed faces, two million faces. Cases that render
// loop over algorithmNames(), so new algorithms are covered as they are registered. The helpers
// (support/HostileRuns.hpp) run the built executable in a temp folder.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "support/HostileRuns.hpp"
#include "support/TestImages.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using namespace test;

// The same square written in every way an exporter might: each renders the same picture.
TEST(HostileFiles, EncodingVariantsRenderTheSamePicture) {
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"crlf", "v -1 -1 0\r\nv 1 -1 0\r\nv 1 1 0\r\nv -1 1 0\r\nf 1 2 3\r\nf 1 3 4\r\n"},
      {"lone cr", "v -1 -1 0\rv 1 -1 0\rv 1 1 0\rv -1 1 0\rf 1 2 3\rf 1 3 4\r"},
      {"tabs", "v\t-1\t-1 0\nv 1\t\t-1 0\t\n\tv 1 1 0\nv -1 1 0\nf\t1 2\t3\nf 1 3 4\n"},
      {"no final newline", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4"},
      {"utf-8 bom", std::string("\xEF\xBB\xBF") + kSquareObj},
      {"non-utf-8 comments",
       std::string("# caf\xE9 \xFF\xFE\x80\n") + kSquareObj + "g gr\xFCn\n# \x01\x02\x7F\n"},
      {"blank lines and trailing blanks", std::string("\n\n   \n") + kSquareObj + "   \n\n"},
  };
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", kSquareObj);
    const cv::Mat reference =
        expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kImageSize, kImageSize);
    ASSERT_GT(coveredPixels(reference), kImageSize * kImageSize / 4);  // fit leaves a margin
    for (const auto& [name, text] : variants) {
      SCOPED_TRACE(name);
      dir.write("m.obj", text);
      const Outcome r = renderModel(dir, algorithm);
      EXPECT_EQ(test::beyondSummary(r.err), "");
      EXPECT_TRUE(
          sameImage(expectPicture(r, dir.file("out.png"), kImageSize, kImageSize), reference));
    }
  }
}

TEST(HostileFiles, EmptyAndCommentsOnlyAreCleanErrors) {
  TempDir dir;
  dir.write("m.obj", "");
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
  dir.write("m.obj", "# only\n# comments\r\n#\n");
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
  dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");  // vertices but no faces
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj", "no faces"});
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

TEST(HostileFiles, Utf16IsACleanError) {
  TempDir dir;
  dir.write("m.obj", utf16(kSquareObj, false));
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj:1:", "UTF-16"});
  dir.write("m.obj", utf16(kSquareObj, true));
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj:1:", "UTF-16"});
  // Without a byte order mark the NUL bytes cut every line: still a clean error.
  dir.write("m.obj", utf16(kSquareObj, false).substr(2));
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HostileFiles, BinaryGarbageIsACleanError) {
  TempDir dir;
  std::mt19937 rng(6);
  for (int trial = 0; trial < 8; ++trial) {
    SCOPED_TRACE(trial);
    std::string bytes(size_t(4096) << trial, '\0');
    for (char& c : bytes) c = char(rng());
    dir.write("m.obj", bytes);
    expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
    // After a valid model, garbage lines are statements zrender does not know (ignored, as
    // OBJ readers do) unless one happens to start with v, vt, vn or f: a picture or an error.
    dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + bytes);
    const Outcome r = renderModel(dir, "zbuffer");
    if (r.status == 0) {
      EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kImageSize, kImageSize)), 0);
      fs::remove(dir.file("out.png"));
    } else {
      expectQuickCleanError(r, {"m.obj"});
    }
  }
}

// Runs zrender on `bytes` saved as `name` (a damaged test model of assimp-testmodels): one
// clean line that starts with `name: message`, within `seconds`, and no picture.
void expectRefused(const std::string& name, const std::string& bytes, const std::string& message,
                   double seconds = kQuickSeconds) {
  TempDir dir;
  dir.write(name, bytes);
  const Outcome r = runLimited({name, "-o", "out.png"}, dir.path, 120);
  expectQuickCleanError(r, {name + ": " + message}, seconds);
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

// A 3DS that makes assimp ask for 47 GB (a test model of assimp-testmodels with 18 bytes
// changed, as the fuzzer changed them): the budget zrender gives a model reader refuses it in
// one line, whatever the machine's memory.
TEST(HostileFiles, A3dsAskingForMoreMemoryThanThereIsIsACleanError) {
  if (!kBadAllocThrown) GTEST_SKIP() << "the sanitizers' operator new does not throw bad_alloc";
  const std::string model = "/usr/share/assimp/models/3DS/cube_with_diffuse_texture.3DS";
  std::string bytes = readFile(model);
  if (bytes.size() != 1423) GTEST_SKIP() << model << " not installed (assimp-testmodels)";
  const std::pair<size_t, int> changes[] = {
      {278, 0135},  {1144, 0374}, {1145, 012},  {1356, 0104}, {1357, 0145}, {1358, 0146},
      {1359, 0141}, {1360, 0165}, {1361, 0154}, {1362, 0164}, {1364, 014},  {1368, 01},
      {1369, 0},    {1370, 02},   {1371, 0},    {1372, 03},   {1373, 0},    {1374, 04}};
  for (const auto& [at, value] : changes) bytes[at] = char(value);
  expectRefused("m.3ds", bytes, "cannot read the 3DS file: it asks for more memory");
}

// A Collada file with a letter in one of its indices ("6A1"), on which assimp 5.2 grows an
// array without end (13 GB in a minute, found by fuzzing): the budget zrender gives a model
// reader ends it in seconds, in one line, without a limit from outside.
TEST(HostileFiles, AColladaThatGrowsWithoutEndIsStoppedByTheBudget) {
  if (!kBadAllocThrown) GTEST_SKIP() << "the sanitizers' operator new does not throw bad_alloc";
  const std::string model = "/usr/share/assimp/models/Collada/ConcavePolygon.dae";
  std::string bytes = readFile(model);
  const std::string indices = " 53 59 62 63 61 58 ";
  const size_t at = bytes.find(indices);
  if (at == std::string::npos) GTEST_SKIP() << model << " not installed (assimp-testmodels)";
  bytes.replace(at, indices.size(), " 53 59 62 63 6A1 58 ");
  expectRefused("m.dae", bytes, "cannot read the Collada file: it asks for more memory", 60);
}

// A binary FBX with one length set to 0xFFFFFFFF fails one of assimp's own checks (ai_assert),
// which ends the process in Debian's build of assimp: zrender's plugin turns it into one line.
TEST(HostileFiles, AnFbxFailingAssimpsOwnCheckIsACleanError) {
  const std::string model = "/usr/share/assimp/models/FBX/boxWithCompressedCTypeArray.FBX";
  std::string bytes = readFile(model);
  if (bytes.size() != 13824) GTEST_SKIP() << model << " not installed (assimp-testmodels)";
  bytes.replace(4149, 4, "\xFF\xFF\xFF\xFF");
  expectRefused("m.fbx", bytes,
                "cannot read the FBX file: assimp's own check failed: begin <= cursor");
}

TEST(HostileFiles, LinesOfSeveralMegabytes) {
  TempDir dir;
  // A 6 MB comment, then a 6 MB group name: read past, the square renders.
  dir.write("m.obj", "# " + std::string(6 << 20, 'x') + "\n" + "g " + std::string(6 << 20, 'y') +
                         "\n" + kSquareObj);
  const Outcome ok = renderModel(dir, "zbuffer");
  EXPECT_GT(coveredPixels(expectPicture(ok, dir.file("out.png"), kImageSize, kImageSize)), 0);
  // A 6 MB number: an error that quotes only the start of it.
  dir.write("m.obj", "v 0 0 " + std::string(6 << 20, '7') + "x\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Outcome bad = renderModel(dir, "zbuffer");
  expectQuickCleanError(bad, {"m.obj:1:"});
  EXPECT_LT(bad.err.size(), 400u);
}

TEST(HostileFiles, FacesWithOneOrTwoVerticesAreSkipped) {
  // Faces 0 and 1 are degenerate and keep their ids: the triangle is face 2 (id image: 3).
  const std::string model = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1\nf 1 2\nf 1 2 3\n";
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", model);
    const Outcome r = renderModel(dir, algorithm, {"--ids", "ids.png"});
    expectPicture(r, dir.file("out.png"), kImageSize, kImageSize);
    const cv::Mat ids = test::imread(dir.file("ids.png"), cv::IMREAD_COLOR);
    ASSERT_FALSE(ids.empty());
    EXPECT_EQ(ids.at<cv::Vec3b>(kImageSize / 2, kImageSize / 2),
              cv::Vec3b(0, 0, 3));  // BGR: red = 3
  }
}

TEST(HostileFiles, AllFacesDegenerateRenderTheBackground) {
  // Zero area: repeated corners, collinear corners, one or two corners.
  const std::string model =
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\nf 4 4 4\n"
      "f 1 2\nf 3\nf 1 2 3 2\n";
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", model);
    const cv::Mat image = expectPicture(renderModel(dir, algorithm, {"--no-cull"}),
                                        dir.file("out.png"), kImageSize, kImageSize);
    EXPECT_EQ(coveredPixels(image), 0);
  }
}

TEST(HostileFiles, PolygonOf300000VerticesIsRefusedQuickly) {
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
  expectQuickCleanError(r, {"m.obj:300001:", std::to_string(kMaxFaceCorners)}, 3.0);
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
    EXPECT_GT(coveredPixels(expectPicture(ok, dir.file("out.png"), kImageSize, kImageSize)),
              kImageSize * kImageSize / 2);
  }
}

struct BadObj {
  const char* name;
  std::string text;
  std::vector<std::string> mustName;
};

TEST(HostileFiles, MalformedModelsNameTheFileAndLine) {
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
    expectQuickCleanError(renderModel(dir, "zbuffer"), c.mustName);
  }
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HostileFiles, HugeCoordinatesRenderOrFailCleanly) {
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
          expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kImageSize, kImageSize);
      EXPECT_GT(coveredPixels(image), kImageSize * kImageSize / 8);
      if (reference.empty()) reference = image;
      EXPECT_TRUE(sameImage(image, reference));
    }
  }
  // 1e300 overflows the bounding sphere and the projection: a clean error, not an empty image.
  TempDir dir;
  dir.write("m.obj", "v -1e300 -1e300 0\nv 1e300 -1e300 0\nv 0 1e300 0\nf 1 2 3\n");
  expectQuickCleanError(renderModel(dir, "zbuffer"), {"m.obj"});
  // Mixed scales: the small triangle is lost in the big one's frame, but nothing breaks.
  dir.write("m.obj",
            "v -1e30 -1e30 0\nv 1e30 -1e30 0\nv 0 1e30 0\nv 0 0 1\nv 1e-30 0 1\n"
            "v 0 1e-30 1\nf 1 2 3\nf 4 5 6\n");
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    expectPicture(renderModel(dir, algorithm), dir.file("out.png"), kImageSize, kImageSize);
  }
}

// 2 million faces (a 1001 x 1001 vertex grid, 50 MB of text) with zbuffer: about 1.5 s in
// Release, most of it parsing the text. Every algorithm on it would add 5 runs of that (and
// ten times as much under ASan), so the agreement check runs on 200,000 faces.
TEST(HostileFiles, TwoMillionFaces) {
  TempDir dir;
  dir.write("m.obj", gridModel(1001, 1001));  // 2 * 1000 * 1000 faces
  const Outcome big = runLimited(
      {"m.obj", "-o", "out.png", "--width", "256", "--height", "256", "--json"}, dir.path, 60);
  const cv::Mat image = expectPicture(big, dir.file("out.png"), 256, 256, 20.0);
  EXPECT_GT(coveredPixels(image), 256 * 16);
  EXPECT_NE(big.out.find("\"faces\":2000000"), std::string::npos) << big.out;

  dir.write("m.obj", gridModel(317, 317));  // 200,000 faces
  cv::Mat reference;
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    const Outcome r =
        runLimited({"m.obj", "-a", algorithm, "-o", "out.png", "--width", "128", "--height", "128"},
                   dir.path, 60);
    const cv::Mat small = expectPicture(r, dir.file("out.png"), 128, 128, 10.0);
    if (reference.empty()) reference = small;
    EXPECT_TRUE(sameImage(small, reference));
  }
}

}  // namespace
}  // namespace zrender
