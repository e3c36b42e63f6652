#pragma once

#include <emmintrin.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

namespace zrender {

// The lexical rules of OBJ text shared by the loader's parse (ObjParser) and its error scan
// (ObjScanner): lines split and statements matched exactly as tinyobjloader rc10 does, which
// still reads the .mtl files and the usemtl/mtllib statements (docs/design.md, Loading).

// The statements the parse reads; the order matches Mesh's attribute arrays.
enum class ObjStatement { kPosition = 0, kTexcoord = 1, kNormal = 2, kFace, kOther };

// Largest decimal exponent magnitude accepted; no finite double needs more than 324. Beyond it
// tinyobjloader's 5^exponent overflows (0e500 would read as NaN), and past 2^31 / 10 it gives up
// and silently reads 0. 1e400 passes and is then refused as infinite.
constexpr int kObjMaxExponent = 400;
// Corner stores int32 indices.
constexpr int64_t kObjMaxIndex = std::numeric_limits<int32_t>::max();
// Fewest numbers each attribute statement needs, by ObjStatement (OBJ: v x y z [w],
// vt u [v [w]], vn i j k).
constexpr int kObjMinNumbers[] = {3, 1, 3};

inline bool isObjDigit(char c) {
  return c >= '0' && c <= '9';
}

// The lines of a text, one after another.
class ObjLines {
 public:
  explicit ObjLines(std::string_view text) : text_(text) {}

  // Next line without its terminator (\n, \r\n or a lone \r, as tinyobjloader's safeGetline),
  // cut at the first NUL because tinyobjloader parses each line through c_str().
  bool next(std::string_view& line) {
    const size_t size = text_.size();
    if (pos_ >= size) return false;
    const char* text = text_.data();
    size_t end = pos_;
    // Sixteen bytes at a time (SSE2, in every x86-64 processor) while they lie in the text,
    // then byte by byte: the first '\n', '\r' or NUL.
    const __m128i newline = _mm_set1_epi8('\n'), ret = _mm_set1_epi8('\r');
    for (; end + 16 <= size; end += 16) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text + end));
      const __m128i stop =
          _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi8(bytes, newline), _mm_cmpeq_epi8(bytes, ret)),
                       _mm_cmpeq_epi8(bytes, _mm_setzero_si128()));
      const int mask = _mm_movemask_epi8(stop);
      if (mask != 0) {
        end += size_t(__builtin_ctz(unsigned(mask)));
        break;
      }
    }
    // The first test passes every printable byte, so most bytes cost one comparison.
    while (end < size && (static_cast<unsigned char>(text[end]) > '\r' ||
                          (text[end] != '\n' && text[end] != '\r' && text[end] != '\0'))) {
      ++end;
    }
    line = std::string_view(text + pos_, end - pos_);
    if (end < size && text[end] == '\0') {  // rare: skip the rest of the line
      while (end < size && text[end] != '\n' && text[end] != '\r') ++end;
    }
    if (end < size && text[end] == '\r' && end + 1 < size && text[end + 1] == '\n') ++end;
    pos_ = end + 1;
    ++lineNumber_;
    return true;
  }

  // 1-based number of the line last returned by next().
  size_t lineNumber() const { return lineNumber_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t lineNumber_ = 0;
};

// The next field of a line, split at spaces and tabs; false at the end of the line.
inline bool nextObjField(std::string_view& line, std::string_view& field) {
  size_t i = 0;
  while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
  if (i == line.size()) return false;
  size_t j = i;
  while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
  field = line.substr(i, j - i);
  line.remove_prefix(j);
  return true;
}

// A line's first field (its keyword), leaving `line` at the fields after it.
inline std::string_view objKeyword(std::string_view& line) {
  std::string_view keyword;
  if (!nextObjField(line, keyword)) return {};
  return keyword;
}

// The statement a keyword starts. tinyobjloader matches "v" then a space or tab; a bare "v" or
// "f" (no fields) counts too here, so that the scan rejects it.
inline ObjStatement objStatementOf(std::string_view keyword) {
  if (keyword == "v") return ObjStatement::kPosition;
  if (keyword == "vt") return ObjStatement::kTexcoord;
  if (keyword == "vn") return ObjStatement::kNormal;
  if (keyword == "f") return ObjStatement::kFace;
  return ObjStatement::kOther;
}

// A line's statement, leaving `line` at its fields.
inline ObjStatement classifyObjLine(std::string_view& line) {
  return objStatementOf(objKeyword(line));
}

// Whether a line whose keyword and fields are these is one of tinyobjloader's usemtl or mtllib
// statements (the keyword, then a space or tab), and which.
inline bool isObjMaterialLine(std::string_view keyword, std::string_view fields, bool& use) {
  if (fields.empty()) return false;
  use = keyword == "usemtl";
  return use || keyword == "mtllib";
}

enum class ObjNumberKind { kOk, kMalformed, kNonFinite, kOutOfRange };

// Whole-field check against the grammar tinyobjloader's tryParseDouble accepts:
// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. tinyobjloader reads the longest
// valid prefix and defaults to 0 when there is none, so it cannot reject a field itself.
// kNonFinite is for words that mean NaN or infinity ("nan", "inf", MSVC's "1.#INF"); the
// caller reports those.
ObjNumberKind classifyObjNumber(std::string_view s);

// One face corner's field, v, v/vt, v//vn or v/vt/vn, split into its indices as written
// (0 where a part is absent; saturated beyond kObjMaxIndex).
struct ObjCorner {
  std::string_view parts[3];  // as written, empty where absent
  int64_t values[3] = {0, 0, 0};
  int partCount = 0;
  bool wellFormed = false;  // each part empty or [+-]digits, and only the middle one empty
};

ObjCorner splitObjCorner(std::string_view field);

}  // namespace zrender
