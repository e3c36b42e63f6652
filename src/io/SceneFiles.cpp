#include "zrender/io/SceneFiles.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "zrender/base/SideBySide.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/models/ModelLoader.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// A scene's face ids stop below the background's.
static_assert(kMaxSceneFaces == kBackgroundId);

namespace {

// glTF's base color is its texture's texel times baseColorFactor: applied to the texels once.
cv::Mat timesDiffuse(cv::Mat texture, const Material& material) {
  if (texture.empty() || !material.textureTimesDiffuse ||
      material.diffuse == cv::Vec3f(1.0f, 1.0f, 1.0f))
    return texture;
  cv::Mat product;
  cv::multiply(texture, cv::Scalar(material.diffuse[2], material.diffuse[1], material.diffuse[0]),
               product);
  return product;
}

}  // namespace

cv::Mat loadTexture(const SceneSettings& settings, const Mesh& mesh, Warnings& warnings) {
  std::string texturePath;
  const Material* material = nullptr;
  if (settings.texture) {
    texturePath = settings.texture->string();
  } else {
    for (const Material& m : mesh.materials) {
      if (!m.embeddedTexels.empty()) return timesDiffuse(m.embeddedTexels, m);
      if (!m.embeddedImage.empty()) {
        std::string error;
        cv::Mat texture = decodeColorImage(m.embeddedImage, error);
        if (texture.empty())
          warnings.push_back(m.diffuseTexture + ": texture " + error + " (ignored)");
        return timesDiffuse(texture, m);
      }
      if (!m.diffuseTexture.empty()) {
        texturePath = m.diffuseTexture;
        material = &m;
        break;
      }
    }
  }
  if (texturePath.empty()) return cv::Mat();
  std::string error;
  cv::Mat texture = decodeColorImage(texturePath, error);
  if (material != nullptr) texture = timesDiffuse(texture, *material);
  // The scene's own `texture` key is a value the user chose: bad input. A material's map_Kd
  // comes with a model from elsewhere, whose textures often go missing: drawn without.
  if (texture.empty() && settings.texture)
    throw InputError(texturePath + ": texture " + error + " (key 'texture' of scene '" +
                     settings.name + "')");
  if (texture.empty()) warnings.push_back(texturePath + ": texture " + error + " (ignored)");
  return texture;
}

Scene loadScene(const SceneSettings& settings, Warnings& warnings, const Threads* threads) {
  if (!settings.objects.empty()) return loadObjects(settings, warnings, threads);
  std::shared_ptr<const Mesh> mesh;
  cv::Mat texture;
  if (settings.texture) {
    // Warnings in the order of loading one after the other: the model's, then the texture's.
    Warnings textureWarnings;
    sideBySide(threads, 2, [&](size_t job) {
      if (job == 0) {
        mesh = std::make_shared<const Mesh>(loadModel(settings.modelPath, warnings, threads));
      } else {
        texture = loadTexture(settings, Mesh(), textureWarnings);
      }
    });
    warnings.insert(warnings.end(), textureWarnings.begin(), textureWarnings.end());
  } else {  // the texture may be named by the model's materials: after the model
    mesh = std::make_shared<const Mesh>(loadModel(settings.modelPath, warnings, threads));
    texture = loadTexture(settings, *mesh, warnings);
  }
  return makeScene(settings, std::move(mesh), std::move(texture));
}

Scene loadObjects(const SceneSettings& settings, Warnings& warnings, const Threads* threads) {
  // Each distinct file once, in the order of first use; the objects share what they name.
  std::vector<std::shared_ptr<const Mesh>> meshes;
  std::vector<std::filesystem::path> paths;
  std::vector<uint32_t> objectModel;
  for (const SceneObject& object : settings.objects) {
    const auto known = std::find(paths.begin(), paths.end(), object.path);
    if (known != paths.end()) {
      objectModel.push_back(uint32_t(known - paths.begin()));
      continue;
    }
    objectModel.push_back(uint32_t(paths.size()));
    paths.push_back(object.path);
    meshes.push_back(std::make_shared<const Mesh>(loadModel(object.path, warnings, threads)));
  }
  SceneMeshes joined = joinMeshes(meshes);
  meshes.clear();  // the joined mesh holds them now (or shares the only one)
  cv::Mat texture = loadTexture(settings, *joined.mesh, warnings);
  return makeScene(settings, std::move(joined), objectModel, std::move(texture));
}

}  // namespace zrender
