// Runs of several views (docs/design.md, Views): --orbit and the settings' `views`, names with
// fields, depth, ids and normals per view, the camera manifest, and parts of a run (--frames,
// --shard, --skip-existing) that write the whole run's files byte for byte; the summary line,
// -q and the errors of options that cannot go together.

#include <gtest/gtest.h>
#include <json/json.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::readFile;
using test::runZrender;
using test::TempDir;

constexpr double kPi = 3.14159265358979323846;

// A UV sphere of radius 1 at the origin, `rings` x `segments` quads (triangles at the poles),
// faces counter-clockwise seen from outside: big faces, so that the pixel of a vertex lies in
// one of the faces around it.
struct Sphere {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;  // 0-based
  std::string obj() const {
    std::ostringstream out;
    out.precision(17);
    for (const Vec3& v : vertices) out << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (const auto& f : faces) {
      out << "f";
      for (int i : f) out << " " << i + 1;
      out << "\n";
    }
    return out.str();
  }
};

Sphere makeSphere(int rings, int segments) {
  Sphere s;
  s.vertices.push_back(Vec3(0, 1, 0));
  for (int r = 1; r < rings; ++r) {
    const double theta = kPi * r / rings;
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * kPi * k / segments;
      s.vertices.push_back(
          Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)));
    }
  }
  s.vertices.push_back(Vec3(0, -1, 0));
  const int bottom = int(s.vertices.size()) - 1;
  const auto at = [&](int r, int k) { return 1 + (r - 1) * segments + (k % segments); };
  for (int k = 0; k < segments; ++k) s.faces.push_back({0, at(1, k), at(1, k + 1)});
  for (int r = 1; r + 1 < rings; ++r) {
    for (int k = 0; k < segments; ++k)
      s.faces.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1), at(r, k + 1)});
  }
  for (int k = 0; k < segments; ++k)
    s.faces.push_back({at(rings - 1, k), bottom, at(rings - 1, k + 1)});
  return s;
}

// A scene `ball` of the sphere, 96 x 80, seen from (0, 0, 4).
void writeBall(TempDir& dir, const Sphere& sphere, const std::string& extra = "") {
  dir.write("ball.obj", sphere.obj());
  dir.write("settings.json", R"({"ball": {"path": "ball.obj", "width": 96, "height": 80,
    "eye": [0, 0, 4], "target": [0, 0, 0], "project": [40, 0, 0.5, 10])" +
                                 extra + "}}");
}

Json::Value parseJson(const std::string& text) {
  Json::Value v;
  std::istringstream(text) >> v;
  return v;
}

std::vector<Json::Value> jsonLines(const std::string& text) {
  std::vector<Json::Value> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(parseJson(line));
  return lines;
}

// Every file of a folder and its bytes.
std::map<std::string, std::string> folderFiles(const std::string& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(folder))
    files[e.path().filename().string()] = readFile(e.path().string());
  return files;
}

