// Errors of the OBJ loader (docs/design.md, Models and Errors): one line naming the file and the
// line, for missing files, malformed numbers and statements, bad indices, non-finite
// coordinates, models without faces, too many corners and binary garbage; and every input of the
// OBJ fuzz target's corpus loads or fails so.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "support/ObjLoaderFixture.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {
namespace {

using ObjLoaderErrors = test::ObjLoaderFixture;
using test::expectMessage;
using test::kSquareVertices;
namespace fs = std::filesystem;

TEST_F(ObjLoaderErrors, LineNumbersCountCrlfAndLoneCr) {
  // Lines: 1 v, 2 v, 3 blank, 4 v, 5 bad.
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError("v 0 0 0\r\nv 1 0 0\r\r\nv 0 1 0\rv 1 x 0\r\nf 1 2 3\r\n"), path,
                {":5: ", "'x'"});
}

TEST_F(ObjLoaderErrors, MissingFile) {
  const fs::path path = dir_ / "nope.obj";
  Warnings warnings;
  try {
    loadObj(path, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": cannot open file");
  }
  try {
    loadObj(dir_, warnings);  // a folder
    FAIL() << "no error";
  } catch (const InputError& e) {
    expectMessage(e.what(), dir_, {": cannot open file"});
  }
}

TEST_F(ObjLoaderErrors, MalformedNumbers) {
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 abc 3\nf 1 2 3\n"), path,
                {":3: ", "malformed 'v' line", "'abc' is not a number"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 2 3x\nf 1 2 3\n"), path, {":3: ", "'3x'"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 2\nf 1 2 3\n"), path,
                {":3: ", "expected at least 3 numbers, got 2"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv\nf 1 2 3\n"), path, {":3: ", "got 0"});
  expectMessage(loadError(std::string(kSquareVertices) + "vt 0.5 .\nf 1 2 3\n"), path,
                {":5: ", "malformed 'vt' line", "'.'"});
  expectMessage(loadError(std::string(kSquareVertices) + "vn 0 0 1e\nf 1 2 3\n"), path,
                {":5: ", "malformed 'vn' line", "'1e'"});
  expectMessage(loadError(std::string(kSquareVertices) + "f 1 x 3\n"), path,
                {":5: ", "malformed 'f' line", "'x'"});
  expectMessage(loadError(std::string(kSquareVertices) + "f 1/ 2/ 3/\n"), path, {":5: ", "'1/'"});
  expectMessage(loadError(std::string(kSquareVertices) + "f 1 2 3.0\n"), path, {":5: ", "'3.0'"});
  expectMessage(loadError(std::string(kSquareVertices) + "f 1/1/1/1 2 3\n"), path,
                {":5: ", "'1/1/1/1'"});
  expectMessage(loadError(std::string(kSquareVertices) + "f\n"), path,
                {":5: ", "face has no vertices"});
  // No inline comments: tinyobjloader would read "#" as one more corner.
  expectMessage(loadError(std::string(kSquareVertices) + "f 1 2 3 # c\n"), path, {":5: ", "'#'"});
}

TEST_F(ObjLoaderErrors, IndexZero) {
  const fs::path path = dir_ / "m.obj";
  const std::string head = std::string(kSquareVertices) + "vt 0 0\nvn 0 0 1\n";  // lines 1-6
  expectMessage(loadError(head + "f 1 0 3\n"), path, {":7: ", "vertex index 0 is invalid"});
  expectMessage(loadError(head + "f 1/1 2/0 3/1\n"), path,
                {":7: ", "texture coordinate index 0 is invalid"});
  expectMessage(loadError(head + "f 1//1 2//1 3//-0\n"), path, {":7: ", "normal index 0"});
}

TEST_F(ObjLoaderErrors, IndexOutOfRange) {
  const fs::path path = dir_ / "m.obj";
  const std::string head = std::string(kSquareVertices) + "vt 0 0\nvn 0 0 1\n";  // lines 1-6
  expectMessage(loadError(head + "f 1 2 3\nf 1 12 3\n"), path,
                {":8: ", "vertex index 12 out of range (model has 4 vertices)"});
  expectMessage(loadError(head + "f 1 -5 3\n"), path,
                {":7: ", "vertex index -5 out of range (4 vertices defined before this line)"});
  expectMessage(loadError(head + "f 1/2 2/1 3/1\n"), path,
                {":7: ", "texture coordinate index 2 out of range (model has 1 texture"});
  expectMessage(loadError(head + "f 1/-2 2/1 3/1\n"), path,
                {":7: ", "texture coordinate index -2 out of range"});
  expectMessage(loadError(head + "f 1//1 2//3 3//1\n"), path,
                {":7: ", "normal index 3 out of range (model has 1 normals)"});
  expectMessage(loadError(head + "f 1//1 2//-2 3//1\n"), path, {":7: ", "normal index -2 out"});
  // A negative index cannot reach a vertex defined after its line.
  expectMessage(loadError("v 0 0 0\nf -1 -2 -1\nv 1 0 0\n"), path,
                {":2: ", "vertex index -2 out of range"});
  // Beyond int32: refused, not wrapped by atoi.
  expectMessage(loadError(head + "f 1 2 4294967297\n"), path,
                {":7: ", "vertex index 4294967297 out of range"});
}

TEST_F(ObjLoaderErrors, NonFiniteCoordinates) {
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError(std::string(kSquareVertices) + "v nan 0 0\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite coordinate 'nan'"});
  expectMessage(loadError(std::string(kSquareVertices) + "vt 0 -Inf\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite coordinate '-Inf'"});
  expectMessage(loadError(std::string(kSquareVertices) + "vn 0 0 -1.#IND\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite"});
  // Well-formed numbers that overflow a double, found by tinyobjloader's values.
  expectMessage(loadError(std::string(kSquareVertices) + "f 1 2 3\nv 1e400 0 0\n"), path,
                {":6: ", "NaN or infinite coordinate"});
  expectMessage(loadError(std::string(kSquareVertices) + "vt 0 0\nvt 0 " + std::string(400, '9') +
                          "\nf 1 2 3\n"),
                path, {":6: ", "NaN or infinite coordinate"});
  expectMessage(loadError(std::string(kSquareVertices) + "vn 0 0 1\nf 1 2 3\nvn 1e-999999 0 0\n"),
                path, {":7: ", "out of range"});
}

