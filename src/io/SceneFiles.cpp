#include "zrender/io/SceneFiles.hpp"

#include <memory>
#include <string>

#include "zrender/io/ImageCodecs.hpp"
#include "zrender/io/ObjLoader.hpp"

namespace zrender {

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

Scene loadScene(const SceneSettings& settings, Warnings& warnings) {
  auto mesh = std::make_shared<const Mesh>(loadObj(settings.modelPath, warnings));
  cv::Mat texture = loadTexture(settings, *mesh, warnings);
  return makeScene(settings, std::move(mesh), std::move(texture));
}

}  // namespace zrender
