// Reference images (docs/design.md, Reference images): a render compared with --reference,
// --reference-depth and --reference-ids; the exit status, the line on stderr, the diff image
// and its red pixels, the tolerance, the JSON object, and the bad input that writes nothing.
// The changed references are written here, so every expected count and difference is the
// test's own.

#include <gtest/gtest.h>
#include <json/json.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::kSquareObj;
using test::parseJson;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

constexpr int kSize = 32;  // settingsFor's image: 32 x 32
constexpr int kPixels = kSize * kSize;
const cv::Vec3b kRed(0, 0, 255);

// A folder with the square scene `sq` (settingsFor: the square fills the middle half).
struct SquareScene {
  SquareScene() {
    dir.write("sq.obj", kSquareObj);
    dir.write("settings.json", settingsFor("sq.obj"));
  }
  // Runs `zrender sq ARGS` in the folder.
  test::RunResult run(std::vector<std::string> args) const {
    args.insert(args.begin(), "sq");
    return runZrender(args, dir.path);
  }
  // The names in the folder, apart from the scene's own two files.
  std::set<std::string> made() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir.path)) {
      const std::string name = e.path().filename().string();
      if (name != "sq.obj" && name != "settings.json") names.insert(name);
    }
    return names;
  }
  TempDir dir;
};

// The line a reference that differs prints, in the form docs/design.md gives.
std::string differsLine(const std::string& out, const std::string& ref, int pixels,
                        const std::string& largest, const std::string& diff) {
  return "zrender: reference: " + out + " differs from " + ref + " in " + std::to_string(pixels) +
         " of " + std::to_string(kPixels) + " pixels (largest channel difference " + largest +
         "); marked in " + diff + "\n";
}

// Expects `diff` to be a 32 x 32 8-bit BGR image, pure red exactly at (x, y).
void expectRedOnlyAt(const std::string& path, int x, int y) {
  const cv::Mat diff = test::imread(path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(diff.type(), CV_8UC3) << path;
  ASSERT_EQ(diff.size(), cv::Size(kSize, kSize)) << path;
  for (int row = 0; row < kSize; ++row) {
    for (int col = 0; col < kSize; ++col) {
      if (col == x && row == y)
        EXPECT_EQ(diff.at<cv::Vec3b>(row, col), kRed) << path;
      else
        EXPECT_NE(diff.at<cv::Vec3b>(row, col), kRed) << path << " at " << col << ", " << row;
    }
  }
}

TEST(ReferenceImages, TheSameRenderPasses) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "ref.png", "-q"}).status, 0);
  const auto r = s.run({"-o", "out.png", "--reference", "ref.png"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err), "");
  EXPECT_EQ(s.made(), (std::set<std::string>{"ref.png", "out.png"}));  // no diff image
}

