#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace zrender {

// The statements of an OBJ file that the scan checks; the order matches Mesh's attribute arrays.
enum class ObjStatement { kPosition = 0, kTexcoord = 1, kNormal = 2, kFace, kOther };

// How many of each statement an OBJ text holds, after scanObj() found them all valid.
struct ObjCounts {
  size_t attributes[3] = {0, 0, 0};  // v, vt, vn statements
  size_t faces = 0;
  size_t corners = 0;
};

// The validation scan of OBJ text (docs/design.md, Errors): every v/vt/vn/f line's fields and
// index ranges, with lines counted exactly as tinyobjloader splits them. tinyobjloader rc10
// alone cannot name a bad line: it reads "v 1 abc 3" as (1, 0, 3) and "v nan 0 0" as
// (0, 0, 0), "f 1 x 3" as index 0 and "f 1/ 2/ 3/" as texture index 2 (atoi reads on into the
// next field), and its callback API, which the loader uses for the geometry, reports no line
// numbers and passes indices raw, unchecked. So this pass, before tinyobjloader's, throws
// InputError "FILE:LINE: what is wrong" at the first bad line (or for a positive index past
// the final count). It allocates nothing and builds no geometry: tinyobjloader stays the
// parser.
ObjCounts scanObj(const std::string& file, std::string_view text);

// The line number of the ordinal-th (0-based) statement of a kind in `text`; 0 if none.
size_t objStatementLine(std::string_view text, ObjStatement kind, size_t ordinal);

// Quotes a name from an OBJ or MTL file (of a file, a material) for a one-line message: control
// bytes escaped, UTF-8 kept, long names cut.
std::string quoteName(std::string_view s);

// `s` without its leading and trailing spaces and tabs.
std::string_view trim(std::string_view s);

}  // namespace zrender
