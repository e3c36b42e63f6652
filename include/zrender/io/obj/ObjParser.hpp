#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "zrender/base/Threads.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {

// The parse of OBJ text into a Mesh's geometry, in parts of the text at once (docs/design.md,
// Loading). Two passes over the parts, each part a task: the first counts each part's
// statements, so that the second writes each part's vertices and faces straight to their place
// in the mesh. The rules are those of tinyobjloader rc10 (ObjLexer.hpp), numbers read by
// std::from_chars (correctly rounded). usemtl and mtllib statements are only collected here:
// the loader reads them with tinyobjloader, which also reads the .mtl files.

// A usemtl or mtllib line: its whole text.
struct ObjMaterialLine {
  std::string_view line;
  bool use = false;  // usemtl, not mtllib
};

// One part of the text: whole lines, and what they hold.
struct ObjPart {
  size_t begin = 0, end = 0;         // bytes of the text
  size_t attributes[3] = {0, 0, 0};  // v, vt, vn statements
  size_t faces = 0, corners = 0;
  size_t uses = 0;  // usemtl lines
  std::vector<ObjMaterialLine> materialLines;
  // Every earlier part's counts summed: where this part's statements go in the mesh.
  size_t attributesBefore[3] = {0, 0, 0};
  size_t facesBefore = 0, cornersBefore = 0, usesBefore = 0;
};

// The parts of a text and their counts: the first pass.
struct ObjLayout {
  std::vector<ObjPart> parts;
  size_t attributes[3] = {0, 0, 0};
  size_t faces = 0, corners = 0;
  size_t uses = 0;                             // usemtl lines
  std::vector<ObjMaterialLine> materialLines;  // in file order
};

// Parts of about `partBytes` bytes (cut after a line's '\n'), counted on `threads` (may be null).
ObjLayout layOutObj(std::string_view text, const Threads* threads, size_t partBytes);

// The first v, vt or vn statement (by ordinal in the file) whose numbers overflow to infinity.
struct ObjNonFinite {
  size_t ordinal[3];
};

// The second pass: fills mesh.positions, texcoords, normals, corners, faceStart and
// faceMaterial, which holds the ordinal of the face's usemtl line among the layout's usemtl
// lines (-1 before the first): the loader turns those into materials. Returns false, leaving
// the mesh in no particular state, if any v, vt, vn or f statement breaks the rules that
// scanObj() checks (the caller runs it to name the line). Numbers that overflow break no rule
// the scan can see: they go to `nonFinite` (npos where none).
bool parseObj(std::string_view text, const ObjLayout& layout, const Threads* threads, Mesh& mesh,
              ObjNonFinite& nonFinite);

}  // namespace zrender