// An orbit of 5 views in two rings (10 views), every kind of file, into `folder`.
std::vector<std::string> orbitRun(const std::string& folder, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"ball",
                                   "--orbit",
                                   "5",
                                   "--orbit-elevations",
                                   "0,40",
                                   "-o",
                                   folder + "/{scene}-{view:02}.png",
                                   "--depth",
                                   folder + "/depth-{view:02}.exr",
                                   "--ids",
                                   folder + "/ids-{view:02}.png",
                                   "--normals",
                                   folder + "/normals-{view:02}.png",
                                   "--cameras",
                                   folder + "/transforms.json"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(ViewsRun, AnOrbitWritesEveryViewsFilesTheSameAtAnyThreadCount) {
  TempDir dir;
  writeBall(dir, makeSphere(8, 12));
  const auto one = runZrender(orbitRun("one", {"--threads", "1", "--json"}), dir.path);
  ASSERT_EQ(one.status, 0) << one.err;
  const auto files = folderFiles(dir.file("one"));
  EXPECT_EQ(files.size(), 10u * 4 + 1);
  for (const char* name : {"ball-00.png", "ball-09.png", "depth-09.exr", "ids-00.png",
                           "normals-05.png", "transforms.json"})
    EXPECT_EQ(files.count(name), 1u) << name;
  // One JSON line per view, in view order, naming its files.
  const auto lines = jsonLines(one.out);
  ASSERT_EQ(lines.size(), 10u);
  for (size_t v = 0; v < 10; ++v) {
    EXPECT_EQ(lines[v]["view"].asUInt64(), v);
    char name[32];
    std::snprintf(name, sizeof name, "/ids-%02zu.png", v);
    EXPECT_EQ(lines[v]["files"]["ids"].asString(), "one" + std::string(name));
    EXPECT_TRUE(lines[v]["files"].isMember("normals"));
  }
  // Views in two rings differ; the summary names the patterns and the count.
  EXPECT_NE(files.at("ball-00.png"), files.at("ball-05.png"));
  EXPECT_TRUE(test::matchesWithNumbers(
      one.err,
      "zrender: wrote # views to one/{scene}-{view:02}.png, one/depth-{view:02}.exr, "
      "one/ids-{view:02}.png, one/normals-{view:02}.png and one/transforms.json (96x80, "
      "zbuffer, frame # ms median, # views/s)\n"))
      << one.err;
  for (const char* threads : {"2", "3"}) {
    SCOPED_TRACE(threads);
    const std::string folder = std::string("t") + threads;
    const auto r = runZrender(orbitRun(folder, {"--threads", threads}), dir.path);
    ASSERT_EQ(r.status, 0) << r.err;
    // The manifest names files relative to its folder: the same text from any folder.
    EXPECT_EQ(folderFiles(dir.file(folder)), files);
  }
}

TEST(ViewsRun, AnySplitOfARunWritesTheWholeRunsFilesByteForByte) {
  TempDir dir;
  writeBall(dir, makeSphere(8, 12));
  ASSERT_EQ(runZrender(orbitRun("whole"), dir.path).status, 0);
  const auto whole = folderFiles(dir.file("whole"));
  // Frame ranges.
  for (const char* range : {"0:3", "3:7", "7:"}) {
    const auto r = runZrender(orbitRun("frames", {"--frames", range}), dir.path);
    ASSERT_EQ(r.status, 0) << r.err;
    // Every part writes the whole manifest, the same bytes.
    EXPECT_EQ(readFile(dir.file("frames/transforms.json")), whole.at("transforms.json"));
  }
  EXPECT_EQ(folderFiles(dir.file("frames")), whole);
  // Shards: 3 parts of 10 views, each on its own thread count.
  for (int shard = 0; shard < 3; ++shard) {
    const auto r =
        runZrender(orbitRun("shards", {"--shard", std::to_string(shard) + "/3", "--threads",
                                       std::to_string(1 + shard % 2), "--json"}),
                   dir.path);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = jsonLines(r.out);
    ASSERT_FALSE(lines.empty());
    // Contiguous parts: 0-2, 3-5, 6-9.
    EXPECT_EQ(lines.front()["view"].asUInt64(), size_t(10 * shard / 3));
    EXPECT_EQ(lines.back()["view"].asUInt64(), size_t(10 * (shard + 1) / 3 - 1));
  }
  EXPECT_EQ(folderFiles(dir.file("shards")), whole);
  // A run stopped part way, resumed: only the views with a file missing are rendered again.
  fs::remove(dir.file("shards/ball-04.png"));
  fs::remove(dir.file("shards/normals-08.png"));
  const auto resumed = runZrender(orbitRun("shards", {"--skip-existing", "--json"}), dir.path);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  const auto lines = jsonLines(resumed.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0]["view"].asUInt64(), 4u);
  EXPECT_EQ(lines[1]["view"].asUInt64(), 8u);
  EXPECT_NE(resumed.err.find("(8 already written)"), std::string::npos) << resumed.err;
  EXPECT_EQ(folderFiles(dir.file("shards")), whole);
  // A manifest alone, rendering nothing.
  const auto cameras = runZrender(orbitRun("cams", {"--cameras-only"}), dir.path);
  ASSERT_EQ(cameras.status, 0) << cameras.err;
  EXPECT_EQ(folderFiles(dir.file("cams")),
            (std::map<std::string, std::string>{{"transforms.json", whole.at("transforms.json")}}));
}