TEST(ReferenceImages, OnePixelOffByThreeFailsAndIsMarked) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "ref.png", "-q"}).status, 0);
  cv::Mat ref = test::imread(s.dir.file("ref.png"));
  ASSERT_EQ(ref.size(), cv::Size(kSize, kSize));
  const int x = 16, y = 17;  // inside the square: the diff's context is not black there
  const cv::Vec3b square = ref.at<cv::Vec3b>(y, x);
  ASSERT_NE(square, cv::Vec3b(0, 0, 0));
  ASSERT_LE(square[1], 252);
  ref.at<cv::Vec3b>(y, x)[1] += 3;
  ASSERT_TRUE(test::imwrite(s.dir.file("changed.png"), ref));

  const auto r = s.run({"-o", "out.png", "--reference", "changed.png"});
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err),
            differsLine("out.png", "changed.png", 1, "3", "out-diff.png"));
  expectRedOnlyAt(s.dir.file("out-diff.png"), x, y);
  // Elsewhere the diff shows the render at a quarter of its brightness.
  const cv::Mat diff = test::imread(s.dir.file("out-diff.png"));
  EXPECT_EQ(diff.at<cv::Vec3b>(y, x + 1), cv::Vec3b(square[0] / 4, square[1] / 4, square[2] / 4));
  EXPECT_EQ(diff.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));  // the black background

  // Within the tolerance: success, and the diff image all the same.
  fs::remove(s.dir.file("out-diff.png"));
  const auto within =
      s.run({"-o", "out.png", "--reference", "changed.png", "--reference-tolerance", "1"});
  EXPECT_EQ(within.status, 0) << within.err;
  EXPECT_EQ(test::beyondSummary(within.err),
            differsLine("out.png", "changed.png", 1, "3", "out-diff.png"));
  expectRedOnlyAt(s.dir.file("out-diff.png"), x, y);
  // -q: nothing when within the tolerance, the reference's line alone when not.
  const auto quiet =
      s.run({"-o", "out.png", "--reference", "changed.png", "--reference-tolerance", "1", "-q"});
  EXPECT_EQ(quiet.status, 0);
  EXPECT_EQ(quiet.err, "");
  const auto quietFails = s.run({"-o", "out.png", "--reference", "changed.png", "-q"});
  EXPECT_EQ(quietFails.status, 3);
  EXPECT_EQ(quietFails.err, differsLine("out.png", "changed.png", 1, "3", "out-diff.png"));
}

TEST(ReferenceImages, JsonHoldsTheComparison) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "ref.png", "-q"}).status, 0);
  cv::Mat ref = test::imread(s.dir.file("ref.png"));
  ref.at<cv::Vec3b>(2, 3) = cv::Vec3b(0, 0, 200);  // background (0, 0, 0): 200 off in red
  ref.at<cv::Vec3b>(3, 3) = cv::Vec3b(9, 0, 0);
  ASSERT_TRUE(test::imwrite(s.dir.file("changed.png"), ref));
  const auto r = s.run({"-o", "out.png", "--reference", "changed.png", "--json"});
  EXPECT_EQ(r.status, 3) << r.err;
  const Json::Value j = parseJson(r.out);
  ASSERT_TRUE(j.isMember("reference")) << r.out;
  const Json::Value& color = j["reference"]["color"];
  EXPECT_EQ(color["file"].asString(), "changed.png");
  EXPECT_EQ(color["pixels"].asInt(), kPixels);
  EXPECT_EQ(color["differing_pixels"].asInt(), 2);
  EXPECT_EQ(color["largest_difference"].asDouble(), 200.0);
  EXPECT_EQ(color["diff"].asString(), "out-diff.png");
  EXPECT_EQ(color["tolerance"].asInt(), 0);
  EXPECT_FALSE(color["passed"].asBool());
  EXPECT_EQ(j["files"]["color"].asString(), "out.png");  // the existing fields stay

  ASSERT_EQ(s.run({"-o", "ref.png", "-q"}).status, 0);
  const auto same = s.run({"-o", "out.png", "--reference", "ref.png", "--json"});
  EXPECT_EQ(same.status, 0) << same.err;
  const Json::Value equal = parseJson(same.out)["reference"]["color"];
  EXPECT_EQ(equal["differing_pixels"].asInt(), 0);
  EXPECT_TRUE(equal["diff"].isNull());
  EXPECT_TRUE(equal["passed"].asBool());
}

TEST(ReferenceImages, AnotherSizeFailsWithoutADiff) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "small.png", "--width", "16", "--height", "16", "-q"}).status, 0);
  const auto r = s.run({"-o", "out.png", "--reference", "small.png"});
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err),
            "zrender: reference: out.png (32x32 8-bit, 3 channels) and small.png (16x16 8-bit, 3 "
            "channels) differ in size; not compared\n");
  EXPECT_EQ(s.made(), (std::set<std::string>{"small.png", "out.png"}));
}

