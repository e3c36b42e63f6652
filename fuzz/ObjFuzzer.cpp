// Fuzz target: OBJ (+ MTL) loading. Whatever the bytes, loadObjFromText returns a mesh whose
// indices are all in range, or throws InputError with a one-line message naming the file; in
// parts of any size, the same mesh or the same message; and a mesh loaded is the one
// tinyobjloader's own parse reads. Anything else (another exception, a crash, a sanitizer
// report) is a bug.
//
// Input: OBJ text, optionally followed by kMtlSeparator and the text of "model.mtl", which is
// written beside the model so that "mtllib model.mtl" finds it.

#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "FuzzSupport.hpp"
#include "support/TinyObjReference.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace {

namespace fs = std::filesystem;
using zrender::fuzz::fail;

constexpr std::string_view kMtlSeparator = "\n#%MTL\n";
// Keeps each execution fast; the loader's cost is linear in the text, so nothing is lost.
constexpr size_t kMaxInput = 1 << 16;

bool finite(const cv::Vec3d& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The invariants of Mesh (Mesh.hpp) that every algorithm relies on without checking.
void checkMesh(const zrender::Mesh& mesh) {
  const size_t faces = mesh.faceCount();
  if (faces == 0) fail("mesh without faces returned");
  if (mesh.faceStart.front() != 0 || mesh.faceStart.back() != mesh.corners.size()) {
    fail("faceStart does not span the corners");
  }
  if (mesh.faceMaterial.size() != faces) fail("faceMaterial size differs from the face count");
  for (size_t f = 0; f < faces; ++f) {
    if (mesh.faceStart[f] > mesh.faceStart[f + 1]) fail("faceStart decreases");
    if (mesh.cornerCount(f) > zrender::kMaxFaceCorners) fail("face above kMaxFaceCorners");
    const int32_t m = mesh.faceMaterial[f];
    if (m < -1 || m >= static_cast<int64_t>(mesh.materials.size())) fail("material out of range");
  }
  for (const zrender::Corner& c : mesh.corners) {
    if (c.position < 0 || static_cast<size_t>(c.position) >= mesh.positions.size() ||
        c.texcoord < -1 || c.texcoord >= static_cast<int64_t>(mesh.texcoords.size()) ||
        c.normal < -1 || c.normal >= static_cast<int64_t>(mesh.normals.size())) {
      fail("corner index out of range");
    }
  }
  for (const auto& p : mesh.positions) {
    if (!finite(p)) fail("non-finite position returned");
  }
  for (const auto& n : mesh.normals) {
    if (!finite(n)) fail("non-finite normal returned");
  }
  for (const auto& t : mesh.texcoords) {
    if (!std::isfinite(t[0]) || !std::isfinite(t[1])) fail("non-finite texcoord returned");
  }
}

// The text parsed in parts of `partBytes` bytes: the same mesh as parsed whole, or the same
// message; and the mesh tinyobjloader's own parse reads.
void checkParts(const std::string& obj, const fs::path& objPath,
                const std::optional<zrender::Mesh>& whole, const std::string& message,
                size_t partBytes) {
  zrender::Warnings warnings;
  try {
    const zrender::Mesh parts =
        zrender::loadObjFromText(obj, objPath, warnings, nullptr, partBytes);
    if (!whole) fail("parsed in parts, loaded what the whole text refused: " + message);
    const std::string difference = zrender::test::meshBitsDifference(parts, *whole);
    if (!difference.empty()) fail("parsed in parts, unlike the whole text: " + difference);
  } catch (const zrender::InputError& e) {
    if (whole)
      fail(std::string("parsed in parts, refused what the whole text loaded: ") + e.what());
    if (e.what() != message) fail(std::string("parsed in parts, another message: ") + e.what());
  }
  if (!whole) return;
  std::string_view text(obj);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // the loader skips it
  const std::string difference =
      zrender::test::geometryDifference(*whole, zrender::test::tinyObjReference(text));
  if (!difference.empty()) fail("unlike tinyobjloader's parse: " + difference);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxInput) return 0;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const size_t separator = input.find(kMtlSeparator);
  const std::string obj(input.substr(0, separator));

  const fs::path& folder = zrender::fuzz::scratchFolder();
  const fs::path objPath = folder / "model.obj";
  const fs::path mtlPath = folder / "model.mtl";
  if (separator != std::string_view::npos) {
    std::ofstream(mtlPath, std::ios::binary | std::ios::trunc)
        << input.substr(separator + kMtlSeparator.size());
  } else {
    std::error_code ec;
    fs::remove(mtlPath, ec);  // exercises the missing-.mtl warning
  }

  zrender::Warnings warnings;
  std::optional<zrender::Mesh> whole;
  std::string message;
  try {
    whole = zrender::loadObjFromText(obj, objPath, warnings);
    checkMesh(*whole);
  } catch (const zrender::InputError& e) {
    message = e.what();
    zrender::fuzz::checkMessage(message, objPath.string() + ":", "error");
  } catch (const std::exception& e) {
    fail(std::string("unexpected exception: ") + e.what());
  }
  checkParts(obj, objPath, whole, message, 1 + size % 61);
  for (const std::string& w : warnings) {
    zrender::fuzz::checkMessage(w, objPath.string() + ":", "warning");
  }
  return 0;
}
