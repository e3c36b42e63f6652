// libzrender_models.so: the model formats other than OBJ, read by assimp
// (io/models/ModelPlugin.hpp). A plugin because linking assimp costs every run of zrender about 5
// ms at start (docs/design.md, Plugins), and most runs read OBJ.

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/models/ModelPlugin.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

namespace {

// The files assimp opens: the model itself from the bytes the caller read, and the files it
// names (glTF's buffers and images) only when they are regular files beside it, so that a
// model cannot make zrender read a device or a pipe.
class ModelFiles : public Assimp::DefaultIOSystem {
 public:
  ModelFiles(std::string path, std::string_view bytes, bool filesBeside)
      : path_(std::move(path)), bytes_(bytes), filesBeside_(filesBeside) {}

  bool Exists(const char* file) const override {
    if (path_ == file) return true;
    return filesBeside_ && isRegularFile(file);
  }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (mode == nullptr || mode[0] != 'r') return nullptr;
    if (path_ == file) {
      return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(bytes_.data()),
                                        bytes_.size());
    }
    if (!filesBeside_ || !isRegularFile(file)) return nullptr;
    return DefaultIOSystem::Open(file, mode);
  }

 private:
  static bool isRegularFile(const char* file) {
    struct stat st {};
    return ::stat(file, &st) == 0 && S_ISREG(st.st_mode);
  }

  std::string path_;
  std::string_view bytes_;
  bool filesBeside_;
};

class SceneConverter {
 public:
  SceneConverter(const aiScene& scene, ModelFormat format, const std::string& path, Mesh& mesh,
                 Warnings& warnings)
      : scene_(scene), format_(format), path_(path), mesh_(mesh), warnings_(warnings) {}

  void convert() {
    convertMaterials();
    mesh_.faceStart.push_back(0);
    if (scene_.mRootNode != nullptr) visit(*scene_.mRootNode, Mat4::eye());
    if (!hasColors_) mesh_.faceColors.clear();
  }

 private:
  // OFF has no materials: none, so that its faces take zrender's default as OBJ's do (assimp
  // gives it a 0.6 gray one).
  bool formatHasMaterials() const { return format_ != ModelFormat::Off; }

  void convertMaterials() {
    materialIndex_.assign(scene_.mNumMaterials, -1);
    if (!formatHasMaterials()) return;
    // assimp's glTF importer appends a default material for the primitives that have none:
    // those are drawn with zrender's default, as an OBJ face without usemtl.
    const unsigned count = format_ == ModelFormat::Gltf && scene_.mNumMaterials > 0
                               ? scene_.mNumMaterials - 1
                               : scene_.mNumMaterials;
    for (unsigned i = 0; i < count; ++i) {
      const aiMaterial& source = *scene_.mMaterials[i];
      aiString name;
      source.Get(AI_MATKEY_NAME, name);
      if (std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0) continue;
      Material material;
      material.name = name.C_Str();
      aiColor4D color;
      if (source.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
          source.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
        material.diffuse = cv::Vec3f(unit(color.r), unit(color.g), unit(color.b));
      }
      aiString texture;
      if (source.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
          source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS) {
        setTexture(material, texture.C_Str());
      }
      material.textureTimesDiffuse = format_ == ModelFormat::Gltf;
      materialIndex_[i] = int32_t(mesh_.materials.size());
      mesh_.materials.push_back(std::move(material));
    }
  }

