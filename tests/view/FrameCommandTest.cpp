// The command line that renders the viewer's frame (view/FrameCommand.hpp): every value the
// frame depends on, numbers that parse back to the same doubles, and words a shell keeps whole.

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/view/FrameCommand.hpp"

namespace zrender {
namespace {

std::vector<std::string> words(const std::string& command) {
  std::istringstream in(command);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The value after `option` in `command`.
std::string valueOf(const std::string& command, const std::string& option) {
  const auto w = words(command);
  for (size_t i = 0; i + 1 < w.size(); ++i)
    if (w[i] == option) return w[i + 1];
  ADD_FAILURE() << option << " not in " << command;
  return "";
}

Vec3 vectorOf(const std::string& command, const std::string& option) {
  const std::string text = valueOf(command, option);
  Vec3 v;
  const char* p = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    p = *end == ',' ? end + 1 : end;
  }
  return v;
}

TEST(FrameCommand, EveryValueParsesBackToTheSameDouble) {
  SceneSettings s = test::tinySettings(32);
  s.angle = 1.0 / 3.0;
  s.axis = Vec3(0.1, 0.7, -0.2);
  Camera cam;
  cam.width = 640, cam.height = 480;
  cam.eye = Vec3(1.0 / 7.0, -2.0 / 3.0, 1e-17);
  cam.target = Vec3(-0.0168, 0.1, -0.0015);
  cam.up = Vec3(0, 1, 0);
  cam.fovy = 30.000000000000004;
  cam.aspect = 4.0 / 3.0;
  cam.near = 0.1;
  cam.far = 10.0 / 3.0;
  ViewState state;
  state.algorithm = "octree";
  state.shading = ShadingMode::Phong;
  state.msaa = 4;
  const std::string c = frameCommand("bunny", std::nullopt, s, state, cam);
  EXPECT_EQ(c.rfind("zrender bunny --alg octree --shading phong --msaa 4 --cull ", 0), 0u) << c;
  EXPECT_EQ(valueOf(c, "--width"), "640");
  EXPECT_EQ(valueOf(c, "--height"), "480");
  EXPECT_EQ(vectorOf(c, "--eye"), cam.eye);
  EXPECT_EQ(vectorOf(c, "--target"), cam.target);
  EXPECT_EQ(vectorOf(c, "--up"), cam.up);
  EXPECT_EQ(vectorOf(c, "--axis"), s.axis);
  EXPECT_EQ(std::strtod(valueOf(c, "--fov").c_str(), nullptr), cam.fovy);
  EXPECT_EQ(std::strtod(valueOf(c, "--aspect").c_str(), nullptr), cam.aspect);
  EXPECT_EQ(std::strtod(valueOf(c, "--near").c_str(), nullptr), cam.near);
  EXPECT_EQ(std::strtod(valueOf(c, "--far").c_str(), nullptr), cam.far);
  EXPECT_EQ(std::strtod(valueOf(c, "--angle").c_str(), nullptr), s.angle);
  EXPECT_EQ(c.find("--settings"), std::string::npos);
  EXPECT_EQ(c.find("--no-fit"), std::string::npos);
}

TEST(FrameCommand, FitIsTurnedOffCullingSaidEitherWayAndOddNamesQuoted) {
  SceneSettings s = test::tinySettings(32);
  s.fit = true;
  Camera cam;
  cam.eye = Vec3(0, 0, 2);
  cam.up = Vec3(0, 1, 0);
  ViewState state;
  state.cull = false;
  const std::string c =
      frameCommand("my model's.obj", std::filesystem::path("set tings.json"), s, state, cam);
  EXPECT_EQ(c.rfind("zrender 'my model'\\''s.obj' --settings 'set tings.json' --alg zbuffer", 0),
            0u)
      << c;
  EXPECT_NE(c.find(" --no-cull "), std::string::npos) << c;
  EXPECT_EQ(c.substr(c.size() - 9), " --no-fit") << c;
}

}  // namespace
}  // namespace zrender
