#pragma once

// The OBJ geometry as tinyobjloader's own parse reads it (its callback API, one line after
// another): the reference of the loader's parse in parts (io/ObjParserTest.cpp, the OBJ fuzz
// target). For text that passes the loader's scan, without a byte order mark.

#include <string>
#include <string_view>
#include <vector>

#include "zrender/scene/Mesh.hpp"

namespace zrender::test {

struct TinyObjGeometry {
  Mesh mesh;  // positions, texcoords, normals, corners, faceStart; no materials
  // Per face, the name of the usemtl line in effect, trimmed ("" before the first).
  std::vector<std::string> faceUse;
};

TinyObjGeometry tinyObjReference(std::string_view text);

// How `parsed` differs from the reference's positions, texcoords, normals, corners and
// faceStart ("" if it does not). Indices must be equal; coordinates within 1e-12 relative (plus
// 1e-300 for values near zero): tinyobjloader sums digit * 10^-k, a few units in the last place
// off the correctly rounded value. Where its value is infinite (a number near the largest
// double, which it overflows) the coordinate is not compared.
std::string geometryDifference(const Mesh& parsed, const TinyObjGeometry& reference);

// How two parses of one text differ ("" if they do not): every coordinate and index bit for
// bit, faceStart, faceMaterial and the number of materials.
std::string meshBitsDifference(const Mesh& a, const Mesh& b);

}  // namespace zrender::test
