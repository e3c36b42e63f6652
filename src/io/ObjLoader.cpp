#include "zrender/io/ObjLoader.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

#include "zrender/io/ObjScanner.hpp"

namespace zrender {

namespace {

namespace fs = std::filesystem;

// A read-only streambuf over text already in memory, so tinyobjloader reads it without a copy.
class MemoryBuf : public std::streambuf {
 public:
  explicit MemoryBuf(std::string_view text) {
    char* p = const_cast<char*>(text.data());  // never written: no put area, no putback
    setg(p, p, p + text.size());
  }
};

// Opens the .mtl files named by mtllib, relative to the OBJ's folder. A missing one is a warning;
// only regular files are opened, so "mtllib /dev/zero" or a folder cannot hang the loader.
class MtlReader : public tinyobj::MaterialReader {
 public:
  MtlReader(const std::string& file, const fs::path& folder, Warnings& warnings)
      : file_(file), folder_(folder), warnings_(warnings) {}

  bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* matMap, std::string* warn,
                  std::string* err) override {
    const std::string name(trim(matId));
    if (name.empty()) return false;
    const fs::path path = folder_ / name;
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    if (!in.is_open() || !in) {
      if (reported_.insert(name).second) {
        warnings_.push_back(file_ + ": material file '" + quoteName(name) + "' not found");
      }
      missing_ = true;
      return false;
    }
    tinyobj::LoadMtl(matMap, materials, &in, warn, err);
    return true;
  }

  bool missing() const { return missing_; }

 private:
  const std::string& file_;
  fs::path folder_;
  Warnings& warnings_;
  std::unordered_set<std::string> reported_;
  bool missing_ = false;
};

// Receives tinyobjloader's callbacks, which arrive in file order, one per statement. Values come
// as tinyobj::real_t: float with the tinyobjloader::tinyobjloader target, double with
// tinyobjloader::tinyobjloader_double; either is widened to double here.
struct Builder {
  Mesh mesh;
  std::vector<tinyobj::material_t> materials;
  std::unordered_map<std::string, int32_t> materialIndex;
  std::vector<std::string> unknownMaterials;  // each name once, in order of first use
  std::unordered_set<std::string> unknownSeen;
  int32_t currentMaterial = -1;
  // Ordinal of the first v / vt / vn statement with a non-finite value (overflow), or npos.
  size_t firstNonFinite[3] = {std::string::npos, std::string::npos, std::string::npos};

  void noteFinite(int kind, bool finite, size_t ordinal) {
    if (!finite && firstNonFinite[kind] == std::string::npos) firstNonFinite[kind] = ordinal;
  }

  // OBJ index (1-based, or negative = relative to the `count` attributes so far) to 0-based;
  // tinyobjloader passes 0 for an absent vt or vn. The scan has checked the range.
  static int32_t resolve(int index, size_t count) {
    if (index > 0) return index - 1;
    if (index < 0) return static_cast<int32_t>(static_cast<int64_t>(count) + index);
    return -1;
  }

  static void onVertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                       tinyobj::real_t /*w*/) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(0, std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
                 b.mesh.positions.size());
    b.mesh.positions.emplace_back(x, y, z);
  }

  static void onTexcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t /*w*/) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(1, std::isfinite(u) && std::isfinite(v), b.mesh.texcoords.size());
    b.mesh.texcoords.emplace_back(u, v);
  }

  static void onNormal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(2, std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
                 b.mesh.normals.size());
    b.mesh.normals.emplace_back(x, y, z);
  }

  static void onFace(void* self, tinyobj::index_t* indices, int count) {
    auto& b = *static_cast<Builder*>(self);
    Mesh& m = b.mesh;
    for (int i = 0; i < count; ++i) {
      Corner c;
      c.position = resolve(indices[i].vertex_index, m.positions.size());
      c.texcoord = resolve(indices[i].texcoord_index, m.texcoords.size());
      c.normal = resolve(indices[i].normal_index, m.normals.size());
      m.corners.push_back(c);
    }
    m.faceStart.push_back(static_cast<uint32_t>(m.corners.size()));
    m.faceMaterial.push_back(b.currentMaterial);
  }

  // Looked up by our own trimmed name: tinyobjloader keeps trailing blanks of a usemtl line.
  static void onUseMaterial(void* self, const char* name, int /*tinyobjId*/) {
    auto& b = *static_cast<Builder*>(self);
    const std::string key(trim(name));
    const auto it = b.materialIndex.find(key);
    b.currentMaterial = it == b.materialIndex.end() ? -1 : it->second;
    if (it == b.materialIndex.end() && !key.empty() && b.unknownSeen.insert(key).second) {
      b.unknownMaterials.push_back(key);
    }
  }

  // Called after each mtllib with every material loaded so far.
  static void onMaterials(void* self, const tinyobj::material_t* materials, int count) {
    auto& b = *static_cast<Builder*>(self);
    b.materials.assign(materials, materials + count);
    b.materialIndex.clear();
    for (int i = 0; i < count; ++i) {
      b.materialIndex.emplace(std::string(trim(materials[i].name)), i);  // first one wins
    }
  }
};

float unitClamp(double v) {
  return v > 0.0 ? (v < 1.0 ? static_cast<float>(v) : 1.0f) : 0.0f;
}

// map_Kd relative to the OBJ's folder ("" if the file does not exist). Exporters on Windows
// write backslashes, so those are tried as slashes when the name as written is not found.
std::string resolveTexture(const fs::path& folder, const std::string& name) {
  std::error_code ec;
  fs::path path = folder / name;
  if (fs::is_regular_file(path, ec)) return path.string();
  if (name.find('\\') != std::string::npos) {
    std::string slashed = name;
    for (char& c : slashed) {
      if (c == '\\') c = '/';
    }
    path = folder / slashed;
    if (fs::is_regular_file(path, ec)) return path.string();
  }
  return "";
}