TEST(ReferenceImages, AMissingOrUnreadableReferenceWritesNothing) {
  SquareScene s;
  // A PNG's signature, then no header: libpng's failure. The TIFF: OpenCV's (the codec plugin).
  s.dir.write("text.png", std::string("\x89PNG\r\n\x1a\n", 8) + "not an image\n");
  s.dir.write("text.tif", "not an image either\n");
  fs::create_directory(s.dir.file("folder.png"));
  const std::vector<std::string> outputs = {"-o",    "out/c.png", "--depth",
                                            "d.tif", "--ids",     "ids.png"};
  for (const std::vector<std::string>& reference :
       {std::vector<std::string>{"--reference", "missing.png"},
        std::vector<std::string>{"--reference", "text.png"},
        std::vector<std::string>{"--reference", "folder.png"},
        std::vector<std::string>{"--reference-ids", "missing.png"},
        std::vector<std::string>{"--reference-depth", "missing.tif"},
        std::vector<std::string>{"--reference-depth", "text.tif"},
        std::vector<std::string>{"--reference", "text.png", "--reference-depth", "text.tif"}}) {
    SCOPED_TRACE(reference.back());
    std::vector<std::string> args = outputs;
    args.insert(args.end(), reference.begin(), reference.end());
    const auto r = s.run(args);
    expectCleanError(r, {reference[1], reference[0]});
    EXPECT_EQ(s.made(), (std::set<std::string>{"text.png", "text.tif", "folder.png"}));
  }
}

TEST(ReferenceImages, OptionsThatCannotGoTogether) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "ref.png", "--depth", "ref-d.png", "--ids", "ref-ids.png", "-q"}).status,
            0);
  const std::set<std::string> before = s.made();
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> mustName;
  };
  for (const Case& c : std::vector<Case>{
           {{"--orbit", "2", "-o", "{view}.png", "--reference", "ref.png"}, {"--reference"}},
           {{"--orbit", "2", "-o", "{view}.png", "--depth", "d{view}.png", "--reference-depth",
             "ref-d.png"},
            {"--reference-depth"}},
           {{"-o", "out.png", "--reference-depth", "ref-d.png"}, {"--reference-depth", "--depth"}},
           {{"-o", "out.png", "--reference-ids", "ref-ids.png"}, {"--reference-ids", "--ids"}},
           {{"-o", "out.png", "--reference-tolerance", "2"}, {"--reference-tolerance"}},
           {{"-o", "out.png", "--reference", "ref.png", "--reference-tolerance", "-1"},
            {"--reference-tolerance"}},
           {{"-o", "ref.png", "--reference", "ref.png"}, {"-o", "--reference", "ref.png"}},
           {{"-o", "out.png", "--depth", "out.tif", "--reference", "ref.png", "--reference-depth",
             "ref-d.png"},
            {"out-diff.png"}},
       }) {
    SCOPED_TRACE(c.args.back());
    expectCleanError(s.run(c.args), c.mustName);
    EXPECT_EQ(s.made(), before);
  }
}

// A depth image's one value changed by `change`, written as `changedName`.
void writeChangedDepth(const SquareScene& s, const std::string& from,
                       const std::string& changedName, int x, int y, double change) {
  cv::Mat depth = test::imread(s.dir.file(from), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.size(), cv::Size(kSize, kSize)) << from;
  if (depth.type() == CV_32FC1)
    depth.at<float>(y, x) = float(depth.at<float>(y, x) + change);
  else if (depth.type() == CV_16UC1)
    depth.at<uint16_t>(y, x) = uint16_t(depth.at<uint16_t>(y, x) + change);
  else
    FAIL() << from << ": type " << depth.type();
  ASSERT_TRUE(test::imwrite(s.dir.file(changedName), depth));
}

