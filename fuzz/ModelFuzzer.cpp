// Fuzz target: the model formats beyond OBJ (io/models/ModelLoader.hpp). The first byte picks
// the format (PLY and STL, read by zrender; OFF and binary glTF, by assimp), the rest is the
// file. Whatever the bytes, readModel either gives a mesh whose every index is in range, or
// throws InputError with a one-line message naming the file; nothing crashes, hangs or prints.

#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include "FuzzSupport.hpp"
#include "zrender/io/models/ModelLoader.hpp"

namespace {

using zrender::fuzz::fail;

constexpr size_t kMaxInput = 1 << 16;

struct Case {
  zrender::ModelFormat format;
  const char* file;
};
const Case kCases[] = {{zrender::ModelFormat::Ply, "fuzz/model.ply"},
                       {zrender::ModelFormat::Stl, "fuzz/model.stl"},
                       {zrender::ModelFormat::Off, "fuzz/model.off"},
                       {zrender::ModelFormat::Gltf, "fuzz/model.glb"}};

void checkMesh(const zrender::Mesh& mesh) {
  if (mesh.faceCount() == 0) fail("a mesh without faces was returned");
  if (mesh.faceMaterial.size() != mesh.faceCount()) fail("one material per face");
  if (!mesh.faceColors.empty() && mesh.faceColors.size() != mesh.faceCount())
    fail("face colors for some faces only");
  if (mesh.faceStart.back() != mesh.corners.size()) fail("faceStart does not end at the corners");
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceStart[f] > mesh.faceStart[f + 1]) fail("faceStart goes back");
    if (mesh.faceMaterial[f] >= int32_t(mesh.materials.size())) fail("material out of range");
  }
  for (const zrender::Corner& c : mesh.corners) {
    if (c.position < 0 || size_t(c.position) >= mesh.positions.size())
      fail("position out of range");
    if (c.normal >= int32_t(mesh.normals.size())) fail("normal out of range");
    if (c.texcoord >= int32_t(mesh.texcoords.size())) fail("texcoord out of range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1 || size > kMaxInput) return 0;
  const Case& c = kCases[data[0] % 4];
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  zrender::Warnings warnings;
  try {
    checkMesh(zrender::readModel(bytes, c.file, c.format, warnings));
  } catch (const zrender::InputError& e) {
    zrender::fuzz::checkMessage(e.what(), std::string(c.file) + ":", "error");
  } catch (const std::exception& e) {
    fail(std::string("unexpected exception: ") + e.what());
  }
  for (const std::string& w : warnings) {
    zrender::fuzz::checkMessage(w, std::string(c.file), "warning");
  }
  return 0;
}
