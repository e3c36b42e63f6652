// The OBJ parse in parts (docs/design.md, Loading): the mesh tinyobjloader's own parse reads,
// numbers correctly rounded, the same mesh and the same error message on any number of threads
// and any size of part.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "support/ObjLoaderFixture.hpp"
#include "support/TestSupport.hpp"
#include "support/TinyObjReference.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace zrender {
namespace {

using ObjParser = test::ObjLoaderFixture;

// How the text is parsed: on how many threads (1: none given), in parts of how many bytes.
struct Split {
  int threads;
  size_t partBytes;
};

const Split kSplits[] = {{1, kObjPartBytes}, {1, 1}, {2, 16}, {3, 1}, {7, 40}, {2, 4096}};

Mesh loadWith(const std::string& text, const std::filesystem::path& path, const Split& split,
              Warnings& warnings) {
  if (split.threads == 1) return loadObjFromText(text, path, warnings, nullptr, split.partBytes);
  const Threads threads(split.threads);
  return loadObjFromText(text, path, warnings, &threads, split.partBytes);
}

std::string loadMessage(const std::string& text, const Split& split) {
  Warnings warnings;
  try {
    loadWith(text, "m.obj", split, warnings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// `library`: the text loads m.mtl, which defines red and green.
void expectSameGeometry(const Mesh& parsed, const test::TinyObjGeometry& reference, bool library) {
  ASSERT_EQ(test::geometryDifference(parsed, reference), "");
  ASSERT_EQ(parsed.faceMaterial.size(), reference.faceUse.size());
  for (size_t f = 0; f < parsed.faceMaterial.size(); ++f) {
    const int32_t m = parsed.faceMaterial[f];
    EXPECT_EQ(m < 0 ? std::string("(none)") : parsed.materials[m].name,
              library && (reference.faceUse[f] == "red" || reference.faceUse[f] == "green")
                  ? reference.faceUse[f]
                  : std::string("(none)"))
        << "face " << f;
  }
}

// Valid OBJ text in the variants exporters and hands write: numbers in every form the grammar
// allows, w and extra numbers, vt of one to three numbers, the four corner forms, negative and
// forward indices, tabs, CRLF and lone CR, NUL bytes, comments, groups and usemtl lines.
std::string randomObj(unsigned seed) {
  std::mt19937 rng(seed);
  const auto pick = [&](int n) { return static_cast<int>(rng() % unsigned(n)); };
  const auto number = [&]() {
    std::uniform_real_distribution<double> value(-50.0, 50.0);
    char buf[64];
    switch (pick(8)) {
      case 0:
        std::snprintf(buf, sizeof buf, "%.6f", value(rng));
        break;
      case 1:
        std::snprintf(buf, sizeof buf, "%.17g", value(rng));
        break;
      case 2:
        std::snprintf(buf, sizeof buf, "%+.3e", value(rng));
        break;
      case 3:
        std::snprintf(buf, sizeof buf, "%d", pick(2000) - 1000);
        break;
      case 4:
        std::snprintf(buf, sizeof buf, "%d.", pick(100));
        break;
      case 5:
        std::snprintf(buf, sizeof buf, "-.%d", pick(100000));
        break;
      case 6:
        std::snprintf(buf, sizeof buf, "%.4E", value(rng) * 1e-7);
        break;
      default:
        std::snprintf(buf, sizeof buf, "%.9g", value(rng));
        break;
    }
    return std::string(buf);
  };
  const auto gap = [&]() { return std::string(pick(4) == 0 ? " \t " : pick(3) == 0 ? "\t" : " "); };
  const char* const ends[] = {"\n", "\n", "\n", "\r\n", "\r"};

  // The kinds of statement first, so that positive indices may refer forward to the totals.
  std::vector<int> kinds;  // 0 v, 1 vt, 2 vn, 3 f, 4 other
  const int statements = 20 + pick(120);
  int totals[3] = {0, 0, 0};
  for (int i = 0; i < statements; ++i) {
    const int kind = pick(10) < 4 ? 0 : pick(5);
    kinds.push_back(kind);
    if (kind < 3) ++totals[kind];
  }
  if (totals[0] == 0) {
    kinds.insert(kinds.begin(), 0);
    totals[0] = 1;
  }
  kinds.push_back(3);

  std::string text = pick(2) ? "mtllib m.mtl\n" : "";
  int before[3] = {0, 0, 0};
  for (const int kind : kinds) {
    std::string line(pick(6) == 0 ? " \t" : "");
    if (kind < 3) {
      const char* const keywords[] = {"v", "vt", "vn"};
      const int numbers = kind == 0 ? 3 + pick(3) : kind == 1 ? 1 + pick(3) : 3;
      line += keywords[kind];
      for (int n = 0; n < numbers; ++n) line += gap() + number();
      ++before[kind];
    } else if (kind == 3) {
      line += "f";
      const int corners = 1 + pick(6);
      const int form = pick(4);  // v, v/vt, v//vn, v/vt/vn
      for (int c = 0; c < corners; ++c) {
        const auto index = [&](int k) {
          if (before[k] > 0 && pick(3) == 0) return std::to_string(-1 - pick(before[k]));
          return std::to_string(1 + pick(totals[k]));
        };
        const bool vt = (form == 1 || form == 3) && totals[1] > 0;
        const bool vn = (form == 2 || form == 3) && totals[2] > 0;
        line += gap() + index(0);
        if (vt || vn) line += "/" + (vt ? index(1) : std::string());
        if (vn) line += "/" + index(2);
      }
    } else {
      const char* const others[] = {
          "# a comment", "g part",         "o object",    "s 1",      "",
          "usemtl red",  "usemtl green  ", "usemtl blue", "usemtl\t", "vp 1 2"};
      line += others[pick(10)];
    }
    if (pick(12) == 0) line += std::string(1, '\0') + "junk f 1 2";
    if (pick(5) == 0) line += gap();
    text += line + ends[pick(5)];
  }
  return text;
}

TEST_F(ObjParser, ReadsWhatTinyObjLoaderReadsOnRandomTextInAnySplit) {
  write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl green\nKd 0 1 0\n");
  const std::filesystem::path path = dir_ / "m.obj";
  for (unsigned seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::string text = randomObj(seed);
    const test::TinyObjGeometry reference = test::tinyObjReference(text);
    std::unique_ptr<Mesh> first;
    for (const Split& split : kSplits) {
      SCOPED_TRACE(std::to_string(split.threads) + " threads, parts of " +
                   std::to_string(split.partBytes) + " bytes");
      Warnings warnings;
      Mesh mesh = loadWith(text, path, split, warnings);
      expectSameGeometry(mesh, reference, text.rfind("mtllib m.mtl\n", 0) == 0);
      if (!first)
        first = std::make_unique<Mesh>(std::move(mesh));
      else
        ASSERT_EQ(test::meshBitsDifference(mesh, *first), "");
      if (HasFatalFailure()) return;
    }
  }
}

TEST(ObjParserModels, ReadWhatTinyObjLoaderReadsAndTheSameOnAnyThreads) {
  for (const char* name : {"bunny", "spot", "teapot"}) {
    SCOPED_TRACE(name);
    const SceneSettings settings = test::projectScene(name);
    if (!std::filesystem::exists(settings.modelPath)) GTEST_SKIP() << "models not linked";
    const std::string text = test::readFile(settings.modelPath.string());
    const test::TinyObjGeometry reference = test::tinyObjReference(text);
    Warnings warnings;
    const Mesh one = loadWith(text, settings.modelPath, kSplits[0], warnings);
    ASSERT_EQ(test::geometryDifference(one, reference), "");
    for (const Split split : {Split{2, kObjPartBytes}, Split{3, 4096}, Split{7, 100000}}) {
      ASSERT_EQ(test::meshBitsDifference(loadWith(text, settings.modelPath, split, warnings), one),
                "");
    }
  }
}

// Numbers as the C++ compiler rounds the same literals: correctly.
TEST_F(ObjParser, NumbersAreCorrectlyRounded) {
  const Mesh mesh = load("m.obj",
                         "v 0.1 -2.5e-3 +7\n"
                         "v 0.30000000000000004441 5. -.5\n"
                         "v 1e-400 123456789012345678901234567890 4.9406564584124654e-324\n"
                         "vt 0.7\n"
                         "vn 1E+2 -0 3.14159265358979323846\n"
                         "f 1/1/1 2/1/1 3/1/1\n");
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_TRUE(sameBits(mesh.positions[0][0], 0.1));
  EXPECT_TRUE(sameBits(mesh.positions[0][1], -2.5e-3));
  EXPECT_TRUE(sameBits(mesh.positions[0][2], 7.0));
  EXPECT_TRUE(sameBits(mesh.positions[1][0], 0.30000000000000004441));
  EXPECT_TRUE(sameBits(mesh.positions[1][1], 5.0));
  EXPECT_TRUE(sameBits(mesh.positions[1][2], -0.5));
  EXPECT_TRUE(sameBits(mesh.positions[2][0], 0.0));  // below the least double: zero
  EXPECT_TRUE(sameBits(mesh.positions[2][1], 123456789012345678901234567890.0));
  EXPECT_TRUE(sameBits(mesh.positions[2][2], 4.9406564584124654e-324));
  EXPECT_TRUE(sameBits(mesh.texcoords[0][0], 0.7));
  EXPECT_TRUE(sameBits(mesh.texcoords[0][1], 0.0));  // v absent
  EXPECT_TRUE(sameBits(mesh.normals[0][0], 100.0));
  EXPECT_TRUE(sameBits(mesh.normals[0][1], -0.0));
  EXPECT_TRUE(sameBits(mesh.normals[0][2], 3.14159265358979323846));
}

std::string manyCorners(const std::string& vertices, int corners) {
  std::string text = vertices + "f 1 2 3\nf";
  for (int i = 0; i < corners; ++i) text += " 1";
  return text + "\n";
}

// The first bad line is named whatever the split, even when a later part's bad line is found
// first, and when the bad statement is cut across what would be two parts.
TEST(ObjParserErrors, SameMessageInAnySplit) {
  const std::string square = test::kSquareVertices;
  const std::string cases[] = {
      square + "f 1 2 3\nv 1 abc 3\nf 1 2 9\n",
      square + "f 1 2 3\nf 1 2 -9\nv nan 0 0\n",
      square + "f 1 2 7\nf 1 2 0\n",
      square + "f 1 2 3\nv 1e400 0 0\nv 1e401 0 0\n",
      square + "f 1 2 3\nvt 1e999999 0\n",
      square + "f 1/ 2/ 3/\n",
      square + "f 1 2 3\nvn 0 0\n",
      "v 0 0 0\n",
      manyCorners(square, 4100),
  };
  for (const std::string& text : cases) {
    const std::string expected = loadMessage(text, kSplits[0]);
    EXPECT_NE(expected, "no error") << text.substr(0, 80);
    for (const Split& split : kSplits) {
      EXPECT_EQ(loadMessage(text, split), expected)
          << split.threads << " threads, parts of " << split.partBytes << " bytes";
    }
  }
}

}  // namespace
}  // namespace zrender