TEST_F(ObjLoaderErrors, NoFaces) {
  const fs::path path = dir_ / "m.obj";
  EXPECT_EQ(loadError(std::string(kSquareVertices) + "l 1 2\np 3\n"),
            path.string() + ": model has no faces");
  EXPECT_EQ(loadError(""), path.string() + ": model has no faces");
  EXPECT_EQ(loadError("\xEF\xBB\xBF"), path.string() + ": model has no faces");
}

TEST_F(ObjLoaderErrors, TooManyCorners) {
  std::string obj = kSquareVertices;
  obj += "f";
  for (uint32_t i = 0; i <= kMaxFaceCorners; ++i) obj += " " + std::to_string(i % 4 + 1);
  obj += "\n";
  expectMessage(loadError(obj), dir_ / "m.obj", {":5: ", "more than 4096 corners"});
}

TEST_F(ObjLoaderErrors, BinaryGarbageIsACleanError) {
  uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<char>(state >> 24);
  };
  for (int round = 0; round < 20; ++round) {
    std::string bytes;
    for (int i = 0; i < 20000; ++i) {
      // Some rounds plant statement keywords among the garbage.
      if (round % 2 == 1 && i % 97 == 0) bytes += (i % 3 == 0) ? "\nf " : "\nv ";
      bytes += next();
    }
    const std::string message = loadError(bytes);
    EXPECT_EQ(message.rfind((dir_ / "m.obj").string() + ":", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Every input of the OBJ fuzz target's corpus loads or fails with a one-line InputError.
TEST_F(ObjLoaderErrors, EveryInputOfTheObjFuzzCorpusLoadsOrFailsCleanly) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(ZRENDER_SOURCE_DIR "/fuzz/corpus/obj")) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = test::readFile(entry.path().string());
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
