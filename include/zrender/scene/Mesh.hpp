#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace zrender {

struct Material {
  std::string name;
  cv::Vec3f diffuse{0.8f, 0.8f, 0.8f};  // Kd (glTF: baseColorFactor), linear 0..1, RGB order
  // The texture's file (absolute or settings-relative path of map_Kd or of a glTF image), "" if
  // none; for a texture embedded in the model file, a name for messages ("model.glb#0").
  std::string diffuseTexture;
  // A texture embedded in the model file: its image file's bytes (PNG, JPEG), or its texels
  // (8-bit BGR) where the file holds them so; both empty otherwise.
  std::vector<unsigned char> embeddedImage;
  cv::Mat embeddedTexels;
  bool textureTimesDiffuse = false;  // glTF: texel x baseColorFactor; OBJ: map_Kd replaces Kd
};

// One corner of a face: indices into Mesh::positions / texcoords / normals (0-based, already
// resolved from OBJ's 1-based or negative form); -1 where the OBJ gave none.
struct Corner {
  int32_t position = -1;
  int32_t texcoord = -1;
  int32_t normal = -1;
};

// A polygon mesh as written in the file: one face per OBJ `f` line, in file order, so a face's
// index is its face id (docs/design.md, Faces, ids and shading; other formats: Model formats).
// Faces keep all their corners; triangulation happens later, in window space, so concave faces are
// right.
struct Mesh {
  std::vector<cv::Vec3d> positions;   // model space
  std::vector<cv::Vec2d> texcoords;   // u right, v up (OBJ convention)
  std::vector<cv::Vec3d> normals;     // model space, as given (not necessarily unit length)
  std::vector<Corner> corners;        // the corners of all faces, face after face
  std::vector<uint32_t> faceStart;    // face f owns corners [faceStart[f], faceStart[f + 1])
  std::vector<int32_t> faceMaterial;  // index into materials, -1 for none; one per face
  std::vector<Material> materials;
  // Per face, or empty: the mean of its corners' vertex colors (PLY, glTF COLOR_0), linear
  // 0..1 RGB, the face's base color in place of its material's diffuse.
  std::vector<cv::Vec3f> faceColors;

  size_t faceCount() const { return faceStart.empty() ? 0 : faceStart.size() - 1; }
  uint32_t cornerCount(size_t face) const { return faceStart[face + 1] - faceStart[face]; }
  const Corner* faceCorners(size_t face) const { return corners.data() + faceStart[face]; }
  bool hasNormals() const { return !normals.empty(); }
  bool hasTexcoords() const { return !texcoords.empty(); }
};

}  // namespace zrender
