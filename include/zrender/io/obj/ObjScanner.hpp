#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "zrender/io/obj/ObjLexer.hpp"

namespace zrender {

// How many of each statement an OBJ text holds, after scanObj() found them all valid.
struct ObjCounts {
  size_t attributes[3] = {0, 0, 0};  // v, vt, vn statements
  size_t faces = 0;
  size_t corners = 0;
};

// The validation scan of OBJ text (docs/design.md, Errors): every v/vt/vn/f line's fields and
// index ranges, with lines counted exactly as tinyobjloader splits them. Throws InputError
// "FILE:LINE: what is wrong" at the first bad line (or for a positive index past the final
// count). The parse (ObjParser) checks the same rules in parts of the text at once but cannot
// name the first bad line; when it finds one, the loader runs this scan for the message. It
// allocates nothing and builds no geometry.
ObjCounts scanObj(const std::string& file, std::string_view text);

// The line number of the ordinal-th (0-based) statement of a kind in `text`; 0 if none.
size_t objStatementLine(std::string_view text, ObjStatement kind, size_t ordinal);

// Quotes a name from an OBJ or MTL file (of a file, a material) for a one-line message: control
// bytes escaped, UTF-8 kept, long names cut.
std::string quoteName(std::string_view s);

// `s` without its leading and trailing spaces and tabs.
std::string_view trim(std::string_view s);

}  // namespace zrender
