#include "support/TinyObjReference.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#include "zrender/io/obj/ObjScanner.hpp"

namespace zrender::test {

namespace {

struct Builder {
  TinyObjGeometry out;
  std::string use;

  // 1-based, or negative: back from the `count` attributes so far; 0 (absent) to -1.
  static int32_t resolve(int index, size_t count) {
    if (index > 0) return index - 1;
    if (index < 0) return static_cast<int32_t>(static_cast<int64_t>(count) + index);
    return -1;
  }

  static void onVertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                       tinyobj::real_t) {
    static_cast<Builder*>(self)->out.mesh.positions.emplace_back(x, y, z);
  }
  static void onTexcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
    static_cast<Builder*>(self)->out.mesh.texcoords.emplace_back(u, v);
  }
  static void onNormal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
    static_cast<Builder*>(self)->out.mesh.normals.emplace_back(x, y, z);
  }
  static void onFace(void* self, tinyobj::index_t* indices, int count) {
    auto& b = *static_cast<Builder*>(self);
    Mesh& m = b.out.mesh;
    for (int i = 0; i < count; ++i) {
      Corner c;
      c.position = resolve(indices[i].vertex_index, m.positions.size());
      c.texcoord = resolve(indices[i].texcoord_index, m.texcoords.size());
      c.normal = resolve(indices[i].normal_index, m.normals.size());
      m.corners.push_back(c);
    }
    m.faceStart.push_back(static_cast<uint32_t>(m.corners.size()));
    m.faceMaterial.push_back(-1);
    b.out.faceUse.push_back(b.use);
  }
  static void onUseMaterial(void* self, const char* name, int) {
    static_cast<Builder*>(self)->use = std::string(trim(name));
  }
};

bool near(double parsed, double reference) {
  return !std::isfinite(reference) ||
         std::abs(parsed - reference) <= 1e-12 * std::abs(reference) + 1e-300;
}

template <int N>
std::string attributeDifference(const std::vector<cv::Vec<double, N>>& parsed,
                                const std::vector<cv::Vec<double, N>>& reference,
                                const char* what) {
  if (parsed.size() != reference.size())
    return std::string(what) + " count " + std::to_string(parsed.size()) + " against " +
           std::to_string(reference.size());
  for (size_t i = 0; i < parsed.size(); ++i) {
    for (int k = 0; k < N; ++k) {
      if (!near(parsed[i][k], reference[i][k])) {
        std::ostringstream out;
        out.precision(17);
        out << what << " " << i << "[" << k << "]: " << parsed[i][k] << " against "
            << reference[i][k];
        return out.str();
      }
    }
  }
  return "";
}

}  // namespace

std::string geometryDifference(const Mesh& parsed, const TinyObjGeometry& reference) {
  const Mesh& r = reference.mesh;
  std::string d = attributeDifference(parsed.positions, r.positions, "position");
  if (d.empty()) d = attributeDifference(parsed.texcoords, r.texcoords, "texcoord");
  if (d.empty()) d = attributeDifference(parsed.normals, r.normals, "normal");
  if (!d.empty()) return d;
  if (parsed.faceStart != r.faceStart) return "faceStart differs";
  if (parsed.corners.size() != r.corners.size()) return "corner count differs";
  for (size_t i = 0; i < parsed.corners.size(); ++i) {
    const Corner& a = parsed.corners[i];
    const Corner& b = r.corners[i];
    if (a.position != b.position || a.texcoord != b.texcoord || a.normal != b.normal)
      return "corner " + std::to_string(i) + " differs";
  }
  return "";
}

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

std::string meshBitsDifference(const Mesh& a, const Mesh& b) {
  if (!sameBytes(a.positions, b.positions)) return "positions differ";
  if (!sameBytes(a.texcoords, b.texcoords)) return "texcoords differ";
  if (!sameBytes(a.normals, b.normals)) return "normals differ";
  if (!sameBytes(a.corners, b.corners)) return "corners differ";
  if (a.faceStart != b.faceStart) return "faceStart differs";
  if (a.faceMaterial != b.faceMaterial) return "faceMaterial differs";
  if (a.materials.size() != b.materials.size()) return "material count differs";
  return "";
}

TinyObjGeometry tinyObjReference(std::string_view text) {
  Builder builder;
  builder.out.mesh.faceStart.push_back(0);
  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = &Builder::onVertex;
  callbacks.texcoord_cb = &Builder::onTexcoord;
  callbacks.normal_cb = &Builder::onNormal;
  callbacks.index_cb = &Builder::onFace;
  callbacks.usemtl_cb = &Builder::onUseMaterial;
  std::istringstream stream{std::string(text)};
  std::string warnings, errors;
  tinyobj::LoadObjWithCallback(stream, callbacks, &builder, nullptr, &warnings, &errors);
  return builder.out;
}

}  // namespace zrender::test
