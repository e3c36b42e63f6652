#pragma once

// The fixture of the OBJ loader tests (io/ObjLoaderTest.cpp, io/ObjLoaderErrorsTest.cpp):
// files written byte for byte into a folder of the test's own, loaded, or their error message.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender::test {

namespace fs = std::filesystem;

// Each test gets its own folder under the system temp folder, removed afterwards.
class ObjLoaderFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("zrender_objloader_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Writes bytes exactly as given (binary: no newline translation).
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(out.good()) << path;
    return path;
  }

  Mesh load(const std::string& name, const std::string& bytes) {
    Warnings warnings;
    Mesh mesh = loadObj(write(name, bytes), warnings);
    EXPECT_TRUE(warnings.empty()) << (warnings.empty() ? "" : warnings.front());
    return mesh;
  }

  // The InputError message of loading these bytes, or "no error".
  std::string loadError(const std::string& bytes, const std::string& name = "m.obj") {
    const fs::path path = write(name, bytes);
    Warnings warnings;
    try {
      loadObj(path, warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
};

// Message check: starts with the file path, holds each expected piece.
inline void expectMessage(const std::string& message, const fs::path& file,
                          std::initializer_list<const char*> pieces) {
  EXPECT_EQ(message.rfind(file.string(), 0), 0u) << message;
  for (const char* piece : pieces) {
    EXPECT_NE(message.find(piece), std::string::npos) << "'" << piece << "' not in: " << message;
  }
}

// Four vertices of a unit square (lines 1 to 4 of a file), no faces.
inline constexpr char kSquareVertices[] =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

}  // namespace zrender::test