  static float unit(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

  void setTexture(Material& material, const char* name) {
    if (const aiTexture* embedded = scene_.GetEmbeddedTexture(name)) {
      material.diffuseTexture = path_ + "#" + name;
      if (embedded->mHeight == 0) {  // an image file's bytes (PNG, JPEG): mWidth of them
        const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
        material.embeddedImage.assign(bytes, bytes + embedded->mWidth);
      } else if (uint64_t(embedded->mWidth) * embedded->mHeight > kMaxImagePixels) {
        warnings_.push_back(material.diffuseTexture + ": texture is too large (over " +
                            std::to_string(kMaxImagePixels) + " pixels) (ignored)");
        material.diffuseTexture.clear();
      } else {  // mWidth x mHeight texels, B, G, R, A bytes each
        material.embeddedTexels.create(int(embedded->mHeight), int(embedded->mWidth), CV_8UC3);
        for (int y = 0; y < material.embeddedTexels.rows; ++y) {
          for (int x = 0; x < material.embeddedTexels.cols; ++x) {
            const aiTexel& t = embedded->pcData[size_t(y) * embedded->mWidth + size_t(x)];
            material.embeddedTexels.at<cv::Vec3b>(y, x) = cv::Vec3b(t.b, t.g, t.r);
          }
        }
      }
      return;
    }
    // A file beside the model (glTF's uri, FBX's and Collada's file names).
    std::string relative = name;
    for (char& c : relative) {
      if (c == '\\') c = '/';
    }
    const std::string folder = path_.substr(0, path_.find_last_of('/') + 1);
    const std::string file = !relative.empty() && relative[0] == '/' ? relative : folder + relative;
    struct stat st {};
    if (::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
      material.diffuseTexture = file;
    } else {
      warnings_.push_back(path_ + ": texture '" + name + "' not found");
    }
  }

  // Nodes depth first, a node before its children, each in the file's order; a node's meshes
  // in its order, each mesh's faces in the file's order.
  void visit(const aiNode& node, const Mat4& parent) {
    Mat4 local;
    const aiMatrix4x4& m = node.mTransformation;
    const float* rows[4] = {&m.a1, &m.b1, &m.c1, &m.d1};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) local(r, c) = double(rows[r][c]);
    const Mat4 world = parent * local;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      if (node.mMeshes[i] < scene_.mNumMeshes) addMesh(*scene_.mMeshes[node.mMeshes[i]], world);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) visit(*node.mChildren[i], world);
  }

  void addMesh(const aiMesh& source, const Mat4& world) {
    const bool identity = world == Mat4::eye();
    // Normals go with the inverse transpose of the node's matrix (its 3 x 3 part).
    const cv::Matx33d linear = world.get_minor<3, 3>(0, 0);
    const cv::Matx33d normalMatrix = identity ? cv::Matx33d::eye() : linear.inv().t();
    const bool normals = source.HasNormals();
    const bool uvs = source.HasTextureCoords(0);
    const bool colors = source.HasVertexColors(0);
    std::vector<int32_t> position(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      Vec3 world3(p.x, p.y, p.z);
      if (!identity) world3 = transformPoint(world, world3);
      position[v] = int32_t(mesh_.positions.size());
      mesh_.positions.push_back(world3);
    }
    const int32_t firstNormal = int32_t(mesh_.normals.size());
    if (normals) {
      for (unsigned v = 0; v < source.mNumVertices; ++v) {
        const aiVector3D& n = source.mNormals[v];
        mesh_.normals.push_back(identity ? Vec3(n.x, n.y, n.z)
                                         : normalMatrix * Vec3(n.x, n.y, n.z));
      }
    }
    const int32_t firstUv = int32_t(mesh_.texcoords.size());
    if (uvs) {
      for (unsigned v = 0; v < source.mNumVertices; ++v) {
        const aiVector3D& t = source.mTextureCoords[0][v];
        mesh_.texcoords.emplace_back(t.x, t.y);
      }
    }
    size_t corners = 0;
    for (unsigned f = 0; f < source.mNumFaces; ++f) corners += source.mFaces[f].mNumIndices;
    mesh_.corners.reserve(mesh_.corners.size() + corners);
    mesh_.faceStart.reserve(mesh_.faceStart.size() + source.mNumFaces);
    mesh_.faceMaterial.reserve(mesh_.faceMaterial.size() + source.mNumFaces);
    mesh_.faceColors.reserve(mesh_.faceColors.size() + source.mNumFaces);
    const int32_t material =
        source.mMaterialIndex < materialIndex_.size() ? materialIndex_[source.mMaterialIndex] : -1;
    const cv::Vec3f base =
        material >= 0 ? mesh_.materials[size_t(material)].diffuse : cv::Vec3f(0.8f, 0.8f, 0.8f);
    hasColors_ |= colors;
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      cv::Vec3f color(0, 0, 0);
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        const unsigned v = face.mIndices[i];
        if (v >= source.mNumVertices) continue;  // assimp's validation refuses these
        Corner corner;
        corner.position = position[v];
        if (normals) corner.normal = firstNormal + int32_t(v);
        if (uvs) corner.texcoord = firstUv + int32_t(v);
        mesh_.corners.push_back(corner);
        if (colors) {
          const aiColor4D& c = source.mColors[0][v];
          color += cv::Vec3f(unit(c.r), unit(c.g), unit(c.b));
        }
      }
      mesh_.faceStart.push_back(uint32_t(mesh_.corners.size()));
      mesh_.faceMaterial.push_back(material);
      if (colors && face.mNumIndices > 0) color *= 1.0f / float(face.mNumIndices);
      mesh_.faceColors.push_back(colors ? color : base);
    }
  }

  const aiScene& scene_;
  ModelFormat format_;
  const std::string& path_;
  Mesh& mesh_;
  Warnings& warnings_;
  std::vector<int32_t> materialIndex_;  // per assimp material: index into mesh_.materials
  bool hasColors_ = false;
};