TEST(ReferenceImages, FloatAnd16BitDepthReferences) {  // and OpenEXR
  SquareScene s;
  struct Case {
    std::string extension;  // of the depth images
    double change;          // to one value, in the file's units
    std::string largest;    // as printed
  };
  // 0.25 from a float depth (1, the background, becomes 1.25: both exact); 7 from a 16-bit one
  // (65535, the background, becomes 65528).
  for (const Case& c : {Case{".tif", 0.25, "0.25"}, Case{".png", -7, "7"}}) {
    SCOPED_TRACE(c.extension);
    const std::string ref = "ref" + c.extension, out = "d" + c.extension;
    ASSERT_EQ(s.run({"-o", "ref-c.png", "--depth", ref, "-q"}).status, 0);
    const auto same = s.run({"-o", "c.png", "--depth", out, "--reference-depth", ref});
    EXPECT_EQ(same.status, 0) << same.err;
    EXPECT_EQ(test::beyondSummary(same.err), "");
    EXPECT_FALSE(fs::exists(s.dir.file("d-diff.png")));

    const int x = 2, y = 30;  // background
    const std::string changed = "changed" + c.extension;
    writeChangedDepth(s, ref, changed, x, y, c.change);
    const auto r = s.run({"-o", "c.png", "--depth", out, "--reference-depth", changed});
    EXPECT_EQ(r.status, 3) << r.err;
    EXPECT_EQ(test::beyondSummary(r.err), differsLine(out, changed, 1, c.largest, "d-diff.png"));
    expectRedOnlyAt(s.dir.file("d-diff.png"), x, y);
    fs::remove(s.dir.file("d-diff.png"));
  }
  // The float depth as OpenEXR (written here, the values of ref.tif): the same floats.
  const cv::Mat floats = test::imread(s.dir.file("ref.tif"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(floats.type(), CV_32FC1);
  ASSERT_TRUE(test::imwrite(s.dir.file("ref.exr"), floats));
  const auto exr = s.run({"-o", "c.png", "--depth", "d.tif", "--reference-depth", "ref.exr"});
  EXPECT_EQ(exr.status, 0) << exr.err;
  EXPECT_EQ(test::beyondSummary(exr.err), "");
  // A 16-bit reference for a float depth image: another type, not compared.
  const auto r = s.run({"-o", "c.png", "--depth", "d.tif", "--reference-depth", "ref.png"});
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err),
            "zrender: reference: d.tif (32x32 32-bit float, 1 channel) and ref.png (32x32 "
            "16-bit, 1 channel) differ in type; not compared\n");
  EXPECT_FALSE(fs::exists(s.dir.file("d-diff.png")));
}

TEST(ReferenceImages, IdsReference) {
  SquareScene s;
  ASSERT_EQ(s.run({"-o", "ref-c.png", "--ids", "ref-ids.png", "-q"}).status, 0);
  const auto same = s.run({"-o", "c.png", "--ids", "ids.png", "--reference-ids", "ref-ids.png"});
  EXPECT_EQ(same.status, 0) << same.err;
  EXPECT_EQ(test::beyondSummary(same.err), "");

  // Face 1 (id 2 in the image) where face 0 (id 1) is: a difference of 1 in red, the low byte.
  cv::Mat ids = test::imread(s.dir.file("ref-ids.png"));
  const int x = 20, y = 20;  // lower right of the square's middle: face 0
  ASSERT_EQ(ids.at<cv::Vec3b>(y, x), cv::Vec3b(0, 0, 1));
  ids.at<cv::Vec3b>(y, x) = cv::Vec3b(0, 0, 2);
  ASSERT_TRUE(test::imwrite(s.dir.file("changed-ids.png"), ids));
  const auto r = s.run({"-o", "c.png", "--ids", "ids.png", "--reference-ids", "changed-ids.png"});
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err),
            differsLine("ids.png", "changed-ids.png", 1, "1", "ids-diff.png"));
  expectRedOnlyAt(s.dir.file("ids-diff.png"), x, y);
}

}  // namespace
}  // namespace zrender
