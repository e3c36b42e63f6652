#include "zrender/io/obj/ObjLoader.hpp"

#include <cstdint>
#include <fstream>
#include <istream>
#include <map>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

#include "zrender/io/files/FileText.hpp"
#include "zrender/io/obj/ObjParser.hpp"
#include "zrender/io/obj/ObjScanner.hpp"

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

// Receives tinyobjloader's callbacks for the usemtl and mtllib lines, which arrive in file
// order, one per statement.
struct MaterialBuilder {
  std::vector<tinyobj::material_t> materials;
  std::unordered_map<std::string, int32_t> materialIndex;
  std::vector<std::string> unknownMaterials;  // each name once, in order of first use
  std::unordered_set<std::string> unknownSeen;
  std::vector<int32_t> used;  // the material each usemtl line selects, -1 for none

  // Looked up by our own trimmed name: tinyobjloader keeps trailing blanks of a usemtl line.
  static void onUseMaterial(void* self, const char* name, int /*tinyobjId*/) {
    auto& b = *static_cast<MaterialBuilder*>(self);
    const std::string key(trim(name));
    const auto it = b.materialIndex.find(key);
    b.used.push_back(it == b.materialIndex.end() ? -1 : it->second);
    if (it == b.materialIndex.end() && !key.empty() && b.unknownSeen.insert(key).second) {
      b.unknownMaterials.push_back(key);
    }
  }

  // Called after each mtllib with every material loaded so far.
  static void onMaterials(void* self, const tinyobj::material_t* materials, int count) {
    auto& b = *static_cast<MaterialBuilder*>(self);
    b.materials.assign(materials, materials + count);
    b.materialIndex.clear();
    for (int i = 0; i < count; ++i) {
      b.materialIndex.emplace(std::string(trim(materials[i].name)), i);  // first one wins
    }
  }
};

// The usemtl and mtllib lines, read by tinyobjloader (which also reads the .mtl files) from a
// text of those lines alone, in file order.
void readMaterialLines(const std::vector<ObjMaterialLine>& lines, MtlReader& mtlReader,
                       MaterialBuilder& builder) {
  if (lines.empty()) return;
  std::string text;
  for (const ObjMaterialLine& line : lines) {
    text.append(line.line);
    text.push_back('\n');
  }
  tinyobj::callback_t callbacks;
  callbacks.usemtl_cb = &MaterialBuilder::onUseMaterial;
  callbacks.mtllib_cb = &MaterialBuilder::onMaterials;
  MemoryBuf buffer(text);
  std::istream stream(&buffer);
  std::string tinyWarnings, tinyErrors;  // ours are more precise; these are dropped
  tinyobj::LoadObjWithCallback(stream, callbacks, &builder, &mtlReader, &tinyWarnings, &tinyErrors);
}

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

}  // namespace

Mesh loadObj(const std::filesystem::path& path, Warnings& warnings, const Threads* threads) {
  const FileText file(path.string());
  return loadObjFromText(file.text(), path, warnings, threads);
}

Mesh loadObjFromText(std::string_view text, const std::filesystem::path& path, Warnings& warnings,
                     const Threads* threads, size_t partBytes) {
  const std::string file = path.string();
  // tinyobjloader does not skip a UTF-8 byte order mark; the first statement would be lost.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // UTF-16 text reads as lines cut at their NUL bytes, so the scan would only report "no
  // faces"; the byte order mark tells what is really wrong.
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF") {
    throw InputError(file + ":1: UTF-16 text is not supported (save the file as UTF-8 or ASCII)");
  }

  // Faces stay polygons, numbered in file order, whatever their corner count: tinyobjloader's
  // shapes cannot hold that (they store a face's corner count in an unsigned char, drop faces
  // below 3 corners and split faces by g/o/usemtl), and it parses one line after another. So
  // the geometry is parsed here, in parts at once (docs/design.md, Loading).
  const ObjLayout layout = layOutObj(text, threads, partBytes);
  Mesh mesh;
  ObjNonFinite nonFinite;
  if (!parseObj(text, layout, threads, mesh, nonFinite)) {
    scanObj(file, text);  // names the first bad line
    throw std::logic_error(file + ": the OBJ parse found a bad statement that the scan did not");
  }
  if (mesh.faceCount() == 0) throw InputError(file + ": model has no faces");

  const fs::path folder = path.parent_path();
  MtlReader mtlReader(file, folder, warnings);
  MaterialBuilder builder;
  readMaterialLines(layout.materialLines, mtlReader, builder);
  if (builder.used.size() != layout.uses)
    throw std::logic_error(file + ": tinyobjloader and the parse disagree on the usemtl lines");
  for (int32_t& material : mesh.faceMaterial) material = material < 0 ? -1 : builder.used[material];

  // Numbers that pass the scan can still overflow to infinity (1e400, 400 digits); the
  // statement's ordinal leads back to its line.
  const ObjStatement kinds[] = {ObjStatement::kPosition, ObjStatement::kTexcoord,
                                ObjStatement::kNormal};
  for (int k = 0; k < 3; ++k) {
    if (nonFinite.ordinal[k] == std::string::npos) continue;
    const size_t line = objStatementLine(text, kinds[k], nonFinite.ordinal[k]);
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
  return mesh;
}

}  // namespace zrender