std::string readFile(const fs::path& path, const std::string& file) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(file + ": cannot open file (it is a folder)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file + ": cannot open file");
  std::string text;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size > 0 && in) {
    text.resize(static_cast<size_t>(size));
    in.read(text.data(), size);
    if (in.gcount() != size) throw InputError(file + ": cannot read file");
  } else {
    // Not seekable (a pipe): read it as a stream.
    in.clear();
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  if (in.bad()) throw InputError(file + ": cannot read file");
  return text;
}

}  // namespace

Mesh loadObj(const std::filesystem::path& path, Warnings& warnings) {
  return loadObjFromText(readFile(path, path.string()), path, warnings);
}

Mesh loadObjFromText(const std::string& data, const std::filesystem::path& path,
                     Warnings& warnings) {
  const std::string file = path.string();
  std::string_view text(data);
  // tinyobjloader does not skip a UTF-8 byte order mark; the first statement would be lost.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // UTF-16 text reads as lines cut at their NUL bytes, so the scan would only report "no
  // faces"; the byte order mark tells what is really wrong.
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF") {
    throw InputError(file + ":1: UTF-16 text is not supported (save the file as UTF-8 or ASCII)");
  }

  const ObjCounts counts = scanObj(file, text);
  if (counts.faces == 0) throw InputError(file + ": model has no faces");

  // The callback API rather than ObjReader/LoadObj, whose shapes cannot hold this mesh: they
  // store a face's corner count in an unsigned char (faces above 255 corners wrap), drop faces
  // below 3 corners (shifting every later face id), and split faces into shapes by g/o/usemtl.
  // The callbacks arrive one per statement in file order, with the corner count as an int.
  Builder builder;
  Mesh& mesh = builder.mesh;
  mesh.positions.reserve(counts.attributes[0]);
  mesh.texcoords.reserve(counts.attributes[1]);
  mesh.normals.reserve(counts.attributes[2]);
  mesh.corners.reserve(counts.corners);
  mesh.faceStart.reserve(counts.faces + 1);
  mesh.faceMaterial.reserve(counts.faces);
  mesh.faceStart.push_back(0);

  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = &Builder::onVertex;
  callbacks.texcoord_cb = &Builder::onTexcoord;
  callbacks.normal_cb = &Builder::onNormal;
  callbacks.index_cb = &Builder::onFace;
  callbacks.usemtl_cb = &Builder::onUseMaterial;
  callbacks.mtllib_cb = &Builder::onMaterials;

  const fs::path folder = path.parent_path();
  MtlReader mtlReader(file, folder, warnings);
  MemoryBuf buffer(text);
  std::istream stream(&buffer);
  std::string tinyWarnings, tinyErrors;  // ours are more precise; these are dropped
  tinyobj::LoadObjWithCallback(stream, callbacks, &builder, &mtlReader, &tinyWarnings, &tinyErrors);

  // The scan and tinyobjloader split lines and match statements the same way; if they ever
  // disagreed, the indices checked by the scan would not be the ones stored.
  if (mesh.positions.size() != counts.attributes[0] ||
      mesh.texcoords.size() != counts.attributes[1] ||
      mesh.normals.size() != counts.attributes[2] || mesh.faceCount() != counts.faces ||
      mesh.corners.size() != counts.corners) {
    throw std::logic_error(file + ": OBJ scan and tinyobjloader disagree on the statements");
  }
  for (const Corner& c : mesh.corners) {
    if (c.position < 0 || static_cast<size_t>(c.position) >= mesh.positions.size() ||
        c.texcoord < -1 || c.texcoord >= static_cast<int64_t>(mesh.texcoords.size()) ||
        c.normal < -1 || c.normal >= static_cast<int64_t>(mesh.normals.size())) {
      throw std::logic_error(file + ": face index escaped the OBJ scan");
    }
  }

  // Numbers that pass the scan can still overflow to infinity (1e400, 400 digits); the
  // statement's ordinal leads back to its line.
  const ObjStatement kinds[] = {ObjStatement::kPosition, ObjStatement::kTexcoord,
                                ObjStatement::kNormal};
  for (int k = 0; k < 3; ++k) {
    if (builder.firstNonFinite[k] == std::string::npos) continue;
    const size_t line = objStatementLine(text, kinds[k], builder.firstNonFinite[k]);
    throw InputError(file + ":" + std::to_string(line) +
                     ": NaN or infinite coordinate (a number overflows)");
  }

  // After a missing .mtl every usemtl would be unknown; that file's warning says enough.
  if (!mtlReader.missing()) {
    for (const std::string& name : builder.unknownMaterials) {
      warnings.push_back(file + ": material '" + quoteName(name) + "' not found");
    }
  }

  mesh.materials.reserve(builder.materials.size());
  for (const tinyobj::material_t& source : builder.materials) {
    Material material;
    material.name = std::string(trim(source.name));
    material.diffuse = cv::Vec3f(unitClamp(source.diffuse[0]), unitClamp(source.diffuse[1]),
                                 unitClamp(source.diffuse[2]));
    const std::string texture(trim(source.diffuse_texname));
    if (!texture.empty()) {
      material.diffuseTexture = resolveTexture(folder, texture);
      if (material.diffuseTexture.empty()) {
        warnings.push_back(file + ": texture '" + quoteName(texture) + "' not found");
      }
    }
    mesh.materials.push_back(std::move(material));
  }
  return std::move(builder.mesh);  // mesh is a reference into builder: move, not copy
}

}  // namespace zrender
