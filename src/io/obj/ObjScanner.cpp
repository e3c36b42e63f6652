#include "zrender/io/obj/ObjScanner.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/io/obj/ObjLexer.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace zrender {

namespace {

// Longest excerpt of an offending field quoted in a message; a field can be megabytes long.
constexpr size_t kMaxLineExcerpt = 40;
constexpr size_t kMaxNameExcerpt = 300;

// Quotes file text for a one-line message: control bytes escaped, long text cut. Names (of files,
// materials) keep their UTF-8 bytes; fields that should have been numbers escape them too.
std::string excerpt(std::string_view s, size_t limit = kMaxLineExcerpt, bool keepUtf8 = false) {
  std::string out;
  for (size_t i = 0; i < s.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f || (c > 0x7f && !keepUtf8)) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (s.size() > limit) out += "...";
  return out;
}

using Statement = ObjStatement;

const char* const kKeyword[] = {"v", "vt", "vn"};
const char* const kIndexName[] = {"vertex", "texture coordinate", "normal"};
const char* const kPlural[] = {"vertices", "texture coordinates", "normals"};

class Scanner {
 public:
  using Counts = ObjCounts;

  Scanner(const std::string& file, std::string_view text) : file_(file), lines_(text) {}

  // Throws InputError at the first bad line, or for a positive index past the final count.
  // Once: the lines are read as it goes.
  Counts validate() {
    Counts counts;
    // Positive indices may refer forward (OBJ allows it, tinyobjloader's own loader does too),
    // so they are checked against the totals at the end: the largest one, with its line.
    int64_t maxIndex[3] = {0, 0, 0};
    size_t maxIndexLine[3] = {0, 0, 0};
    std::string_view line;
    while (lines_.next(line)) {
      const Statement statement = classifyObjLine(line);
      if (statement == Statement::kOther) continue;
      if (statement == Statement::kFace) {
        size_t corners = 0;
        std::string_view field;
        while (nextObjField(line, field)) {
          if (++corners > kMaxFaceCorners) {
            fail("face has more than " + std::to_string(kMaxFaceCorners) + " corners");
          }
          checkCorner(field, counts, maxIndex, maxIndexLine);
        }
        if (corners == 0) fail("malformed 'f' line: face has no vertices");
        ++counts.faces;
        counts.corners += corners;
        continue;
      }
      const int k = static_cast<int>(statement);
      int numbers = 0;
      std::string_view field;
      while (nextObjField(line, field)) {
        switch (classifyObjNumber(field)) {
          case ObjNumberKind::kOk:
            break;
          case ObjNumberKind::kMalformed:
            fail(std::string("malformed '") + kKeyword[k] + "' line: '" + excerpt(field) +
                 "' is not a number");
          case ObjNumberKind::kNonFinite:
            fail("NaN or infinite coordinate '" + excerpt(field) + "'");
          case ObjNumberKind::kOutOfRange:
            fail("number '" + excerpt(field) + "' out of range");
        }
        ++numbers;
      }
      if (numbers < kObjMinNumbers[k]) {
        fail(std::string("malformed '") + kKeyword[k] + "' line: expected at least " +
             std::to_string(kObjMinNumbers[k]) + " numbers, got " + std::to_string(numbers));
      }
      ++counts.attributes[k];
    }
    for (int k = 0; k < 3; ++k) {
      if (maxIndex[k] > static_cast<int64_t>(counts.attributes[k])) {
        throw InputError(file_ + ":" + std::to_string(maxIndexLine[k]) + ": " + kIndexName[k] +
                         " index " + std::to_string(maxIndex[k]) + " out of range (model has " +
                         std::to_string(counts.attributes[k]) + " " + kPlural[k] + ")");
      }
      // Corner stores int32 indices and Mesh::faceStart uint32 offsets.
      if (counts.attributes[k] > static_cast<size_t>(kObjMaxIndex)) {
        throw InputError(file_ + ": too many " + kPlural[k]);
      }
    }
    if (counts.corners > std::numeric_limits<uint32_t>::max()) {
      throw InputError(file_ + ": too many face corners");
    }
    return counts;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(lines_.lineNumber()) + ": " + what);
  }

  // One face corner: v, v/vt, v//vn or v/vt/vn, each a nonzero integer in range.
  void checkCorner(std::string_view field, const Counts& counts, int64_t* maxIndex,
                   size_t* maxIndexLine) const {
    const ObjCorner corner = splitObjCorner(field);
    if (!corner.wellFormed) {
      fail("malformed 'f' line: '" + excerpt(field) +
           "' is not a vertex reference (v, v/vt, v//vn or v/vt/vn)");
    }
    for (int k = 0; k < corner.partCount; ++k) {
      if (corner.parts[k].empty()) continue;
      const int64_t value = corner.values[k];
      const size_t count = counts.attributes[k];
      if (value == 0) {
        fail(std::string(kIndexName[k]) + " index 0 is invalid (OBJ indices start at 1)");
      }
      if (value > kObjMaxIndex || value < -kObjMaxIndex) {
        fail(std::string(kIndexName[k]) + " index " + excerpt(corner.parts[k]) + " out of range");
      }
      if (value < 0 && -value > static_cast<int64_t>(count)) {
        // A negative index counts back from the last attribute defined before this line.
        fail(std::string(kIndexName[k]) + " index " + std::to_string(value) + " out of range (" +
             std::to_string(count) + " " + kPlural[k] + " defined before this line)");
      }
      if (value > maxIndex[k]) {
        maxIndex[k] = value;
        maxIndexLine[k] = lines_.lineNumber();
      }
    }
  }

  const std::string& file_;
  ObjLines lines_;
};

}  // namespace

std::string quoteName(std::string_view s) {
  return excerpt(s, kMaxNameExcerpt, true);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

ObjCounts scanObj(const std::string& file, std::string_view text) {
  return Scanner(file, text).validate();
}

size_t objStatementLine(std::string_view text, ObjStatement kind, size_t ordinal) {
  ObjLines lines(text);
  std::string_view line;
  while (lines.next(line)) {
    if (classifyObjLine(line) == kind && ordinal-- == 0) return lines.lineNumber();
  }
  return 0;
}

}  // namespace zrender
