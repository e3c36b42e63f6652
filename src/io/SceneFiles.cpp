#include "zrender/io/SceneFiles.hpp"

#include <algorithm>
#include <map>
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

cv::Mat loadTexture(const SceneSettings& settings) {
  if (!settings.texture) return cv::Mat();
  const std::string path = settings.texture->string();
  std::string error;
  cv::Mat texture = decodeColorImage(path, error);
  // The scene's own `texture` key is a value the user chose: bad input.
  if (texture.empty())
    throw InputError(path + ": texture " + error + " (key 'texture' of scene '" + settings.name +
                     "')");
  return texture;
}

std::vector<cv::Mat> loadMaterialTextures(const Mesh& mesh, Warnings& warnings) {
  std::vector<cv::Mat> textures(mesh.materials.size());
  std::map<std::string, cv::Mat> files;  // each file once, as read (empty: could not be)
  for (size_t i = 0; i < mesh.materials.size(); ++i) {
    const Material& m = mesh.materials[i];
    cv::Mat texels;
    if (!m.embeddedTexels.empty()) {
      texels = m.embeddedTexels;
    } else if (!m.embeddedImage.empty()) {
      std::string error;
      texels = decodeColorImage(m.embeddedImage, error);
      if (texels.empty())
        warnings.push_back(m.diffuseTexture + ": texture " + error + " (ignored)");
    } else if (!m.diffuseTexture.empty()) {
      const auto known = files.find(m.diffuseTexture);
      if (known != files.end()) {
        texels = known->second;
      } else {
        // A material's map_Kd comes with a model from elsewhere, whose textures often go
        // missing: drawn without.
        std::string error;
        texels = decodeColorImage(m.diffuseTexture, error);
        if (texels.empty())
          warnings.push_back(m.diffuseTexture + ": texture " + error + " (ignored)");
        files.emplace(m.diffuseTexture, texels);
      }
    }
    textures[i] = timesDiffuse(texels, m);
  }
  return textures;
}

Scene loadScene(const SceneSettings& settings, Warnings& warnings, const Threads* threads) {
  if (!settings.objects.empty()) return loadObjects(settings, warnings, threads);
  std::shared_ptr<const Mesh> mesh;
  cv::Mat texture;
  if (settings.texture) {
    sideBySide(threads, 2, [&](size_t job) {
      if (job == 0) {
        mesh = std::make_shared<const Mesh>(loadModel(settings.modelPath, warnings, threads));
      } else {
        texture = loadTexture(settings);
      }
    });
    return makeScene(settings, std::move(mesh), std::move(texture));
  }
  // The textures are named by the model's materials: after the model.
  mesh = std::make_shared<const Mesh>(loadModel(settings.modelPath, warnings, threads));
  std::vector<cv::Mat> materialTextures = loadMaterialTextures(*mesh, warnings);
  Scene scene = makeScene(settings, std::move(mesh));
  scene.materialTextures = std::move(materialTextures);
  return scene;
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
  cv::Mat texture = loadTexture(settings);
  std::vector<cv::Mat> materialTextures;
  if (texture.empty()) materialTextures = loadMaterialTextures(*joined.mesh, warnings);
  Scene scene = makeScene(settings, std::move(joined), objectModel, std::move(texture));
  scene.materialTextures = std::move(materialTextures);
  // The objects' own textures, each file once; one that cannot be read is bad input, as the
  // scene's `texture` key.
  std::vector<int32_t> objectTexture(settings.objects.size(), -1);
  std::vector<std::filesystem::path> textureFiles;
  for (size_t o = 0; o < settings.objects.size(); ++o) {
    const std::optional<std::filesystem::path>& file = settings.objects[o].texture;
    if (!file) continue;
    const auto known = std::find(textureFiles.begin(), textureFiles.end(), *file);
    objectTexture[o] = int32_t(known - textureFiles.begin());
    if (known != textureFiles.end()) continue;
    textureFiles.push_back(*file);
    std::string error;
    cv::Mat texels = decodeColorImage(*file, error);
    if (texels.empty())
      throw InputError(file->string() + ": texture " + error + " (key 'objects[" +
                       std::to_string(o) + "].texture' of scene '" + settings.name + "')");
    scene.objectTextures.push_back(texels);
  }
  for (size_t k = 0; k < scene.instances.size(); ++k)
    scene.instances[k].texture = objectTexture[k % settings.objects.size()];
  return scene;
}

}  // namespace zrender
