#include "zrender/view/FrameCommand.hpp"

#include <cstdio>

namespace zrender {

namespace {

// `text` as one shell word: as it is when it is made of safe characters, else in single quotes.
std::string shellWord(const std::string& text) {
  bool safe = !text.empty();
  for (const char c : text) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!plain && std::string("_-./,:=+%@").find(c) == std::string::npos) safe = false;
  }
  if (safe) return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string exact(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string exact(const Vec3& v) {
  return exact(v[0]) + "," + exact(v[1]) + "," + exact(v[2]);
}

}  // namespace

std::string frameCommand(const std::string& scene,
                         const std::optional<std::filesystem::path>& settingsFile,
                         const SceneSettings& settings, const ViewState& state,
                         const Camera& camera) {
  std::string command = "zrender " + shellWord(scene);
  if (settingsFile) command += " --settings " + shellWord(settingsFile->string());
  command += " --alg " + state.algorithm + " --shading " + shadingModeName(state.shading) +
             " --msaa " + std::to_string(state.msaa) + (state.cull ? " --cull" : " --no-cull");
  command +=
      " --width " + std::to_string(camera.width) + " --height " + std::to_string(camera.height);
  command += " --eye " + exact(camera.eye) + " --target " + exact(camera.target) + " --up " +
             exact(camera.up);
  command += " --fov " + exact(camera.fovy) + " --aspect " + exact(camera.aspect) + " --near " +
             exact(camera.near) + " --far " + exact(camera.far);
  command += " --angle " + exact(settings.angle) + " --axis " + exact(settings.axis);
  if (settings.fit) command += " --no-fit";
  return command;
}

}  // namespace zrender