// The pixel of a world point through a manifest frame's matrices, and its window depth.
struct Projected {
  double x, y, depth;
};
Projected project(const Json::Value& frame, const Vec3& p, int w, int h) {
  const auto matrix = [](const Json::Value& rows) {
    Mat4 m;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m(r, c) = rows[r][c].asDouble();
    return m;
  };
  const Mat4 cameraToWorld = matrix(frame["transform_matrix"]);
  const Vec4 clip = matrix(frame["zrender"]["projection_matrix"]) * cameraToWorld.inv() *
                    Vec4(p[0], p[1], p[2], 1.0);
  return {(clip[0] / clip[3] + 1) * 0.5 * w, (1 - clip[1] / clip[3]) * 0.5 * h,
          (clip[2] / clip[3] + 1) * 0.5};
}

TEST(ViewsRun, TheManifestsCamerasProjectEachVisibleVertexOntoAFaceThatUsesIt) {
  TempDir dir;
  const Sphere sphere = makeSphere(10, 16);
  // Views in full and relative, a zoom among them, and an eye straight above (elevation 90).
  writeBall(dir, sphere, R"(, "views": [{}, {"azimuth": 30, "elevation": 20},
    {"eye": [2, 1.5, 3]}, {"azimuth": -60, "zoom": 1.5}, {"elevation": 90}])");
  const auto r = runZrender(
      {"ball", "-o", "v/{view}.png", "--ids", "v/ids-{view}.png", "--cameras", "v/transforms.json"},
      dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json::Value manifest = parseJson(readFile(dir.file("v/transforms.json")));
  const int w = manifest["w"].asInt(), h = manifest["h"].asInt();
  ASSERT_EQ(w, 96);
  ASSERT_EQ(h, 80);
  ASSERT_EQ(manifest["frames"].size(), 5u);
  std::vector<std::set<uint32_t>> facesOf(sphere.vertices.size());
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    for (int v : sphere.faces[f]) facesOf[size_t(v)].insert(uint32_t(f));
  for (Json::ArrayIndex k = 0; k < manifest["frames"].size(); ++k) {
    SCOPED_TRACE("view " + std::to_string(k));
    const Json::Value& frame = manifest["frames"][k];
    EXPECT_EQ(frame["file_path"].asString(), std::to_string(k) + ".png");
    const cv::Mat ids = test::imread(dir.file("v/" + frame["zrender"]["ids_file_path"].asString()),
                                     cv::IMREAD_UNCHANGED);
    ASSERT_EQ(ids.cols, w);
    // The eye in world space: the camera-to-world matrix's translation.
    const Json::Value& m = frame["transform_matrix"];
    const Vec3 eye(m[0][3].asDouble(), m[1][3].asDouble(), m[2][3].asDouble());
    const double flX = frame.get("fl_x", manifest["fl_x"]).asDouble();
    const double flY = frame.get("fl_y", manifest["fl_y"]).asDouble();
    int checked = 0;
    for (size_t v = 0; v < sphere.vertices.size(); ++v) {
      const Vec3 p = sphere.vertices[v];
      // Visible on a convex model: facing the eye, well inside the silhouette.
      if (p.dot(cv::normalize(eye - p)) < 0.4) continue;
      const Projected q = project(frame, p, w, h);
      if (q.x < 1 || q.y < 1 || q.x >= w - 1 || q.y >= h - 1) continue;
      const cv::Vec3b px = ids.at<cv::Vec3b>(int(q.y), int(q.x));
      const uint32_t id = (uint32_t(px[2]) | uint32_t(px[1]) << 8 | uint32_t(px[0]) << 16) - 1;
      EXPECT_EQ(facesOf[v].count(id), 1u)
          << "vertex " << v << " at " << q.x << ", " << q.y << " shows face " << id;
      // The pinhole intrinsics say the same as the projection matrix (OpenGL axes: the camera
      // looks down -Z, image y down).
      const Vec3 c = transformPoint(
          Mat4(m[0][0].asDouble(), m[0][1].asDouble(), m[0][2].asDouble(), m[0][3].asDouble(),
               m[1][0].asDouble(), m[1][1].asDouble(), m[1][2].asDouble(), m[1][3].asDouble(),
               m[2][0].asDouble(), m[2][1].asDouble(), m[2][2].asDouble(), m[2][3].asDouble(), 0, 0,
               0, 1)
              .inv(),
          p);
      EXPECT_NEAR(manifest["cx"].asDouble() + flX * c[0] / -c[2], q.x, 1e-9);
      EXPECT_NEAR(manifest["cy"].asDouble() - flY * c[1] / -c[2], q.y, 1e-9);
      ++checked;
    }
    EXPECT_GT(checked, 20);
  }
  // The zoomed view's focal lengths are its own, 1.5 times the others'.
  EXPECT_NEAR(manifest["frames"][3]["fl_x"].asDouble(), 1.5 * manifest["fl_x"].asDouble(), 1e-9);
  EXPECT_FALSE(manifest["frames"][1].isMember("fl_x"));
}

