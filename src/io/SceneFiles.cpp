#include "zrender/io/SceneFiles.hpp"

#include <memory>
#include <string>

#include "zrender/base/SideBySide.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// A scene's face ids stop below the background's.
static_assert(kMaxSceneFaces == kBackgroundId);

cv::Mat loadTexture(const SceneSettings& settings, const Mesh& mesh, Warnings& warnings) {
  std::string texturePath;
  if (settings.texture) {
    texturePath = settings.texture->string();
  } else {
    for (const Material& m : mesh.materials) {
      if (!m.diffuseTexture.empty()) {
        texturePath = m.diffuseTexture;
        break;
      }
    }
  }
  if (texturePath.empty()) return cv::Mat();
  std::string error;
  cv::Mat texture = decodeColorImage(texturePath, error);
  // The scene's own `texture` key is a value the user chose: bad input. A material's map_Kd
  // comes with a model from elsewhere, whose textures often go missing: drawn without.
  if (texture.empty() && settings.texture)
    throw InputError(texturePath + ": texture " + error + " (key 'texture' of scene '" +
                     settings.name + "')");
  if (texture.empty()) warnings.push_back(texturePath + ": texture " + error + " (ignored)");
  return texture;
}

Scene loadScene(const SceneSettings& settings, Warnings& warnings, const Threads* threads) {
  std::shared_ptr<const Mesh> mesh;
  cv::Mat texture;
  if (settings.texture) {
    // Warnings in the order of loading one after the other: the model's, then the texture's.
    Warnings textureWarnings;
    sideBySide(threads, 2, [&](size_t job) {
      if (job == 0) {
        mesh = std::make_shared<const Mesh>(loadObj(settings.modelPath, warnings, threads));
      } else {
        texture = loadTexture(settings, Mesh(), textureWarnings);
      }
    });
    warnings.insert(warnings.end(), textureWarnings.begin(), textureWarnings.end());
  } else {  // the texture may be named by the model's materials: after the model
    mesh = std::make_shared<const Mesh>(loadObj(settings.modelPath, warnings, threads));
    texture = loadTexture(settings, *mesh, warnings);
  }
  return makeScene(settings, std::move(mesh), std::move(texture));
}

}  // namespace zrender