// What a file that makes assimp ask for more memory than there is, or than the budget zrender
// gives a model (io/models/ModelLoader.cpp), gets said about it: assimp sizes some arrays by
// counts in the file before it reads them, and grows some without end on damaged input.
constexpr const char* kTooLarge =
    "it asks for more memory than zrender allows a model reader (is it damaged?)";

class AssimpModels final : public ModelPlugin {
 public:
  bool read(const std::string& path, std::string_view bytes, ModelFormat format, bool filesBeside,
            Mesh& mesh, Warnings& warnings, std::string& error) override {
    try {
      Assimp::Importer importer;
      // No logger is attached: assimp's log is process-wide, and its messages would reach the
      // terminal; a failure's reason comes back through GetErrorString().
      // assimp picks its glTF reader by the name: .glb for the binary form, .gltf for JSON.
      // The name it reads is the file's with the extension its content calls for, in the same
      // folder, so that the files it names are found beside it.
      std::string name = path;
      if (format == ModelFormat::Gltf) {
        const size_t dot = name.find_last_of('.'), slash = name.find_last_of('/');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
          name.resize(dot);
        name += bytes.substr(0, 4) == "glTF" ? ".glb" : ".gltf";
      }
      importer.SetIOHandler(new ModelFiles(name, bytes, filesBeside));
      importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
      const aiScene* scene = importer.ReadFile(name, aiProcess_ValidateDataStructure);
      if (scene == nullptr) {
        error = importer.GetErrorString();
        if (error.empty()) error = "assimp read nothing";
        if (error == "std::bad_alloc") error = kTooLarge;  // caught inside ReadFile
        return false;
      }
      mesh = Mesh();
      SceneConverter(*scene, format, path, mesh, warnings).convert();
      return true;
    } catch (const std::bad_alloc&) {
      error = kTooLarge;
      return false;
    } catch (const std::exception& e) {
      error = e.what();
      return false;
    }
  }
};

}  // namespace

}  // namespace zrender

// assimp 5.2 as Debian builds it checks its invariants with ai_assert, which damaged files reach
// (a binary FBX cut inside a token: "begin <= cursor"), and its aiAssertViolation ends the process.
// This definition takes the place of assimp's: the plugin comes before libassimp.so in the scope
// of the dlopen that loads both, so assimp's calls resolve here. It throws instead, and
// Importer::ReadFile, which catches what its readers throw, reports the file as unreadable.
namespace Assimp {
__attribute__((visibility("default"))) void aiAssertViolation(const char* expression,
                                                              const char* file, int line) {
  const char* slash = std::strrchr(file, '/');
  throw std::runtime_error(std::string("assimp's own check failed: ") + expression + " (" +
                           (slash ? slash + 1 : file) + ":" + std::to_string(line) +
                           "; is it damaged?)");
}
}  // namespace Assimp

extern "C" __attribute__((visibility("default"))) void* zrenderModelPlugin() {
  static zrender::AssimpModels plugin;
  return &plugin;
}