TEST(ViewsRun, NormalsAreTheNormalModesWithinARounding) {
  // spot has vertex normals (the surface kernel's interpolation), the ball has none (its faces'
  // normals).
  TempDir dir;
  writeBall(dir, makeSphere(8, 12));
  for (const std::vector<std::string>& scene :
       {std::vector<std::string>{"spot", "--width", "160", "--height", "120", "--settings",
                                 ZRENDER_SOURCE_DIR "/settings.json"},
        std::vector<std::string>{"ball"}}) {
    SCOPED_TRACE(scene.front());
    if (scene.front() == "spot" && !test::referenceModel("spot")) continue;
    std::vector<std::string> args = scene;
    for (const char* a : {"--shading", "normal", "-o", "n.png", "-q", "--normals"})
      args.push_back(a);
    args.push_back("n.exr");
    ASSERT_EQ(runZrender(args, dir.path).status, 0);
    args.back() = "n16.png";
    ASSERT_EQ(runZrender(args, dir.path).status, 0);
    const cv::Mat sixteen = test::imread(dir.file("n16.png"), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(sixteen.type(), CV_16UC3);
    const cv::Mat color = test::imread(dir.file("n.png"));
    const cv::Mat normals = test::imread(dir.file("n.exr"), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(normals.type(), CV_32FC3);
    ASSERT_EQ(normals.size(), color.size());
    int covered = 0;
    for (int y = 0; y < color.rows; ++y) {
      for (int x = 0; x < color.cols; ++x) {
        const cv::Vec3f n = normals.at<cv::Vec3f>(y, x);
        const cv::Vec3b c = color.at<cv::Vec3b>(y, x);
        const cv::Vec<uint16_t, 3> n16 = sixteen.at<cv::Vec<uint16_t, 3>>(y, x);
        if (n == cv::Vec3f(0, 0, 0)) {
          EXPECT_EQ(c, cv::Vec3b(0, 0, 0)) << x << ", " << y;
          EXPECT_EQ(n16, (cv::Vec<uint16_t, 3>(0, 0, 0)));
          continue;
        }
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(n16[i], std::lround((double(n[i]) + 1) * 0.5 * 65535)) << x << ", " << y;
        ++covered;
        EXPECT_NEAR(cv::norm(n), 1.0, 1e-5);
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(double(c[i]), (double(n[i]) + 1) * 127.5, 1.0) << x << ", " << y << " " << i;
      }
    }
    EXPECT_GT(covered, 500);
  }
}

TEST(ViewsRun, SixteenBitNormalsOfASquareFacingTheEye) {
  TempDir dir;
  dir.write("sq.obj", test::kSquareObj);
  dir.write("settings.json", test::settingsFor("sq.obj"));
  ASSERT_EQ(runZrender({"sq", "--normals", "n.png", "-q"}, dir.path).status, 0);
  const cv::Mat n = test::imread(dir.file("n.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(n.type(), CV_16UC3);
  // The square spans the middle half of the 32 x 32 image: (0, 0, 1) there, 0 elsewhere.
  using Pixel16 = cv::Vec<uint16_t, 3>;
  EXPECT_EQ(n.at<Pixel16>(16, 16), Pixel16(65535, 32768, 32768));
  EXPECT_EQ(n.at<Pixel16>(2, 2), Pixel16(0, 0, 0));
}

TEST(ViewsRun, OneLineOnSuccessAndQuietSaysNothing) {
  TempDir dir;
  dir.write("sq.obj", test::kSquareObj);
  dir.write("settings.json", test::settingsFor("sq.obj"));
  const auto r = runZrender({"sq", "--ids", "i.png"}, dir.path);
  ASSERT_EQ(r.status, 0);
  EXPECT_TRUE(test::matchesWithNumbers(
      r.err, "zrender: wrote sq.png and i.png (32x32, zbuffer, frame # ms)\n"))
      << r.err;
  const auto q = runZrender({"sq", "-q", "--azimuth", "10"}, dir.path);
  ASSERT_EQ(q.status, 0);
  EXPECT_EQ(q.err, "");
  // A log (stderr not a terminal): progress lines, none before five seconds.
  const auto lines = runZrender({"sq", "--orbit", "3", "--progress", "lines"}, dir.path);
  ASSERT_EQ(lines.status, 0);
  EXPECT_EQ(std::count(lines.err.begin(), lines.err.end(), '\n'), 1) << lines.err;
}

TEST(ViewsRun, OptionsThatCannotGoTogetherAreCleanErrors) {
  TempDir dir;
  dir.write("sq.obj", test::kSquareObj);
  dir.write("settings.json",
            test::settingsFor("sq.obj", R"(, "views": [{"zoom": 2}, {"eye": [0, 0, 0]}])"));
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{"--orbit", "4", "--frames", "2:9"}, {"--frames", "0 <= A < B <= 4", "'2:9'"}},
      {{"--orbit", "4", "--frames", "3:3"}, {"--frames", "'3:3'"}},
      {{"--orbit", "4", "--shard", "4/4"}, {"--shard", "'4/4'"}},
      {{"--orbit", "4", "--shard", "x"}, {"--shard", "I/N"}},
      {{"--orbit", "4", "-o", "t.mp4", "--shard", "0/2"}, {"video", "--shard"}},
      {{"--orbit", "4", "--contact-sheet", "s.png", "--frames", "0:2"},
       {"--contact-sheet", "--frames"}},
      {{"--orbit", "4", "-o", "{view}.png", "--normals", "n.exr"}, {"--normals", "{view}"}},
      {{"--cameras-only"}, {"--cameras-only needs --cameras"}},
      {{"--orbit", "4", "-o", "t.mp4", "--cameras", "c.json"}, {"--cameras", "video"}},
      {{"--orbit", "4", "--turntable", "4"}, {"--turntable", "--orbit"}},
      {{"--progress", "fancy"}, {"--progress", "fancy"}},
      {{"--orbit", "2", "-o", "{view}.png", "--cameras", "c.txt"}, {"c.txt", "camera manifest"}},
      {{"-o", "{frame}.png"}, {"-o", "{frame}"}},
  };
  for (const auto& [args, pieces] : cases) {
    std::vector<std::string> all = {"sq"};
    all.insert(all.end(), args.begin(), args.end());
    std::string trace;
    for (const std::string& a : args) trace += a + " ";
    SCOPED_TRACE(trace);
    expectCleanError(runZrender(all, dir.path), pieces);
  }
  // The settings' second view: its eye is the target.
  expectCleanError(runZrender({"sq", "-o", "{view}.png"}, dir.path),
                   {"settings.json: scene 'sq': key 'views[1]'", "is the target"});
  EXPECT_FALSE(fs::exists(dir.file("0.png")));
}

}  // namespace
}  // namespace zrender
