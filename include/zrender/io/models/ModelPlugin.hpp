#pragma once

// What libzrender_models.so (src/io/models/assimp/AssimpModels.cpp) gives: the model formats
// other than OBJ, read by assimp, loaded by the first such file (io/models/ModelLoader.hpp;
// base/Plugin.hpp). Its factory: zrenderModelPlugin.

#include <string>
#include <string_view>

#include "zrender/base/Error.hpp"
#include "zrender/io/models/ModelFormats.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {

class ModelPlugin {
 public:
  // The model whose file `path` holds `bytes`, into `mesh` (faces in the order docs/design.md,
  // Model formats, gives). The files it names (glTF buffers and images) are read beside it
  // when `filesBeside`, and none is otherwise. False with assimp's reason in `error`.
  virtual bool read(const std::string& path, std::string_view bytes, ModelFormat format,
                    bool filesBeside, Mesh& mesh, Warnings& warnings, std::string& error) = 0;

 protected:
  ~ModelPlugin() = default;
};

}  // namespace zrender
